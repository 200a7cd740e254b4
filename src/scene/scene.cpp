#include "hipr/scene.h"

#include <limits>

#include "core/hash.h"

namespace hipr {

MaterialParameters default_material_params() {
  MaterialParameters m{};
  m.base_weight = 1.0f;
  m.base_color = glm::vec3(0.8f);
  m.base_metalness = 0.0f;
  m.base_diffuse_roughness = 0.0f;
  m.specular_weight = 1.0f;
  m.specular_color = glm::vec3(1.0f);
  m.specular_roughness = 0.3f;
  m.specular_ior = 1.5f;
  m.transmission_color = glm::vec3(1.0f);
  m.transmission_dispersion_scale = 0.0f;
  m.transmission_dispersion_abbe_number = 20.0f;  // OpenPBR's default (and glTF's reference)
  m.subsurface_color = glm::vec3(0.8f);
  m.subsurface_radius = 1.0f;
  m.coat_roughness = 0.0f;
  m.coat_ior = 1.6f;
  m.coat_darkening = 1.0f;
  m.coat_color = glm::vec3(1.0f);
  m.fuzz_color = glm::vec3(1.0f);
  m.fuzz_roughness = 0.5f;
  m.thin_film_thickness = 500.0f;  // nm (OpenPBR's default 0.5 um)
  m.thin_film_ior = 1.4f;
  m.emission_luminance = 0.0f;
  m.emission_color = glm::vec3(1.0f);
  m.geometry_opacity = 1.0f;
  m.flags = 0;
  m.normal_scale = 1.0f;
  m.base_color_texture = kNoTexture;
  m.metallic_roughness_texture = kNoTexture;
  m.normal_texture = kNoTexture;
  m.emission_texture = kNoTexture;
  m.alpha_cutoff = -1.0f;
  m.coat_normal_scale = 1.0f;
  m.thin_film_thickness_min = 0.0f;
  for (uint32_t* texture : texture_slots(m)) *texture = kNoTexture;
  return m;
}

std::vector<uint32_t*> texture_slots(MaterialParameters& m) {
  return {&m.base_color_texture,
          &m.metallic_roughness_texture,
          &m.normal_texture,
          &m.emission_texture,
          &m.transmission_texture,
          &m.clearcoat_texture,
          &m.clearcoat_roughness_texture,
          &m.clearcoat_normal_texture,
          &m.sheen_color_texture,
          &m.sheen_roughness_texture,
          &m.specular_texture,
          &m.specular_color_texture,
          &m.iridescence_texture,
          &m.iridescence_thickness_texture,
          &m.anisotropy_texture};
}

uint64_t image_revision(const Image& image) {
  Hasher hash;
  hash.add(&image.width, sizeof image.width).add(&image.height, sizeof image.height);
  hash.add(image.rgba8.data(), image.rgba8.size());
  return hash.value();
}

uint64_t mesh_revision(const Mesh& mesh) {
  Hasher hash;
  const auto add = [&](const auto& values) {
    const uint64_t count = values.size();
    hash.add(&count, sizeof count);
    hash.add(values.data(), values.size() * sizeof(values[0]));
  };
  for (const MeshPrimitive& p : mesh.primitives) {
    add(p.positions);
    add(p.normals);
    add(p.tangents);
    add(p.uvs);
    add(p.uvs1);
    add(p.indices);
  }
  return hash.value();
}

bool material_is_opaque(const MaterialParameters& m) {
  // A MASK material is tested even at full opacity: its texture alpha may cut it out.
  if (m.alpha_cutoff >= 0.0f) return false;
  const bool texture_alpha =
      m.base_color_texture != kNoTexture && !(m.flags & kMaterialIgnoreTextureAlpha);
  return m.geometry_opacity >= 1.0f && !texture_alpha;
}

bool material_is_view_dependent(const MaterialParameters& m) {
  // Roughness thresholds: a lobe this smooth shows recognisable reflections, whose place on the
  // surface moves with the eye; a dielectric's (4 % at normal incidence) needs to be smoother to
  // stand out than a metal's. Texture factors multiply these parameters, so they bound them.
  constexpr float kGlossyMetal = 0.4f, kGlossyDielectric = 0.2f, kGlossyCoat = 0.3f;
  const bool metal =
      m.base_metalness >= 0.5f && m.specular_weight > 0.0f && m.specular_roughness < kGlossyMetal;
  const bool dielectric = m.specular_weight > 0.0f && m.specular_roughness < kGlossyDielectric;
  const bool coat = m.coat_weight > 0.0f && m.coat_roughness < kGlossyCoat;
  return m.transmission_weight > 0.0f || metal || dielectric || coat;
}

bool material_emits(const MaterialParameters& m) {
  return m.emission_luminance > 0.0f &&
         glm::any(glm::greaterThan(m.emission_color, glm::vec3(0.0f)));
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
  for (auto it = root_nodes.rbegin(); it != root_nodes.rend(); ++it)
    stack.push_back({*it, glm::mat4(1.0f), true});
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

std::vector<uint32_t> Scene::camera_nodes() const {
  // Depth-first in scene order, so "the first camera" is what a glTF viewer would pick.
  std::vector<uint32_t> found;
  std::vector<uint32_t> stack(root_nodes.rbegin(), root_nodes.rend());
  while (!stack.empty()) {
    const uint32_t index = stack.back();
    stack.pop_back();
    if (nodes[index].camera >= 0) found.push_back(index);
    const auto& kids = children[index];
    stack.insert(stack.end(), kids.rbegin(), kids.rend());
  }
  return found;
}

int Scene::camera_node() const {
  const std::vector<uint32_t> all = camera_nodes();
  for (uint32_t node : all)
    if (int(node) == active_camera) return active_camera;
  return all.empty() ? -1 : int(all.front());
}

std::vector<bool> Scene::reachable_nodes() const {
  std::vector<bool> reachable(nodes.size(), false);
  std::vector<uint32_t> stack(root_nodes.begin(), root_nodes.end());
  while (!stack.empty()) {
    const uint32_t index = stack.back();
    stack.pop_back();
    if (reachable[index]) continue;  // the loader guarantees a tree; this only bounds the walk
    reachable[index] = true;
    stack.insert(stack.end(), children[index].begin(), children[index].end());
  }
  return reachable;
}

std::vector<uint32_t> Scene::light_nodes() const {
  const std::vector<bool> reachable = reachable_nodes();
  std::vector<uint32_t> result;
  for (uint32_t n = 0; n < nodes.size(); ++n)
    if (reachable[n] && nodes[n].light >= 0) result.push_back(n);
  return result;
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
