#pragma once
// The light table the kernels sample from: every emissive triangle (world space), punctual
// light and the environment, with a CDF proportional to each light's estimated power and the
// light tree over the lights at finite distance (light_tree.h).
#include <vector>

#include "hipr/scene.h"
#include "render/light_groups.h"
#include "shaders/shared/abi.h"

namespace hipr {

// A scene with two to this many punctual lights samples each of them at every vertex, one
// shadow ray each: a punctual light has no noise of its own, so the only noise next-event
// estimation has from it is which light was picked (docs/method.md, "Many-light sampling").
// One punctual light stays in the pick: there is nothing to pick it from but the other emitters,
// and a shadow ray of its own cost more than it gained (cornell_sphere: 0.84x the efficiency).
// (abi::kEachPunctualLights: the trace kernel holds one value per light.)
inline constexpr uint32_t kEachPunctualLights = abi::kEachPunctualLights;

struct LightTables {
  std::vector<abi::Light> lights;
  // Two CDFs of lights.size() + 1 entries each (first 0, last 1): over every light by power
  // (--light-selection power), then over the lights the tree does not hold (tree_cdf_offset).
  std::vector<float> cdf;
  std::vector<abi::LightTreeNode> tree;  // root first; empty when no light at finite distance emits
  // The share of the estimated power the tree's lights hold: how often the tree picks.
  float tree_probability = 0.0f;
  uint32_t tree_cdf_offset() const { return uint32_t(lights.size() + 1); }
  std::vector<uint32_t> record_light_offset;  // per GeometryRecord: first Light, or kInvalidIndex
  // The punctual lights, when there are two to kEachPunctualLights of them, are each sampled at
  // every vertex (lights[each_offset, each_offset + each_count)): neither the tree nor a CDF
  // holds them.
  uint32_t each_offset = 0, each_count = 0;
  uint32_t environment_index = abi::kInvalidIndex;
};

// `record_base[i]` is the first GeometryRecord of instances[i]; records follow the mesh's
// primitive order. `scene_radius` sizes the power estimate of lights at infinity. Each light
// carries its group (`groups`; none where pooled or without groups). `environment_mean` is
// environment_mean_luminance of the scene's map, which callers keep while the map stays: it reads
// every texel, and the tables are built again at every edit that moves or changes a light.
LightTables build_light_tables(const Scene& scene, const std::vector<Instance>& instances,
                               const std::vector<uint32_t>& record_base, uint32_t record_count,
                               float scene_radius, float environment_mean,
                               const LightGroups& groups = {});

// A punctual light as the kernels see it, placed by its node's world transform (no group).
abi::Light punctual_light(const PunctualLight& light, const glm::mat4& world);

// Mean luminance of the environment's texels weighted by solid angle.
float environment_mean_luminance(const Environment& env);

}  // namespace hipr
