#include "scene/default_camera.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace hipr {

Camera resolve_camera(const Scene& scene) {
  if (const int node = scene.camera_node(); node >= 0) {
    Camera camera = scene.cameras[size_t(scene.nodes[size_t(node)].camera)];
    // Scale in the node chain would skew the camera frame: keep rotation + translation only.
    const glm::mat4 world = scene.world_transform(uint32_t(node));
    glm::mat4 frame(1.0f);
    for (int axis = 0; axis < 3; ++axis) {
      const glm::vec3 v(world[axis]);
      const float len = glm::length(v);
      frame[axis] = glm::vec4(len > 0.0f ? v / len : glm::vec3(0.0f), 0.0f);
    }
    frame[3] = world[3];
    camera.camera_to_world = frame;
    return camera;
  }
  const auto [lo, hi] = scene.bounds();
  const glm::vec3 center = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
  Camera camera;
  camera.name = "default";
  camera.yfov = glm::radians(40.0f);
  const float distance = radius / std::sin(0.5f * camera.yfov) * 1.05f;
  const glm::vec3 eye = center + glm::vec3(0.0f, 0.0f, distance);
  camera.camera_to_world = glm::inverse(glm::lookAt(eye, center, glm::vec3(0.0f, 1.0f, 0.0f)));
  camera.znear = distance * 1e-3f;
  return camera;
}

}  // namespace hipr
