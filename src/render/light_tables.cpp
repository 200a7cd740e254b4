#include "render/light_tables.h"
#include "render/light_tree.h"
#include "shaders/shared/abi.h"

#include <cmath>

namespace hipr {
namespace {

constexpr float kPi = 3.14159265358979f;

float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

glm::vec3 emission_of(const MaterialParameters& m) {
  return m.emission_color * m.emission_luminance;
}

glm::vec3 light_direction(const glm::mat4& world) {
  // KHR_lights_punctual: lights shine down their local -Z.
  const glm::vec3 d = glm::vec3(world * glm::vec4(0, 0, -1, 0));
  const float len = glm::length(d);
  return len > 0.0f ? d / len : glm::vec3(0, 0, -1);
}

// Cumulative shares of `power` (non-negative): power.size() + 1 entries from 0 to 1; equal
// shares when nothing has power.
std::vector<float> power_cdf(const std::vector<double>& power) {
  double total = 0.0;
  for (double p : power) total += p;
  std::vector<float> cdf(power.size() + 1, 0.0f);
  double running = 0.0;
  for (size_t i = 0; i < power.size(); ++i) {
    running += power[i];
    cdf[i + 1] = total > 0.0 ? float(running / total) : float(i + 1) / float(power.size());
  }
  cdf.back() = 1.0f;
  return cdf;
}

}  // namespace

float environment_mean_luminance(const Environment& env) {
  double sum = 0.0, weight = 0.0;
  for (uint32_t y = 0; y < env.height; ++y) {
    const double s = std::sin((y + 0.5) / env.height * kPi);
    for (uint32_t x = 0; x < env.width; ++x) {
      sum += s * luminance(env.texels[size_t(y) * env.width + x]);
      weight += s;
    }
  }
  return weight > 0.0 ? float(sum / weight) : 0.0f;
}

abi::Light punctual_light(const PunctualLight& src, const glm::mat4& world) {
  abi::Light light{};
  light.position = glm::vec3(world[3]);
  light.direction = light_direction(world);
  light.intensity = src.color * src.intensity;
  light.range = src.range;
  light.group = abi::kInvalidIndex;
  switch (src.type) {
    case LightType::Point:
      light.type = abi::kLightPoint;
      break;
    case LightType::Spot:
      light.type = abi::kLightSpot;
      light.spotCosOuter = std::cos(src.outer_cone);
      light.spotCosInner = std::cos(src.inner_cone);
      break;
    case LightType::Directional:
      light.type = abi::kLightDirectional;
      break;
  }
  return light;
}

LightTables build_light_tables(const Scene& scene, const std::vector<Instance>& instances,
                               const std::vector<uint32_t>& record_base, uint32_t record_count,
                               float scene_radius, float environment_mean,
                               const LightGroups& groups) {
  LightTables t;
  t.record_light_offset.assign(record_count, abi::kInvalidIndex);
  std::vector<double> power;
  std::vector<LightBounds> bounds;

  for (size_t i = 0; i < instances.size(); ++i) {
    const Instance& instance = instances[i];
    if (!instance.visible) continue;
    const Mesh& mesh = scene.meshes[instance.mesh];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const MeshPrimitive& prim = mesh.primitives[p];
      const MaterialParameters& m = scene.materials[prim.material].params;
      const float radiance = luminance(emission_of(m));
      if (!(radiance > 0.0f) || !std::isfinite(radiance)) continue;
      const bool two_sided = (m.flags & abi::kMaterialDoubleSided) != 0;
      // Every triangle gets an entry (even degenerate ones, with zero power) so that
      // light index = offset + primitive holds on the GPU.
      t.record_light_offset[record_base[i] + p] = uint32_t(t.lights.size());
      for (size_t tri = 0; tri < prim.indices.size() / 3; ++tri) {
        const glm::vec3 a =
            glm::vec3(instance.world * glm::vec4(prim.positions[prim.indices[3 * tri]], 1.0f));
        const glm::vec3 b =
            glm::vec3(instance.world * glm::vec4(prim.positions[prim.indices[3 * tri + 1]], 1.0f));
        const glm::vec3 c =
            glm::vec3(instance.world * glm::vec4(prim.positions[prim.indices[3 * tri + 2]], 1.0f));
        abi::Light light{};
        light.type = abi::kLightTriangle;
        light.geometryRecord = record_base[i] + uint32_t(p);
        light.primitive = uint32_t(tri);
        light.group = groups.of_material(prim.material);
        light.position = a;
        light.edge1 = b - a;
        light.edge2 = c - a;
        light.area = 0.5f * glm::length(glm::cross(b - a, c - a));
        if (!std::isfinite(light.area)) light.area = 0.0f;
        bounds.push_back(light_bounds(light, radiance, two_sided));
        bounds.back().light = uint32_t(t.lights.size());
        t.lights.push_back(light);
        power.push_back(double(radiance) * light.area * kPi * (two_sided ? 2.0 : 1.0));
      }
    }
  }

  // Punctual lights: one per node that references a light. Few of them are each sampled at
  // every vertex: no power (never picked), no leaf.
  const std::vector<uint32_t> light_nodes = scene.light_nodes();
  const bool each = light_nodes.size() >= 2 && light_nodes.size() <= kEachPunctualLights;
  if (each) {
    t.each_offset = uint32_t(t.lights.size());
    t.each_count = uint32_t(light_nodes.size());
  }
  for (uint32_t n : light_nodes) {
    const Node& node = scene.nodes[n];
    abi::Light light = punctual_light(scene.lights[size_t(node.light)], scene.world_transform(n));
    light.group = groups.of_node(n);
    const double lum = luminance(light.intensity);
    switch (light.type) {
      case abi::kLightPoint:
        power.push_back(4.0 * kPi * lum);
        break;
      case abi::kLightSpot:
        power.push_back(2.0 * kPi * (1.0 - light.spotCosOuter) * lum);
        break;
      default:
        power.push_back(lum * kPi * scene_radius * scene_radius);
        break;  // directional
    }
    if (each) {
      power.back() = 0.0;
    } else {
      bounds.push_back(light_bounds(light, 0.0f, false));
      bounds.back().light = uint32_t(t.lights.size());
    }
    t.lights.push_back(light);
  }

  if (scene.environment) {
    abi::Light light{};
    light.type = abi::kLightEnvironment;
    light.group = groups.environment;
    t.environment_index = uint32_t(t.lights.size());
    t.lights.push_back(light);
    const double mean = double(environment_mean) * scene.environment->intensity;
    power.push_back(4.0 * kPi * kPi * scene_radius * scene_radius * mean);
  }

  t.tree = build_light_tree(std::move(bounds), t.lights);
  for (double& p : power) p = (std::isfinite(p) && p > 0.0) ? p : 0.0;
  t.cdf = power_cdf(power);
  // The tree's lights leave the second CDF to the lights at infinity; the tree picks with the
  // share of the power it holds.
  double tree_power = 0.0, total = 0.0;
  for (size_t i = 0; i < power.size(); ++i) {
    total += power[i];
    if (t.lights[i].treeLeaf != abi::kInvalidIndex) {
      tree_power += power[i];
      power[i] = 0.0;
    }
  }
  const std::vector<float> rest = power_cdf(power);
  t.cdf.insert(t.cdf.end(), rest.begin(), rest.end());
  t.tree_probability = t.tree.empty() ? 0.0f : total > 0.0 ? float(tree_power / total) : 1.0f;
  // Nothing else emits: the tree always picks (whatever rounding left of the rest).
  if (tree_power == total && !t.tree.empty()) t.tree_probability = 1.0f;
  return t;
}

}  // namespace hipr
