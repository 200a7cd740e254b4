#include "scene/default_camera.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"

namespace hipr {
namespace {

// Scale in a node chain would skew the camera frame: keep rotation + translation only. Both the
// camera node's and the stored default camera's matrices go through it, so a default camera
// saved as a node and loaded again renders bit for bit the same view.
glm::mat4 rigid_frame(const glm::mat4& world) {
  glm::mat4 frame(1.0f);
  for (int axis = 0; axis < 3; ++axis) {
    const glm::vec3 v(world[axis]);
    const float len = glm::length(v);
    frame[axis] = glm::vec4(len > 0.0f ? v / len : glm::vec3(0.0f), 0.0f);
  }
  frame[3] = world[3];
  return frame;
}

}  // namespace

Camera framing_camera(const Scene& scene) {
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

// (Not value_or: that would frame the scene, reading every vertex, on every call.)
Camera default_view(const Scene& scene) {
  return scene.default_camera ? *scene.default_camera : framing_camera(scene);
}

void fix_default_camera(Scene& scene) {
  if (!scene.default_camera && scene.camera_node() < 0)
    scene.default_camera = framing_camera(scene);
}

Camera resolve_camera(const Scene& scene) {
  Camera camera;
  glm::mat4 world;
  if (const int node = scene.camera_node(); node >= 0) {
    camera = scene.cameras[size_t(scene.nodes[size_t(node)].camera)];
    world = scene.world_transform(uint32_t(node));
  } else {
    camera = default_view(scene);
    world = camera.camera_to_world;
  }
  camera.camera_to_world = rigid_frame(world);
  return camera;
}

uint32_t find_camera_node(const Scene& scene, const std::string& name_or_index) {
  const std::vector<uint32_t> cameras = scene.camera_nodes();
  if (cameras.empty())
    throw InputError("--camera " + name_or_index + ": the scene has no camera (it is seen " +
                     "from a default view framing it)");
  const bool digits = !name_or_index.empty() && name_or_index.size() < 10 &&
                      name_or_index.find_first_not_of("0123456789") == std::string::npos;
  if (digits) {
    const size_t index = std::stoul(name_or_index);
    if (index < cameras.size()) return cameras[index];
  }
  for (uint32_t node : cameras) {
    const Node& n = scene.nodes[node];
    if (n.name == name_or_index || scene.cameras[size_t(n.camera)].name == name_or_index)
      return node;
  }
  std::string known;
  for (size_t i = 0; i < cameras.size() && i < 8; ++i)
    known += (i ? ", " : "") + std::to_string(i) + " " + camera_label(scene, cameras[i]);
  if (cameras.size() > 8) known += ", ...";
  throw InputError("--camera " + name_or_index + ": no such camera (the scene has " + known + ")");
}

std::string camera_label(const Scene& scene, uint32_t node) {
  const Node& n = scene.nodes[node];
  std::string label = n.name.empty() ? "#" + std::to_string(node) : n.name;
  const std::string& camera = scene.cameras[size_t(n.camera)].name;
  if (!camera.empty() && camera != n.name) label += " (" + camera + ")";
  return label;
}

}  // namespace hipr
