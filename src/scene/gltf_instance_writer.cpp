#include "scene/gltf_instance_writer.h"

#include <glm/gtc/quaternion.hpp>

namespace hipr::gltf {
namespace {

constexpr int kFloat = 5126;
constexpr const char* kExtension = "EXT_mesh_gpu_instancing";

// The instances of `group` still shown, in the order the loader made them.
std::vector<glm::mat4> shown_instances(const Scene& scene, const Scene::GpuInstances& group,
                                       const std::vector<bool>& reachable) {
  std::vector<glm::mat4> out;
  for (uint32_t child : scene.children[group.node]) {
    const Node& node = scene.nodes[child];
    if (node.gpu_instance && reachable[child] && node.visible) out.push_back(node.local);
  }
  return out;
}

}  // namespace

void write_gpu_instances(Json& doc, const Scene& scene, BufferWriter& buffer) {
  const std::vector<bool> reachable = scene.reachable_nodes();
  for (const Scene::GpuInstances& group : scene.gpu_instances) {
    const std::vector<glm::mat4> shown = shown_instances(scene, group, reachable);
    if (shown == group.loaded) continue;
    if (shown.empty()) {
      Json& node = doc["nodes"][group.node];
      node.erase("mesh");
      node["extensions"].erase(kExtension);
      if (node["extensions"].empty()) node.erase("extensions");
      continue;
    }
    std::vector<float> translation, rotation, scale;
    // T * R * S, as the loader composed it (a sheared edit keeps its nearest rotation).
    for (const glm::mat4& m : shown) {
      glm::vec3 axes[3] = {glm::vec3(m[0]), glm::vec3(m[1]), glm::vec3(m[2])};
      glm::vec3 s(glm::length(axes[0]), glm::length(axes[1]), glm::length(axes[2]));
      if (glm::determinant(glm::mat3(m)) < 0.0f) s.x = -s.x;  // a mirror: one negative scale
      for (int k = 0; k < 3; ++k) axes[k] = s[k] != 0.0f ? axes[k] / s[k] : glm::vec3(0.0f);
      const glm::quat r = glm::normalize(glm::quat_cast(glm::mat3(axes[0], axes[1], axes[2])));
      translation.insert(translation.end(), {m[3].x, m[3].y, m[3].z});
      rotation.insert(rotation.end(), {r.x, r.y, r.z, r.w});
      scale.insert(scale.end(), {s.x, s.y, s.z});
    }
    // (Accessors first: adding them may move the document's members, so no reference is held.)
    const size_t t = buffer.add_accessor(translation, kFloat, "VEC3", 0);
    const size_t r = buffer.add_accessor(rotation, kFloat, "VEC4", 0);
    const size_t s = buffer.add_accessor(scale, kFloat, "VEC3", 0);
    Json& attributes = doc["nodes"][group.node]["extensions"][kExtension]["attributes"];
    if (shown.size() != group.loaded.size()) attributes = Json::object();
    attributes["TRANSLATION"] = t;
    attributes["ROTATION"] = r;
    attributes["SCALE"] = s;
  }
}

}  // namespace hipr::gltf
