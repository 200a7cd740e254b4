#include "app/viewer/viewport_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>

#include "app/viewer/panels.h"
#include "scene/default_camera.h"

namespace hipr::viewer {
namespace {

// A press that moves less than this (window pixels) before release is a click, not a drag.
constexpr float kClickSlop = 3.0f;
// The gizmo's handles: their length and how near (window coordinates) a press must be.
constexpr float kGizmoHandlePixels = 80.0f;
constexpr float kGizmoTolerancePixels = 7.0f;

glm::mat4 parent_world(const Scene& scene, uint32_t node) {
  const int parent = scene.nodes[node].parent;
  return parent >= 0 ? scene.world_transform(uint32_t(parent)) : glm::mat4(1.0f);
}

// A world-space offset as a change of the node's local translation (parent space).
glm::vec3 to_local_offset(const Scene& scene, uint32_t node, glm::vec3 world_offset) {
  return glm::vec3(glm::inverse(parent_world(scene, node)) * glm::vec4(world_offset, 0.0f));
}

}  // namespace

void ViewportInput::start_camera_gesture(const Session& session) {
  const Scene& scene = session.scene();
  const Camera camera = resolve_camera(scene);
  const auto [lo, hi] = session.bounds();
  const glm::vec3 eye(camera.camera_to_world[3]);
  const glm::vec3 forward = -glm::vec3(camera.camera_to_world[2]);
  // Orbit about the scene's centre as seen along the view axis.
  float distance = glm::dot(0.5f * (lo + hi) - eye, forward);
  if (!(distance > 1e-3f * session.radius())) distance = session.radius();
  m_camera.reset(camera.camera_to_world, distance);
}

void ViewportInput::apply_camera(Session& session, ViewerState& state) {
  const Scene& scene = session.scene();
  const int node = scene.camera_node();  // the session gives every scene a camera node
  if (node < 0) return;
  const glm::mat4 local =
      glm::inverse(parent_world(scene, uint32_t(node))) * m_camera.camera_to_world();
  try_edit(session, state, CameraEdit{std::nullopt, local});
}

void ViewportInput::drag_object(Session& session, ViewerState& state, glm::vec2 delta) {
  const Scene& scene = session.scene();
  const Camera camera = resolve_camera(scene);
  // World units per rendered pixel at the grabbed point's depth: the point follows the mouse.
  const float per_pixel =
      2.0f * m_depth * std::tan(0.5f * camera.yfov) / float(session.settings().render.height);
  const glm::vec3 offset = (delta.x * glm::vec3(camera.camera_to_world[0]) -
                            delta.y * glm::vec3(camera.camera_to_world[1])) *
                           per_pixel;
  glm::mat4 local = m_start_local;
  local[3] += glm::vec4(to_local_offset(scene, m_node, offset), 0.0f);
  try_edit(session, state, TransformEdit{node_reference(scene, m_node), std::nullopt, local});
}

void ViewportInput::key(Session& session, ViewerState& state, const KeyPress& press) {
  const int k = press.key;
  if (press.ctrl) {
    if (k == GLFW_KEY_Z) press.shift ? session.redo() : session.undo();
    if (k == GLFW_KEY_Y) session.redo();
    if (k == GLFW_KEY_S && !press.repeat) state.request_save = true;
    if (k == GLFW_KEY_D && !press.repeat) duplicate_selection(session, state);
    return;
  }
  if (k == GLFW_KEY_F12 && !press.repeat) state.request_screenshot = true;
  if (press.repeat && k != GLFW_KEY_LEFT && k != GLFW_KEY_RIGHT && k != GLFW_KEY_UP &&
      k != GLFW_KEY_DOWN && k != GLFW_KEY_PAGE_UP && k != GLFW_KEY_PAGE_DOWN)
    return;  // only moves repeat while a key is held
  if (k == GLFW_KEY_TAB) state.show_ui = !state.show_ui;
  if (k == GLFW_KEY_N) state.denoise.enabled = !state.denoise.enabled;
  const Overlay overlays[] = {Overlay::None, Overlay::Ids, Overlay::Weights, Overlay::Owed};
  if (k >= GLFW_KEY_0 && k <= GLFW_KEY_3) state.overlay = overlays[k - GLFW_KEY_0];
  if (k == GLFW_KEY_ESCAPE) state.selected_node = -1;
  if (k == GLFW_KEY_W) state.gizmo_mode = GizmoMode::Translate;
  if (k == GLFW_KEY_E) state.gizmo_mode = GizmoMode::Rotate;
  if (k == GLFW_KEY_R) state.gizmo_mode = GizmoMode::Scale;
  if (k == GLFW_KEY_Q)
    state.gizmo_space =
        state.gizmo_space == GizmoSpace::World ? GizmoSpace::Local : GizmoSpace::World;

  const std::optional<uint32_t> selected = selected_node(session, state);
  if (!selected) return;
  if (k == GLFW_KEY_DELETE) {
    delete_selection(session, state);
    return;
  }
  const Scene& scene = session.scene();
  const uint32_t node = *selected;
  if (k == GLFW_KEY_H)
    try_edit(session, state,
             VisibilityEdit{node_reference(scene, node), !scene.nodes[node].visible});
  const struct {
    int key;
    glm::vec3 direction;
  } moves[] = {{GLFW_KEY_LEFT, {-1, 0, 0}},   {GLFW_KEY_RIGHT, {1, 0, 0}},
               {GLFW_KEY_UP, {0, 0, -1}},     {GLFW_KEY_DOWN, {0, 0, 1}},
               {GLFW_KEY_PAGE_UP, {0, 1, 0}}, {GLFW_KEY_PAGE_DOWN, {0, -1, 0}}};
  for (const auto& move : moves) {
    if (k != move.key) continue;
    const float step = 0.01f * session.radius() * (press.shift ? 10.0f : 1.0f);
    glm::mat4 local = scene.nodes[node].local;
    local[3] += glm::vec4(to_local_offset(scene, node, move.direction * step), 0.0f);
    try_edit(session, state, TransformEdit{node_reference(scene, node), std::nullopt, local});
  }
}

void ViewportInput::finish_drag(Session& session) {
  if (m_grouped) session.end_group();
  m_grouped = false;
  m_drag = Drag::None;
  m_gizmo.reset();
}

std::optional<GizmoScreen> ViewportInput::gizmo(const Session& session, ViewerState& state,
                                                const ViewLayout& layout, float pixel_ratio) const {
  const std::optional<uint32_t> selected = selected_node(session, state);
  if (!selected || !state.show_ui) return std::nullopt;
  const Scene& scene = session.scene();
  ViewProjection view{resolve_camera(scene), layout.render_width, layout.render_height, layout};
  return gizmo_screen(view, scene.world_transform(*selected), state.gizmo_space, state.gizmo_mode,
                      kGizmoHandlePixels * pixel_ratio);
}

void ViewportInput::draw_gizmo(const GizmoScreen& screen, GizmoMode mode, int hot,
                               float pixel_ratio) const {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const auto at = [&](glm::vec2 p) { return ImVec2(p.x / pixel_ratio, p.y / pixel_ratio); };
  const ImU32 colours[3] = {IM_COL32(230, 60, 60, 255), IM_COL32(70, 200, 70, 255),
                            IM_COL32(70, 110, 240, 255)};
  const ImU32 highlight = IM_COL32(255, 220, 40, 255);
  const ImVec2 origin = at(screen.origin);
  for (int axis = 0; axis < 3; ++axis) {
    const ImU32 colour = hot == axis ? highlight : colours[axis];
    const float width = hot == axis ? 3.5f : 2.5f;
    if (mode == GizmoMode::Rotate) {
      std::vector<ImVec2> ring;
      for (glm::vec2 p : screen.rings[size_t(axis)]) ring.push_back(at(p));
      draw->AddPolyline(ring.data(), int(ring.size()), colour, ImDrawFlags_None, width);
      continue;
    }
    const ImVec2 tip = at(screen.tips[size_t(axis)]);
    draw->AddLine(origin, tip, colour, width);
    if (mode == GizmoMode::Scale) {
      draw->AddRectFilled(ImVec2(tip.x - 5, tip.y - 5), ImVec2(tip.x + 5, tip.y + 5), colour);
    } else {  // an arrow head along the handle
      const glm::vec2 d = screen.tips[size_t(axis)] - screen.origin;
      if (glm::length(d) < 4.0f) continue;
      const glm::vec2 u = glm::normalize(d), n(-u.y, u.x);
      const glm::vec2 base = screen.tips[size_t(axis)] - 14.0f * pixel_ratio * u;
      draw->AddTriangleFilled(at(screen.tips[size_t(axis)]), at(base + 6.0f * pixel_ratio * n),
                              at(base - 6.0f * pixel_ratio * n), colour);
    }
  }
  if (mode == GizmoMode::Scale) {
    const ImU32 colour = hot == kGizmoUniformScale ? highlight : IM_COL32(230, 230, 230, 255);
    draw->AddRectFilled(ImVec2(origin.x - 6, origin.y - 6), ImVec2(origin.x + 6, origin.y + 6),
                        colour);
  }
}

void ViewportInput::update(Session& session, ViewerState& state, const ViewLayout& layout,
                           float pixel_ratio, const std::vector<KeyPress>& keys) {
  const ImGuiIO& io = ImGui::GetIO();
  const glm::vec2 mouse(io.MousePos.x * pixel_ratio, io.MousePos.y * pixel_ratio);
  // Keys typed into a text field are the field's.
  if (!io.WantCaptureKeyboard)
    for (const KeyPress& press : keys) key(session, state, press);
  const float view_height = layout.scale * float(layout.render_height);

  if (m_drag == Drag::None && !io.WantCaptureMouse) {
    const bool left = ImGui::IsMouseClicked(ImGuiMouseButton_Left),
               right = ImGui::IsMouseClicked(ImGuiMouseButton_Right),
               middle = ImGui::IsMouseClicked(ImGuiMouseButton_Middle);
    const std::optional<GizmoScreen> handles = gizmo(session, state, layout, pixel_ratio);
    const int handle =
        handles ? gizmo_hit(*handles, state.gizmo_mode, mouse, kGizmoTolerancePixels * pixel_ratio)
                : -1;
    if (left && !io.KeyAlt && handle >= 0) {
      m_node = *selected_node(session, state);
      const Scene& scene = session.scene();
      m_gizmo.emplace(*handles, state.gizmo_mode, handle, mouse, scene.nodes[m_node].local,
                      parent_world(scene, m_node), resolve_camera(scene).camera_to_world[3]);
      m_drag = Drag::Gizmo;
    } else if (left && !io.KeyAlt && state.pick_focus) {
      // Click to focus: the surface's depth along the view axis becomes the focus distance.
      if (const auto pixel = layout.to_render(mouse)) {
        const Renderer::PixelHit hit = session.pick(pixel->x, pixel->y);
        if (hit.instance != UINT32_MAX && hit.depth > 0.0f) {
          CameraEdit edit;
          edit.focus_distance = hit.depth;
          try_edit(session, state, edit);
        }
      }
      state.pick_focus = false;
    } else if (left && !io.KeyAlt) {
      if (const auto pixel = layout.to_render(mouse)) {
        const Renderer::PixelHit hit = session.pick(pixel->x, pixel->y);
        const auto instances = session.scene().instances();
        if (hit.instance < instances.size()) {
          m_node = instances[hit.instance].node;
          state.selected_node = int(m_node);
          m_start_local = session.scene().nodes[m_node].local;
          m_depth = hit.depth;
          m_drag = Drag::Pending;
        } else {
          state.selected_node = -1;
        }
      }
    } else if (left || right || middle) {
      m_drag = (middle || (right && io.KeyShift)) ? Drag::Pan : Drag::Orbit;
      start_camera_gesture(session);
    }
    if (m_drag != Drag::None) {
      m_press = m_last = mouse;
      session.begin_group();  // everything this drag does is one undo step
      m_grouped = true;
    }
    if (m_drag == Drag::None && io.MouseWheel != 0.0f && layout.to_render(mouse)) {
      start_camera_gesture(session);
      m_camera.zoom(io.MouseWheel);
      apply_camera(session, state);
    }
  }
  // Where the user looks: the selection and, when asked, the pixel under the cursor
  // (docs/method.md#focus); a panel under the mouse holds no gaze.
  std::optional<glm::vec2> cursor;
  if (const auto pixel = io.WantCaptureMouse ? std::nullopt : layout.to_render(mouse))
    cursor = glm::vec2(*pixel) + 0.5f;
  session.set_view_focus(view_focus(session.scene(), state, cursor));

  // The gizmo, its handle under the mouse (or the one dragged) highlighted.
  if (const std::optional<GizmoScreen> handles = gizmo(session, state, layout, pixel_ratio)) {
    int hot = -1;
    if (m_drag == Drag::Gizmo && m_gizmo)
      hot = m_gizmo->handle();
    else if (m_drag == Drag::None && !io.WantCaptureMouse)
      hot = gizmo_hit(*handles, state.gizmo_mode, mouse, kGizmoTolerancePixels * pixel_ratio);
    draw_gizmo(*handles, state.gizmo_mode, hot, pixel_ratio);
  }

  if (m_drag == Drag::None) return;
  const glm::vec2 delta = mouse - m_last;
  m_last = mouse;
  switch (m_drag) {
    case Drag::Pending:
      if (glm::length(mouse - m_press) <= kClickSlop) break;
      m_drag = Drag::Move;
      drag_object(session, state, (mouse - m_press) / layout.scale);
      break;
    case Drag::Move:
      if (delta != glm::vec2(0.0f)) drag_object(session, state, (mouse - m_press) / layout.scale);
      break;
    case Drag::Gizmo:
      if (delta != glm::vec2(0.0f) && m_gizmo)
        try_edit(session, state,
                 TransformEdit{node_reference(session.scene(), m_node), std::nullopt,
                               m_gizmo->local_at(mouse, io.KeyCtrl)});
      break;
    case Drag::Orbit:
      if (delta != glm::vec2(0.0f)) {
        m_camera.orbit(delta, view_height);
        apply_camera(session, state);
      }
      break;
    case Drag::Pan:
      if (delta != glm::vec2(0.0f)) {
        m_camera.pan(delta, view_height, std::tan(0.5f * resolve_camera(session.scene()).yfov));
        apply_camera(session, state);
      }
      break;
    case Drag::None:
      break;
  }
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left) && !ImGui::IsMouseDown(ImGuiMouseButton_Right) &&
      !ImGui::IsMouseDown(ImGuiMouseButton_Middle))
    finish_drag(session);
}

}  // namespace hipr::viewer
