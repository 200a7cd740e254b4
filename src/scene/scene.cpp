#include "hipr/scene.h"

#include <limits>

namespace hipr {

abi::MaterialBlock default_material_params() {
  abi::MaterialBlock m{};
  m.base_weight = 1.0f;
  m.base_color = glm::vec3(0.8f);
  m.base_metalness = 0.0f;
  m.base_diffuse_roughness = 0.0f;
  m.specular_weight = 1.0f;
  m.specular_color = glm::vec3(1.0f);
  m.specular_roughness = 0.3f;
  m.specular_ior = 1.5f;
  m.transmission_color = glm::vec3(1.0f);
  m.subsurface_color = glm::vec3(0.8f);
  m.subsurface_radius = 1.0f;
  m.coat_roughness = 0.0f;
  m.coat_ior = 1.6f;
  m.coat_darkening = 1.0f;
  m.coat_color = glm::vec3(1.0f);
  m.fuzz_color = glm::vec3(1.0f);
  m.fuzz_roughness = 0.5f;
  m.thin_film_thickness = 0.5f;
  m.thin_film_ior = 1.4f;
  m.emission_luminance = 0.0f;
  m.emission_color = glm::vec3(1.0f);
  m.geometry_opacity = 1.0f;
  m.flags = 0;
  m.normal_scale = 1.0f;
  m.base_color_texture = abi::kInvalidIndex;
  m.metallic_roughness_texture = abi::kInvalidIndex;
  m.normal_texture = abi::kInvalidIndex;
  m.emission_texture = abi::kInvalidIndex;
  return m;
}

glm::mat4 Scene::world_transform(uint32_t node) const {
  glm::mat4 world = nodes[node].local;
  // The loader guarantees the parent chain is acyclic.
  for (int parent = nodes[node].parent; parent >= 0; parent = nodes[size_t(parent)].parent)
    world = nodes[size_t(parent)].local * world;
  return world;
}

std::vector<Instance> Scene::instances() const {
  std::vector<Instance> result;
  struct Entry {
    uint32_t node;
    glm::mat4 parent_world;
    bool parent_visible;
  };
  std::vector<Entry> stack;
  for (auto it = root_nodes.rbegin(); it != root_nodes.rend(); ++it) stack.push_back({*it, glm::mat4(1.0f), true});
  while (!stack.empty()) {
    const Entry entry = stack.back();
    stack.pop_back();
    const Node& node = nodes[entry.node];
    const glm::mat4 world = entry.parent_world * node.local;
    const bool visible = entry.parent_visible && node.visible;  // hiding a group hides its subtree
    if (node.mesh >= 0) result.push_back({entry.node, uint32_t(node.mesh), world, visible});
    const auto& kids = children[entry.node];
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) stack.push_back({*it, world, visible});
  }
  return result;
}

int Scene::camera_node() const {
  // Depth-first in scene order, so "the first camera" is what a glTF viewer would pick.
  std::vector<uint32_t> stack(root_nodes.rbegin(), root_nodes.rend());
  while (!stack.empty()) {
    const uint32_t index = stack.back();
    stack.pop_back();
    if (nodes[index].camera >= 0) return int(index);
    const auto& kids = children[index];
    stack.insert(stack.end(), kids.rbegin(), kids.rend());
  }
  return -1;
}

std::pair<glm::vec3, glm::vec3> Scene::bounds() const {
  glm::vec3 lo(std::numeric_limits<float>::max());
  glm::vec3 hi(-std::numeric_limits<float>::max());
  for (const Instance& instance : instances()) {
    if (!instance.visible) continue;
    for (const MeshPrimitive& primitive : meshes[instance.mesh].primitives) {
      for (const glm::vec3& p : primitive.positions) {
        const glm::vec3 w = glm::vec3(instance.world * glm::vec4(p, 1.0f));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
      }
    }
  }
  if (lo.x > hi.x) return {glm::vec3(-1.0f), glm::vec3(1.0f)};
  return {lo, hi};
}

}  // namespace hipr
