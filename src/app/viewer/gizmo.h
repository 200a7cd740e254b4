#pragma once
// The transform gizmo over the selection: three handles, one per axis, that move (arrows),
// turn (rings) or stretch (boxes, and a centre box for all three) the selected node when
// dragged. World or local axes; Ctrl snaps (moves to steps of a tenth of a handle's length
// rounded to 1, 2 or 5 x a power of ten, turns to 15 degrees, scales to tenths). Every frame
// of a drag sends the node's whole local matrix, computed from where the drag started, so a
// long drag does not gather rounding error and its edits form one undo step.
//
// Geometry only (the drawing is ViewportInput's): everything is in framebuffer pixels of the
// window, through the same camera the renderer traces (pixel_ray.glsl's projection).
#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "app/viewer/view_layout.h"
#include "hipr/scene.h"

namespace hipr::viewer {

enum class GizmoMode { Translate, Rotate, Scale };
enum class GizmoSpace { World, Local };
constexpr int kGizmoUniformScale = 3;  // the handle at the centre (scale mode)

// World -> window pixels through the scene's camera and the view layout.
struct ViewProjection {
  Camera camera;
  uint32_t render_width = 1, render_height = 1;
  ViewLayout layout;

  std::optional<glm::vec2> to_window(const glm::vec3& world) const;  // none behind the camera
  glm::vec3 eye() const { return glm::vec3(camera.camera_to_world[3]); }
  // World size of one window pixel at `world`'s depth.
  float world_per_pixel(const glm::vec3& world) const;
};

struct GizmoScreen {
  glm::vec3 origin_world{0.0f};
  glm::vec2 origin{0.0f};
  std::array<glm::vec3, 3> axes{};              // unit world directions of the handles
  std::array<glm::vec2, 3> tips{};              // the handles' ends
  std::array<std::vector<glm::vec2>, 3> rings;  // rotate mode: each axis's circle, closed
  float world_length = 1.0f;                    // a handle's length in world units
  float handle_pixels = 80.0f;                  // and in window pixels, seen square-on
};

// Where the gizmo of a node whose world transform is `node_world` appears, handles
// `handle_pixels` long; none when its origin is behind the camera. Scale handles always follow
// the node's own axes (scaling along other axes would shear it).
std::optional<GizmoScreen> gizmo_screen(const ViewProjection& view, const glm::mat4& node_world,
                                        GizmoSpace space, GizmoMode mode, float handle_pixels);

// The handle under `mouse` (0-2: x, y, z; kGizmoUniformScale; -1: none), within `tolerance`
// pixels; the nearest wins.
int gizmo_hit(const GizmoScreen& screen, GizmoMode mode, glm::vec2 mouse, float tolerance);

// One drag of one handle, from the press to the release.
class GizmoDrag {
 public:
  GizmoDrag(const GizmoScreen& screen, GizmoMode mode, int handle, glm::vec2 press,
            const glm::mat4& start_local, const glm::mat4& parent_world, const glm::vec3& eye);
  // The node's local transform with the mouse at `mouse` (`snap`: Ctrl held).
  glm::mat4 local_at(glm::vec2 mouse, bool snap);
  GizmoMode mode() const { return m_mode; }
  int handle() const { return m_handle; }

 private:
  GizmoScreen m_screen;
  GizmoMode m_mode;
  int m_handle;
  glm::vec2 m_press;
  glm::mat4 m_start_local, m_parent_world;
  bool m_axis_toward_eye = false;
  // Rotation: the angle turned so far, followed frame by frame so a drag may go past 180.
  float m_turned = 0.0f, m_last_angle = 0.0f;
};

// The snapping step of a move: a tenth of `length`, rounded down to 1, 2 or 5 x 10^k.
float nice_step(float length);

}  // namespace hipr::viewer
