#include "render/light_groups.h"

#include <algorithm>

#include "shaders/shared/abi.h"

namespace hipr {
LightGroups assign_light_groups(const Scene& scene, uint32_t budget) {
  static_assert(kNoLightGroup == abi::kInvalidIndex, "the kernels read kInvalidIndex as no group");
  budget = std::min(budget, abi::kMaxLightGroups);
  LightGroups groups;
  groups.node.assign(scene.nodes.size(), kNoLightGroup);
  groups.material.assign(scene.materials.size(), kNoLightGroup);
  const auto add = [&](uint32_t& slot, std::string name) {
    if (groups.count < budget) {
      slot = groups.count++;
      groups.names.push_back(std::move(name));
    } else {
      groups.pooled.push_back(std::move(name));
    }
  };
  if (scene.environment) add(groups.environment, "environment");
  for (uint32_t n : scene.light_nodes())
    add(groups.node[n],
        "light " + (scene.nodes[n].name.empty() ? "#" + std::to_string(n) : scene.nodes[n].name));
  // Emissive materials that some instance (shown or hidden) uses.
  std::vector<bool> used(scene.materials.size(), false);
  for (const Instance& instance : scene.instances())
    for (const MeshPrimitive& p : scene.meshes[instance.mesh].primitives) used[p.material] = true;
  for (size_t m = 0; m < scene.materials.size(); ++m)
    if (used[m] && material_emits(scene.materials[m].params))
      add(groups.material[m],
          "emission " + (scene.materials[m].name.empty() ? "#" + std::to_string(m)
                                                         : scene.materials[m].name));
  // A scene without an environment may get one by an edit (the viewer's Environment panel): a
  // group left over is kept for it, so that its intensity is relit too.
  if (!scene.environment && groups.count < budget) {
    groups.environment = groups.count++;
    groups.names.push_back("environment (none yet)");
  }
  return groups;
}

std::optional<std::vector<glm::vec3>> LightGroups::factors(
    const std::vector<EmitterScale>& scales) const {
  std::vector<glm::vec3> result(count, glm::vec3(1.0f));
  for (const EmitterScale& s : scales) {
    const uint32_t group = s.kind == EmitterScale::Kind::Environment     ? environment
                           : s.kind == EmitterScale::Kind::PunctualLight ? of_node(s.index)
                                                                         : of_material(s.index);
    if (group == kNoLightGroup) return std::nullopt;
    result[group] *= s.factor;
  }
  return result;
}

}  // namespace hipr
