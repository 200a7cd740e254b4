#pragma once
// Mouse and keyboard over the rendered image (what the UI did not take), read from ImGui's IO:
//   left click       pick the object under the cursor (G-buffer instance id); background clears
//   left drag        on a gizmo handle: move, turn or scale the selection along that axis
//                    (Ctrl snaps); elsewhere: move the object under the cursor in the view
//                    plane (one undo step either way)
//   W / E / R        gizmo: move / rotate / scale;  Q  its axes: world / local
//   left click after the Camera panel's "click to focus": the focus distance, not a selection
//   right drag / Alt+left drag   orbit the camera;  middle drag / Shift+right drag   pan
//   wheel            zoom towards the pivot
//   arrows, PgUp/PgDn   move the selection along world X (left/right), Z (up/down), Y (page keys);
//                       Shift: 10x the step (1% of the scene's size)
//   Ctrl+Z / Ctrl+Y (Ctrl+Shift+Z)   undo / redo;  Ctrl+S save;  F12 screenshot
//   Tab  panels on/off;  0-3  overlay none / ids / weights / owed;  H  hide/show selection;
//   Esc  clear selection
// Every camera move is a camera edit (the render restarts, as in the paper), undoable.
#include <glm/glm.hpp>

#include <optional>

#include "app/viewer/camera_controller.h"
#include "app/viewer/gizmo.h"
#include "app/viewer/session.h"
#include "app/viewer/view_layout.h"
#include "app/viewer/viewer_state.h"
#include "app/viewer/window.h"

namespace hipr::viewer {

class ViewportInput {
 public:
  // `pixel_ratio`: framebuffer pixels per window coordinate (ImGui reports the mouse in the
  // latter, the layout is in the former). `keys`: the presses since the last frame. Hands the
  // session the view's focus (the selection, the cursor) every frame.
  void update(Session& session, ViewerState& state, const ViewLayout& layout, float pixel_ratio,
              const std::vector<KeyPress>& keys);

 private:
  enum class Drag { None, Pending, Move, Orbit, Pan, Gizmo };
  void start_camera_gesture(const Session& session);
  void apply_camera(Session& session, ViewerState& state);
  void drag_object(Session& session, ViewerState& state, glm::vec2 delta_render_pixels);
  void key(Session& session, ViewerState& state, const KeyPress& press);
  void finish_drag(Session& session);
  // The selection's gizmo as it appears now (none without a selection or with the UI hidden).
  std::optional<GizmoScreen> gizmo(const Session& session, ViewerState& state,
                                   const ViewLayout& layout, float pixel_ratio) const;
  void draw_gizmo(const GizmoScreen& screen, GizmoMode mode, int hot, float pixel_ratio) const;

  Drag m_drag = Drag::None;
  glm::vec2 m_press{0.0f};  // window pixels where the button went down
  glm::vec2 m_last{0.0f};
  bool m_grouped = false;  // this drag opened an undo group
  // Object moves: the node, its local transform at the press, and the depth of the point grabbed.
  uint32_t m_node = 0;
  glm::mat4 m_start_local{1.0f};
  float m_depth = 1.0f;
  std::optional<GizmoDrag> m_gizmo;  // while Drag::Gizmo
  CameraController m_camera;
};

}  // namespace hipr::viewer
