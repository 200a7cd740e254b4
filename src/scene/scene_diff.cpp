#include "hipr/scene_diff.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "core/error.h"
#include "scene/default_camera.h"

namespace hipr {
namespace {

bool same_bytes(const MaterialParameters& a, const MaterialParameters& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_light(const PunctualLight& a, const PunctualLight& b) {
  return a.type == b.type && a.color == b.color && a.intensity == b.intensity && a.range == b.range &&
         a.inner_cone == b.inner_cone && a.outer_cone == b.outer_cone;
}

// Per channel after / before, where that is a finite number (a channel that stays 0 scales by 1);
// nullopt where radiance does not follow by a factor (from 0 to more, non-finite values).
std::optional<glm::vec3> channel_factor(glm::vec3 before, glm::vec3 after) {
  glm::vec3 factor(1.0f);
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(before[c]) || !std::isfinite(after[c]) || before[c] < 0.0f || after[c] < 0.0f) return std::nullopt;
    if (before[c] == 0.0f) {
      if (after[c] != 0.0f) return std::nullopt;
      continue;
    }
    factor[c] = after[c] / before[c];
    if (!std::isfinite(factor[c])) return std::nullopt;
  }
  return factor;
}

// The material's emission scaled and nothing else changed.
std::optional<glm::vec3> emission_factor(const MaterialParameters& before, const MaterialParameters& after) {
  MaterialParameters rest = after;
  rest.emission_color = before.emission_color;
  rest.emission_luminance = before.emission_luminance;
  if (!same_bytes(rest, before)) return std::nullopt;
  return channel_factor(before.emission_color * before.emission_luminance,
                        after.emission_color * after.emission_luminance);
}

// The light's intensity or colour scaled and nothing else changed.
std::optional<glm::vec3> light_factor(const PunctualLight& before, const PunctualLight& after) {
  PunctualLight rest = after;
  rest.color = before.color;
  rest.intensity = before.intensity;
  if (!same_light(rest, before)) return std::nullopt;
  return channel_factor(before.color * before.intensity, after.color * after.intensity);
}

}  // namespace

ChangeSet diff_scenes(const Scene& before, const Scene& after) {
  ChangeSet changes;
  const std::vector<Instance> old_instances = before.instances();
  const std::vector<Instance> new_instances = after.instances();
  if (old_instances.size() != new_instances.size() || before.materials.size() != after.materials.size() ||
      before.lights.size() != after.lights.size())
    throw InternalError("scene diff between different scenes");

  // Whether every change so far is an emitter scaled by a factor (emitter_scales).
  bool linear = true;
  std::vector<EmitterScale> scales;
  std::vector<bool> material_changed(after.materials.size(), false);
  for (size_t m = 0; m < after.materials.size(); ++m) {
    if (same_bytes(before.materials[m].params, after.materials[m].params)) continue;
    material_changed[m] = true;
    changes.materials = true;
    if (material_emits(before.materials[m].params) || material_emits(after.materials[m].params)) changes.light_tables = true;
    const std::optional<glm::vec3> factor = emission_factor(before.materials[m].params, after.materials[m].params);
    if (factor) scales.push_back({EmitterScale::Kind::Material, uint32_t(m), *factor});
    else linear = false;
  }

  for (size_t i = 0; i < new_instances.size(); ++i) {
    const Instance& a = old_instances[i];
    const Instance& b = new_instances[i];
    bool changed = a.world != b.world || a.visible != b.visible;
    if (changed) {
      linear = false;
      changes.transforms = true;
      for (const MeshPrimitive& p : after.meshes[b.mesh].primitives)
        if (material_emits(after.materials[p.material].params)) changes.light_tables = true;
    }
    for (const MeshPrimitive& p : after.meshes[b.mesh].primitives) changed = changed || material_changed[p.material];
    if (changed) changes.instances.push_back(uint32_t(i));
  }

  for (uint32_t n = 0; n < after.nodes.size(); ++n) {
    const int light = after.nodes[n].light;
    if (light < 0) continue;
    // A light node the scene before did not have counts as moved (edits add none today; a camera
    // edit may add its camera's node).
    const glm::mat4 new_world = after.world_transform(n);
    const glm::mat4 old_world = n < before.nodes.size() ? before.world_transform(n) : new_world;
    const bool moved = n >= before.nodes.size() || old_world != new_world;
    if (moved || !same_light(before.lights[size_t(light)], after.lights[size_t(light)])) {
      changes.lights.push_back({n, {before.lights[size_t(light)], old_world}, {after.lights[size_t(light)], new_world}});
      changes.light_tables = true;
      const std::optional<glm::vec3> factor =
          moved ? std::nullopt : light_factor(before.lights[size_t(light)], after.lights[size_t(light)]);
      if (factor) scales.push_back({EmitterScale::Kind::PunctualLight, n, *factor});
      else linear = false;
    }
  }

  const Camera old_camera = resolve_camera(before);
  const Camera new_camera = resolve_camera(after);
  changes.camera = old_camera.camera_to_world != new_camera.camera_to_world || old_camera.yfov != new_camera.yfov;
  if (changes.camera) changes.camera_before = old_camera;
  if (changes.camera) linear = false;

  const std::optional<Environment>& a = before.environment;
  const std::optional<Environment>& b = after.environment;
  // Maps are told apart by what made them (the snapshot keeps no texels): a file, the studio, or
  // the sky with its sun.
  changes.environment_map = a.has_value() != b.has_value() ||
                            (a && (a->path != b->path || a->sky != b->sky || a->width != b->width ||
                                   a->height != b->height));
  if (changes.environment_map || (a && (a->intensity != b->intensity || a->rotation != b->rotation))) {
    changes.environment = true;
    // The light-selection CDF weighs the environment by its mean radiance x intensity.
    changes.light_tables = true;
    const std::optional<glm::vec3> factor =
        changes.environment_map || a->rotation != b->rotation
            ? std::nullopt
            : channel_factor(glm::vec3(a->intensity), glm::vec3(b->intensity));
    if (factor) scales.push_back({EmitterScale::Kind::Environment, 0, *factor});
    else linear = false;
  }
  if (linear) changes.emitter_scales = std::move(scales);
  return changes;
}

Scene diff_snapshot(const Scene& scene) {
  Scene s;
  s.source = scene.source;
  s.nodes = scene.nodes;
  s.materials = scene.materials;
  s.lights = scene.lights;
  s.cameras = scene.cameras;
  s.root_nodes = scene.root_nodes;
  s.children = scene.children;
  // Without a camera node the default camera frames the scene's bounds: keep positions then.
  const bool need_positions = scene.camera_node() < 0;
  s.meshes.reserve(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) {
    Mesh copy;
    copy.name = mesh.name;
    for (const MeshPrimitive& primitive : mesh.primitives) {
      MeshPrimitive p;
      p.material = primitive.material;
      if (need_positions) p.positions = primitive.positions;
      copy.primitives.push_back(std::move(p));
    }
    s.meshes.push_back(std::move(copy));
  }
  if (scene.environment) {
    Environment env;
    env.path = scene.environment->path;
    env.sky = scene.environment->sky;
    env.width = scene.environment->width;
    env.height = scene.environment->height;
    env.intensity = scene.environment->intensity;
    env.rotation = scene.environment->rotation;
    s.environment = std::move(env);
  }
  return s;
}

}  // namespace hipr
