#include "scene/scene_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "scene/default_camera.h"

namespace hipr {
namespace {

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

bool within(const glm::vec3& p) {
  // Written so that NaN fails too.
  return std::abs(p.x) <= kMaxWorldCoordinate && std::abs(p.y) <= kMaxWorldCoordinate &&
         std::abs(p.z) <= kMaxWorldCoordinate;
}

bool radiance_ok(float value) { return value >= 0.0f && value <= kMaxRadiance; }

struct LocalBox {
  glm::vec3 lo{std::numeric_limits<float>::max()};
  glm::vec3 hi{-std::numeric_limits<float>::max()};
  bool finite = true;
  bool empty() const { return lo.x > hi.x; }
};

LocalBox mesh_box(const Mesh& mesh) {
  LocalBox box;
  for (const MeshPrimitive& primitive : mesh.primitives)
    for (const glm::vec3& p : primitive.positions) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) box.finite = false;
      box.lo = glm::min(box.lo, p);
      box.hi = glm::max(box.hi, p);
    }
  return box;
}

void check_geometry(const Scene& scene, const std::string& what) {
  std::vector<LocalBox> boxes(scene.meshes.size());
  std::vector<bool> boxed(scene.meshes.size(), false);
  for (const Instance& instance : scene.instances()) {
    const std::string& node = scene.nodes[instance.node].name;
    if (!finite(instance.world))
      throw InputError(what + ": node '" + node + "' has a world transform that is not finite");
    if (!boxed[instance.mesh]) {
      boxes[instance.mesh] = mesh_box(scene.meshes[instance.mesh]);
      boxed[instance.mesh] = true;
    }
    const LocalBox& box = boxes[instance.mesh];
    if (!box.finite)
      throw InputError(what + ": mesh of node '" + node + "' has a vertex that is not finite");
    if (box.empty()) continue;
    // The world box's corners bound every vertex (an affine map): checking them checks all.
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 local((corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                            (corner & 4) ? box.hi.z : box.lo.z);
      if (!within(glm::vec3(instance.world * glm::vec4(local, 1.0f))))
        throw InputError(
            what + ": node '" + node +
            "' reaches beyond 1e9 m from the origin (or overflows): its transform is out of range");
    }
  }
}

void check_lights_and_camera(const Scene& scene, const std::string& what) {
  for (const uint32_t n : scene.light_nodes()) {
    const Node& node = scene.nodes[n];
    const glm::mat4 world = scene.world_transform(n);
    if (!finite(world) || !within(glm::vec3(world[3])))
      throw InputError(what + ": light node '" + node.name + "' is placed out of range");
    const PunctualLight& light = scene.lights[size_t(node.light)];
    if (!radiance_ok(light.intensity) || !std::isfinite(light.color.r) ||
        !std::isfinite(light.color.g) || !std::isfinite(light.color.b))
      throw InputError(what + ": light of node '" + node.name +
                       "' has an intensity or colour out of range (at most " + "1e12)");
  }
  for (const Material& material : scene.materials)
    if (!radiance_ok(material.params.emission_luminance))
      throw InputError(what + ": material '" + material.name +
                       "' has an emission luminance out of range (at most 1e12 nits)");
  if (scene.environment && !radiance_ok(scene.environment->intensity))
    throw InputError(what + ": the environment's intensity is out of range (at most 1e12)");
  const int camera_node = scene.camera_node();
  const glm::mat4 view = camera_node >= 0 ? scene.world_transform(uint32_t(camera_node))
                                          : default_view(scene).camera_to_world;
  const Camera camera = resolve_camera(scene);
  bool degenerate = false;
  for (int axis = 0; axis < 3; ++axis)
    degenerate |= glm::length(glm::vec3(camera.camera_to_world[axis])) == 0.0f;
  if (!finite(view) || !finite(camera.camera_to_world) || degenerate || !within(glm::vec3(view[3])))
    throw InputError(what + ": the camera's transform is out of range or degenerate");
}

}  // namespace

void check_scene_limits(const Scene& scene, const std::string& what, bool geometry) {
  if (geometry) check_geometry(scene, what);
  check_lights_and_camera(scene, what);
}

void check_edit_values(const Edit& edit) {
  const auto refuse = [&](const std::string& why) {
    throw InputError(describe(edit) + ": " + why);
  };
  const auto check = [&](const std::optional<float>& value, const char* name) {
    if (value && !radiance_ok(*value))
      refuse(std::string(name) + " " + std::to_string(*value) + " is out of range (0 to 1e12)");
  };
  if (const auto* light = std::get_if<LightEdit>(&edit)) {
    check(light->intensity, "intensity");
    if (light->color)
      check(std::max({light->color->r, light->color->g, light->color->b}), "colour");
    if (light->color && !(std::min({light->color->r, light->color->g, light->color->b}) >= 0.0f))
      refuse("a colour must be finite and >= 0");
    if (light->range && !(*light->range >= 0.0f && std::isfinite(*light->range)))
      refuse("range must be finite and >= 0");
  }
  if (const auto* environment = std::get_if<EnvironmentEdit>(&edit))
    check(environment->intensity, "intensity");
  if (const auto* material = std::get_if<MaterialEdit>(&edit))
    for (const ParameterValue& value : material->set)
      if (value.key == "emission_luminance" && value.values.size() == 1)
        check(value.values[0], "emission_luminance");
}

bool edit_moves_geometry(const Edit& edit) {
  return std::holds_alternative<TransformEdit>(edit) ||
         std::holds_alternative<DuplicateEdit>(edit) || std::holds_alternative<ImportEdit>(edit) ||
         std::holds_alternative<DeformEdit>(edit) || std::holds_alternative<StructureEdit>(edit);
}

}  // namespace hipr
