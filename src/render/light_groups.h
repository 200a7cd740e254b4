#pragma once
// Light groups (relighting by linearity, docs/method.md#relighting): the emitters whose share of
// every pixel's radiance the film keeps apart, so that an edit of their intensity or colour
// rescales the converged image exactly. Chosen once, when the renderer is made, from what emits
// then: the environment, each punctual light, each emissive material, in that order, up to the
// budget (RenderSettings::light_groups); the rest are pooled (never rescaled: their edits
// re-render as any other). An emitter that appears later is pooled too, but for the environment:
// a scene without one keeps a group for it when the budget allows (an edit may switch one on).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hipr/scene.h"
#include "hipr/scene_diff.h"

namespace hipr {

// Group indices; kNoLightGroup (abi::kInvalidIndex) for an emitter that has none.
inline constexpr uint32_t kNoLightGroup = 0xffffffffu;

struct LightGroups {
  uint32_t count = 0;
  uint32_t environment = kNoLightGroup;  // group of the environment
  std::vector<uint32_t> node;            // per node: group of its punctual light
  std::vector<uint32_t> material;        // per material: group of its emission
  std::vector<std::string> names;        // per group: "environment", "light lamp", "emission light"
  std::vector<std::string> pooled;       // emitters over the budget, named alike

  uint32_t of_node(size_t n) const { return n < node.size() ? node[n] : kNoLightGroup; }
  uint32_t of_material(size_t m) const { return m < material.size() ? material[m] : kNoLightGroup; }

  // Per group, the factor an edit scales its radiance by (1 for groups the edit left alone);
  // nullopt when an emitter the edit scaled is pooled.
  std::optional<std::vector<glm::vec3>> factors(const std::vector<EmitterScale>& scales) const;
};

LightGroups assign_light_groups(const Scene& scene, uint32_t budget);

}  // namespace hipr
