#pragma once
// Orbit, pan and zoom around a pivot, as 3D viewports do. The controller keeps the camera as
// pivot + distance + yaw/pitch with +Y up, so orbiting never rolls the view; starting from a
// camera with roll drops the roll at the first move. Callers turn camera_to_world() into a
// CameraEdit (every move restarts the render, as in the paper).
#include <glm/glm.hpp>

namespace hipr::viewer {

class CameraController {
 public:
  // Takes over a camera (world matrix, looking down its -Z). The pivot is the point on the
  // view axis at `pivot_distance`.
  void reset(const glm::mat4& camera_to_world, float pivot_distance);

  // Mouse motion in window pixels over a view `viewport_height` pixels tall: a drag across
  // the whole height turns the view by half a turn.
  void orbit(glm::vec2 delta_pixels, float viewport_height);
  // Moves camera and pivot in the view plane so the point at the pivot's depth follows the
  // mouse. `tan_half_fov`: of the vertical field of view.
  void pan(glm::vec2 delta_pixels, float viewport_height, float tan_half_fov);
  // Mouse wheel steps: positive moves towards the pivot (never through it).
  void zoom(float steps);

  glm::mat4 camera_to_world() const;
  glm::vec3 pivot() const { return m_pivot; }
  float distance() const { return m_distance; }

 private:
  glm::vec3 m_pivot{0.0f};
  float m_distance = 1.0f;
  float m_yaw = 0.0f;    // radians about +Y; 0 looks down -Z
  float m_pitch = 0.0f;  // radians, positive looks down onto the pivot
};

}  // namespace hipr::viewer
