#include "app/viewer/gizmo.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace hipr::viewer {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr int kRingPoints = 64;
constexpr float kSnapDegrees = 15.0f;
constexpr float kSnapScale = 0.1f;

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

// Two unit vectors completing `axis` to an orthonormal frame (for its ring).
void ring_basis(glm::vec3 axis, glm::vec3& u, glm::vec3& v) {
  const glm::vec3 helper = std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  u = glm::normalize(glm::cross(axis, helper));
  v = glm::cross(axis, u);
}

float snapped(float value, float step) { return std::round(value / step) * step; }

}  // namespace

std::optional<glm::vec2> ViewProjection::to_window(const glm::vec3& world) const {
  const glm::vec3 right = glm::normalize(glm::vec3(camera.camera_to_world[0]));
  const glm::vec3 up = glm::normalize(glm::vec3(camera.camera_to_world[1]));
  const glm::vec3 forward = -glm::normalize(glm::vec3(camera.camera_to_world[2]));
  const glm::vec3 d = world - eye();
  const float z = glm::dot(d, forward);
  if (!(z > 1e-6f)) return std::nullopt;
  const float tan_half = std::tan(0.5f * camera.yfov);
  const float aspect = float(render_width) / float(render_height);
  // pixel_centre_ray's inverse: ndc.x along right, ndc.y down along -up.
  const glm::vec2 ndc(glm::dot(d, right) / (z * tan_half * aspect),
                      -glm::dot(d, up) / (z * tan_half));
  const glm::vec2 render = (ndc + 1.0f) * 0.5f * glm::vec2(render_width, render_height);
  return glm::vec2(layout.x, layout.y) + render * layout.scale;
}

float ViewProjection::world_per_pixel(const glm::vec3& world) const {
  const glm::vec3 forward = -glm::normalize(glm::vec3(camera.camera_to_world[2]));
  const float z = std::max(glm::dot(world - eye(), forward), 1e-6f);
  return 2.0f * z * std::tan(0.5f * camera.yfov) / (float(render_height) * layout.scale);
}

std::optional<GizmoScreen> gizmo_screen(const ViewProjection& view, const glm::mat4& node_world,
                                        GizmoSpace space, GizmoMode mode, float handle_pixels) {
  GizmoScreen s;
  s.origin_world = glm::vec3(node_world[3]);
  const std::optional<glm::vec2> origin = view.to_window(s.origin_world);
  if (!origin) return std::nullopt;
  s.origin = *origin;
  s.world_length = handle_pixels * view.world_per_pixel(s.origin_world);
  s.handle_pixels = handle_pixels;
  const bool local = space == GizmoSpace::Local || mode == GizmoMode::Scale;
  for (int axis = 0; axis < 3; ++axis) {
    glm::vec3 direction(0.0f);
    direction[axis] = 1.0f;
    if (local) {
      const glm::vec3 column(node_world[axis]);
      if (glm::length(column) > 0.0f) direction = glm::normalize(column);
    }
    s.axes[size_t(axis)] = direction;
    // A handle whose end is behind the camera points at it: drawn as a dot at the origin.
    s.tips[size_t(axis)] =
        view.to_window(s.origin_world + s.world_length * direction).value_or(s.origin);
    if (mode != GizmoMode::Rotate) continue;
    glm::vec3 u, v;
    ring_basis(direction, u, v);
    std::vector<glm::vec2>& ring = s.rings[size_t(axis)];
    for (int i = 0; i <= kRingPoints; ++i) {
      const float angle = 2.0f * kPi * float(i) / kRingPoints;
      const glm::vec3 p =
          s.origin_world + 0.9f * s.world_length * (std::cos(angle) * u + std::sin(angle) * v);
      if (const auto q = view.to_window(p)) ring.push_back(*q);
    }
  }
  return s;
}

int gizmo_hit(const GizmoScreen& screen, GizmoMode mode, glm::vec2 mouse, float tolerance) {
  int best = -1;
  float best_distance = tolerance;
  if (mode == GizmoMode::Scale && glm::length(mouse - screen.origin) <= tolerance * 1.25f)
    return kGizmoUniformScale;
  for (int axis = 0; axis < 3; ++axis) {
    float distance = 1e30f;
    if (mode == GizmoMode::Rotate) {
      const std::vector<glm::vec2>& ring = screen.rings[size_t(axis)];
      for (size_t i = 1; i < ring.size(); ++i)
        distance = std::min(distance, distance_to_segment(mouse, ring[i - 1], ring[i]));
    } else {
      const glm::vec2 tip = screen.tips[size_t(axis)];
      if (glm::length(tip - screen.origin) < 4.0f) continue;  // seen end-on: not draggable
      // From a little way out, so the centre stays the uniform handle's.
      distance = distance_to_segment(mouse, screen.origin + 0.2f * (tip - screen.origin), tip);
    }
    if (distance <= best_distance) {
      best_distance = distance;
      best = axis;
    }
  }
  return best;
}

float nice_step(float length) {
  const float tenth = std::max(length * 0.1f, 1e-6f);
  const float power = std::pow(10.0f, std::floor(std::log10(tenth)));
  for (float m : {5.0f, 2.0f, 1.0f})
    if (m * power <= tenth) return m * power;
  return power;
}

GizmoDrag::GizmoDrag(const GizmoScreen& screen, GizmoMode mode, int handle, glm::vec2 press,
                     const glm::mat4& start_local, const glm::mat4& parent_world,
                     const glm::vec3& eye)
    : m_screen(screen),
      m_mode(mode),
      m_handle(handle),
      m_press(press),
      m_start_local(start_local),
      m_parent_world(parent_world) {
  if (handle >= 0 && handle < 3)
    m_axis_toward_eye = glm::dot(screen.axes[size_t(handle)], eye - screen.origin_world) > 0.0f;
  const glm::vec2 from = press - screen.origin;
  m_last_angle = std::atan2(from.y, from.x);
}

glm::mat4 GizmoDrag::local_at(glm::vec2 mouse, bool snap) {
  const glm::vec2 origin = m_screen.origin;
  if (m_mode == GizmoMode::Scale) {
    float factor = 1.0f;
    if (m_handle == kGizmoUniformScale) {
      // Right or up grows, left or down shrinks: a handle's length doubles the size.
      const glm::vec2 moved = mouse - m_press;
      factor = 1.0f + (moved.x - moved.y) / std::max(m_screen.handle_pixels, 1.0f);
    } else {
      const glm::vec2 axis = m_screen.tips[size_t(m_handle)] - origin;
      const float len2 = std::max(glm::dot(axis, axis), 1.0f);
      // The handle's end follows the mouse: 1 at the press, 2 a handle's length further out.
      factor = 1.0f + glm::dot(mouse - m_press, axis) / len2;
    }
    factor = std::clamp(factor, 0.01f, 100.0f);
    if (snap) factor = std::max(snapped(factor, kSnapScale), kSnapScale);
    glm::vec3 scale(1.0f);
    if (m_handle == kGizmoUniformScale)
      scale = glm::vec3(factor);
    else
      scale[m_handle] = factor;
    return m_start_local * glm::scale(glm::mat4(1.0f), scale);
  }

  const glm::vec3 axis = m_screen.axes[size_t(m_handle)];
  glm::mat4 world_change(1.0f);
  if (m_mode == GizmoMode::Translate) {
    const glm::vec2 screen_axis = m_screen.tips[size_t(m_handle)] - origin;
    const float len2 = std::max(glm::dot(screen_axis, screen_axis), 1.0f);
    float distance = glm::dot(mouse - m_press, screen_axis) / len2 * m_screen.world_length;
    if (snap) distance = snapped(distance, nice_step(m_screen.world_length));
    world_change = glm::translate(glm::mat4(1.0f), distance * axis);
  } else {
    const glm::vec2 to = mouse - origin;
    if (glm::length(to) > 2.0f) {  // at the centre the angle is undefined: keep the last
      const float angle = std::atan2(to.y, to.x);
      float step = angle - m_last_angle;
      if (step > kPi) step -= 2.0f * kPi;
      if (step < -kPi) step += 2.0f * kPi;
      m_turned += step;
      m_last_angle = angle;
    }
    // Window y points down: turning on screen counter-clockwise about an axis that points at
    // the viewer is a positive (right-handed) turn.
    float radians = m_axis_toward_eye ? -m_turned : m_turned;
    if (snap) radians = glm::radians(snapped(glm::degrees(radians), kSnapDegrees));
    const glm::vec3 o = m_screen.origin_world;
    world_change = glm::translate(glm::mat4(1.0f), o) *
                   glm::rotate(glm::mat4(1.0f), radians, axis) *
                   glm::translate(glm::mat4(1.0f), -o);
  }
  // W' = change * P * L, and L' = P^-1 * W'.
  return glm::inverse(m_parent_world) * world_change * m_parent_world * m_start_local;
}

}  // namespace hipr::viewer
