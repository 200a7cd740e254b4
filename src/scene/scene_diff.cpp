#include "hipr/scene_diff.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "core/error.h"
#include "scene/default_camera.h"

namespace hipr {
namespace {

bool same_bytes(const MaterialParameters& a, const MaterialParameters& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_light(const PunctualLight& a, const PunctualLight& b) {
  return a.type == b.type && a.color == b.color && a.intensity == b.intensity &&
         a.range == b.range && a.inner_cone == b.inner_cone && a.outer_cone == b.outer_cone;
}

// Per channel after / before, where that is a finite number (a channel that stays 0 scales by 1);
// nullopt where radiance does not follow by a factor (from 0 to more, non-finite values).
std::optional<glm::vec3> channel_factor(glm::vec3 before, glm::vec3 after) {
  glm::vec3 factor(1.0f);
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(before[c]) || !std::isfinite(after[c]) || before[c] < 0.0f ||
        after[c] < 0.0f)
      return std::nullopt;
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
std::optional<glm::vec3> emission_factor(const MaterialParameters& before,
                                         const MaterialParameters& after) {
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

// Per node, its instance in `instances`, or -1.
std::vector<int> instance_of_node(const Scene& scene, const std::vector<Instance>& instances) {
  std::vector<int> of(scene.nodes.size(), -1);
  for (size_t i = 0; i < instances.size(); ++i) of[instances[i].node] = int(i);
  return of;
}

bool emits_any(const Scene& scene, uint32_t mesh) {
  for (const MeshPrimitive& p : scene.meshes[mesh].primitives)
    if (material_emits(scene.materials[p.material].params)) return true;
  return false;
}

// A light that was not there (or no longer is): the same light, dark.
PlacedLight dark(PlacedLight light) {
  light.light.intensity = 0.0f;
  return light;
}

}  // namespace

ChangeSet diff_scenes(const Scene& before, const Scene& after) {
  ChangeSet changes;
  const std::vector<Instance> old_instances = before.instances();
  const std::vector<Instance> new_instances = after.instances();

  // Whether every change so far is an emitter scaled by a factor (emitter_scales).
  bool linear = true;
  std::vector<EmitterScale> scales;
  std::vector<bool> material_changed(after.materials.size(), true);  // new ones count as changed
  if (before.materials.size() != after.materials.size()) {
    changes.materials = true;
    linear = false;
  }
  for (size_t m = 0; m < std::min(before.materials.size(), after.materials.size()); ++m) {
    material_changed[m] = false;
    if (same_bytes(before.materials[m].params, after.materials[m].params)) continue;
    material_changed[m] = true;
    changes.materials = true;
    if (material_emits(before.materials[m].params) || material_emits(after.materials[m].params))
      changes.light_tables = true;
    const std::optional<glm::vec3> factor =
        emission_factor(before.materials[m].params, after.materials[m].params);
    if (factor)
      scales.push_back({EmitterScale::Kind::Material, uint32_t(m), *factor});
    else
      linear = false;
  }

  changes.geometry = before.meshes.size() != after.meshes.size();
  for (size_t m = 0; m < std::min(before.meshes.size(), after.meshes.size()); ++m)
    changes.geometry = changes.geometry || before.meshes[m].revision != after.meshes[m].revision;
  // A primitive showing another material (a material variant): its instances change, and the
  // geometry records (and a BLAS whose opacity it changes) are rebuilt.
  std::vector<bool> reassigned(after.meshes.size(), false);
  for (size_t m = 0; m < std::min(before.meshes.size(), after.meshes.size()); ++m) {
    const auto& a = before.meshes[m].primitives;
    const auto& b = after.meshes[m].primitives;
    if (before.meshes[m].revision != after.meshes[m].revision || a.size() != b.size()) continue;
    for (size_t p = 0; p < a.size() && !reassigned[m]; ++p)
      reassigned[m] = a[p].material != b[p].material;
    changes.geometry = changes.geometry || reassigned[m];
  }
  if (changes.geometry) linear = false;

  const std::vector<int> old_of_node = instance_of_node(before, old_instances);
  const std::vector<int> new_of_node = instance_of_node(after, new_instances);
  for (size_t i = 0; i < new_instances.size(); ++i) {
    const Instance& b = new_instances[i];
    const int old = b.node < old_of_node.size() ? old_of_node[b.node] : -1;
    // Another mesh (or the same index holding other vertices) is a new instance.
    const bool same_mesh = old >= 0 && old_instances[size_t(old)].mesh == b.mesh &&
                           before.meshes[b.mesh].revision == after.meshes[b.mesh].revision &&
                           !reassigned[b.mesh];
    bool changed = !same_mesh || old_instances[size_t(old)].world != b.world ||
                   old_instances[size_t(old)].visible != b.visible;
    if (changed) {
      linear = false;
      changes.transforms = true;
      if (emits_any(after, b.mesh) ||
          (old >= 0 && emits_any(before, old_instances[size_t(old)].mesh)))
        changes.light_tables = true;
    }
    for (const MeshPrimitive& p : after.meshes[b.mesh].primitives)
      changed = changed || material_changed[p.material];
    if (changed) changes.instances.push_back(uint32_t(i));
  }
  for (const Instance& a : old_instances) {
    if (a.node < new_of_node.size() && new_of_node[a.node] >= 0) continue;
    changes.departed.push_back(a.node);
    changes.transforms = true;
    linear = false;
    if (emits_any(before, a.mesh)) changes.light_tables = true;
  }

  // Punctual lights, paired by node: one that appeared was dark before, one that left is after.
  const std::vector<uint32_t> old_lights = before.light_nodes();
  const std::vector<uint32_t> new_lights = after.light_nodes();
  const auto placed = [](const Scene& scene, uint32_t n) {
    return PlacedLight{scene.lights[size_t(scene.nodes[n].light)], scene.world_transform(n)};
  };
  const auto had_light = [&](uint32_t n) {
    return std::binary_search(old_lights.begin(), old_lights.end(), n);
  };
  for (uint32_t n : new_lights) {
    const PlacedLight now = placed(after, n);
    if (!had_light(n)) {
      changes.lights.push_back({n, dark(now), now});
      changes.light_tables = true;
      linear = false;
      continue;
    }
    const PlacedLight was = placed(before, n);
    const bool moved = was.world != now.world;
    if (moved || !same_light(was.light, now.light)) {
      changes.lights.push_back({n, was, now});
      changes.light_tables = true;
      const std::optional<glm::vec3> factor =
          moved ? std::nullopt : light_factor(was.light, now.light);
      if (factor)
        scales.push_back({EmitterScale::Kind::PunctualLight, n, *factor});
      else
        linear = false;
    }
  }
  for (uint32_t n : old_lights) {
    if (std::binary_search(new_lights.begin(), new_lights.end(), n)) continue;
    const PlacedLight was = placed(before, n);
    changes.lights.push_back({n, was, dark(was)});
    changes.light_tables = true;
    linear = false;
  }

  const Camera old_camera = resolve_camera(before);
  const Camera new_camera = resolve_camera(after);
  changes.camera =
      old_camera.camera_to_world != new_camera.camera_to_world ||
      old_camera.yfov != new_camera.yfov ||
      old_camera.aperture_radius != new_camera.aperture_radius ||
      (new_camera.aperture_radius > 0.0f && old_camera.focus_distance != new_camera.focus_distance);
  // Reprojection maps each pixel's surface through pinholes: a lens open on either side blurs
  // what it would carry over, so such a change restarts the image (docs/method.md, "Cameras").
  changes.lens = old_camera.aperture_radius > 0.0f || new_camera.aperture_radius > 0.0f;
  if (changes.camera) changes.camera_before = old_camera;
  if (changes.camera) linear = false;

  const std::optional<Environment>& a = before.environment;
  const std::optional<Environment>& b = after.environment;
  // Maps are told apart by what made them (the snapshot keeps no texels): a file, the studio, or
  // the sky with its sun.
  changes.environment_map =
      a.has_value() != b.has_value() || (a && (a->path != b->path || a->sky != b->sky ||
                                               a->width != b->width || a->height != b->height));
  if (changes.environment_map ||
      (a && (a->intensity != b->intensity || a->rotation != b->rotation))) {
    changes.environment = true;
    // The light-selection CDF weighs the environment by its mean radiance x intensity.
    changes.light_tables = true;
    const std::optional<glm::vec3> factor =
        changes.environment_map || a->rotation != b->rotation
            ? std::nullopt
            : channel_factor(glm::vec3(a->intensity), glm::vec3(b->intensity));
    if (factor)
      scales.push_back({EmitterScale::Kind::Environment, 0, *factor});
    else
      linear = false;
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
  s.default_camera = scene.default_camera;
  s.active_camera = scene.active_camera;
  s.root_nodes = scene.root_nodes;
  s.children = scene.children;
  s.loaded_node_count = scene.loaded_node_count;
  s.loaded_light_count = scene.loaded_light_count;
  // Without a camera node or a stored default camera the view frames the scene's bounds: keep
  // positions then.
  const bool need_positions = scene.camera_node() < 0 && !scene.default_camera;
  s.meshes.reserve(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) {
    Mesh copy;
    copy.name = mesh.name;
    copy.revision = mesh.revision;
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
