// Applying edits to the scene model, and their inverses (undo).
#include <algorithm>
#include <cstdio>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "hipr/edits.h"
#include "image/builtin_environments.h"
#include "scene/default_camera.h"
#include "scene/geometry_edits.h"
#include "scene/material_parameters.h"
#include "scene/scene_limits.h"

namespace hipr {
namespace {

// "#index" or a name; with several of the same name, the first wins (as in glTF tools).
template <typename Items, typename NameOf>
size_t find_by_name(const Items& items, const std::string& name, NameOf name_of, const char* kind) {
  if (name.size() > 1 && name[0] == '#') {
    try {
      size_t used = 0;
      const unsigned long index = std::stoul(name.substr(1), &used);
      if (used == name.size() - 1 && index < items.size()) return index;
    } catch (const std::exception&) {
    }
  }
  for (size_t i = 0; i < items.size(); ++i)
    if (name_of(items[i]) == name) return i;
  throw InputError(std::string("no ") + kind + " named '" + name + "' in the scene");
}

size_t find_material(const Scene& scene, const std::string& name) {
  return find_by_name(
      scene.materials, name, [](const Material& m) { return m.name; }, "material");
}

void move_node(glm::mat4& local, const std::optional<glm::vec3>& translate,
               const std::optional<glm::mat4>& matrix) {
  if (matrix)
    local = *matrix;
  else
    local[3] += glm::vec4(*translate, 0.0f);
}

// What apply_edit refuses of a camera edit: a `use` that names no camera node in the scene,
// a lens out of range.
void check_camera_edit(const Scene& scene, const CameraEdit& e) {
  if (e.translate && e.matrix)
    throw InputError("a camera edit moves by translate or matrix, not both");
  if (e.use && (e.translate || e.matrix || e.aperture_radius || e.focus_distance))
    throw InputError("a camera edit that switches cameras (\"use\") changes nothing else");
  if (e.use) {
    const size_t node = find_node(scene, *e.use);
    const std::vector<uint32_t> cameras = scene.camera_nodes();
    if (std::find(cameras.begin(), cameras.end(), uint32_t(node)) == cameras.end())
      throw InputError("camera: node '" + *e.use + "' is not a camera in the scene");
  }
  if (e.aperture_radius && !(*e.aperture_radius >= 0.0f && *e.aperture_radius <= 1e6f))
    throw InputError("camera: the aperture radius must be between 0 and 1e6");
  if (e.focus_distance && !(*e.focus_distance > 0.0f && *e.focus_distance <= 1e12f))
    throw InputError("camera: the focus distance must be above 0 and at most 1e12");
}

// What apply_edit refuses of an environment edit (but a file that cannot be read): without a
// source it changes the current environment, so there must be one; the sun needs the sky.
void check_environment_edit(const Scene& scene, const EnvironmentEdit& e) {
  if (e.restore) return;
  if (!e.source && !scene.environment)
    throw InputError(
        "the scene has no environment to edit (switch one on with \"source\", or --env)");
  const std::filesystem::path target = e.source ? *e.source : scene.environment->path;
  if (e.sets_sun() && target != kSkyEnvironmentName)
    throw InputError("the sun's parameters need the sky environment (\"source\": \"sky\")");
}

// The sky an edit asks for: its values over the current sky's (the defaults when there is none).
SkyParameters edited_sky(const Scene& scene, const EnvironmentEdit& e) {
  SkyParameters sky;
  if (scene.environment && scene.environment->path == kSkyEnvironmentName)
    sky = scene.environment->sky;
  if (e.sun_elevation_degrees) sky.sun_elevation_degrees = *e.sun_elevation_degrees;
  if (e.sun_azimuth_degrees) sky.sun_azimuth_degrees = *e.sun_azimuth_degrees;
  if (e.turbidity) sky.turbidity = *e.turbidity;
  check_sky(sky);
  return sky;
}

struct Applier {
  Scene& scene;

  void operator()(const TransformEdit& e) const {
    glm::mat4& local = scene.nodes[find_node(scene, e.node)].local;
    local = transformed_local(local, e);
  }

  void operator()(const MaterialEdit& e) const {
    MaterialParameters& block = scene.materials[find_material(scene, e.material)].params;
    // Every value checked before any is written: a refused edit changes nothing. (Scripts check
    // ranges as they parse; edits made in code, the viewer's, meet the same ranges here. NaN
    // fails them.)
    for (const ParameterValue& p : e.set) {
      const MaterialParameter* parameter = find_material_parameter(p.key);
      if (!parameter || int(p.values.size()) != parameter->components)
        throw InputError("invalid material parameter '" + p.key + "'");
      for (const float v : p.values)
        if (!(v >= parameter->min && v <= parameter->max))
          throw InputError("material parameter '" + p.key + "' = " + std::to_string(v) +
                           " is outside [" + std::to_string(parameter->min) + ", " +
                           std::to_string(parameter->max) + "]");
    }
    for (const ParameterValue& p : e.set) {
      const MaterialParameter* parameter = find_material_parameter(p.key);
      std::memcpy(reinterpret_cast<char*>(&block) + parameter->offset, p.values.data(),
                  p.values.size() * sizeof(float));
    }
  }

  void operator()(const LightEdit& e) const {
    const Node& node = scene.nodes[find_node(scene, e.node)];
    if (node.light < 0) throw InputError("node '" + e.node + "' has no light");
    PunctualLight& light = scene.lights[size_t(node.light)];
    if (e.intensity) light.intensity = *e.intensity;
    if (e.color) light.color = *e.color;
    if (e.range) light.range = *e.range;
  }

  void operator()(const VisibilityEdit& e) const {
    scene.nodes[find_node(scene, e.node)].visible = e.visible;
  }

  void operator()(const CameraEdit& e) const {
    check_camera_edit(scene, e);
    if (e.use) scene.active_camera = int(find_node(scene, *e.use));
    if (!e.translate && !e.matrix && !e.aperture_radius && !e.focus_distance) return;
    // No camera in the file: materialize the default one so the edit has something to change.
    const size_t node = pin_default_camera(scene);
    if (e.translate || e.matrix) move_node(scene.nodes[node].local, e.translate, e.matrix);
    Camera& camera = scene.cameras[size_t(scene.nodes[node].camera)];
    if (e.aperture_radius) camera.aperture_radius = *e.aperture_radius;
    if (e.focus_distance) camera.focus_distance = *e.focus_distance;
  }

  void operator()(const EnvironmentEdit& e) const {
    if (e.restore) {
      scene.environment = *e.restore;
    } else {
      check_environment_edit(scene, e);
      const SkyParameters sky = edited_sky(scene, e);
      if (e.source || (e.sets_sun() && sky != scene.environment->sky)) {
        std::optional<Environment> next =
            make_environment(e.source.value_or(kSkyEnvironmentName), sky);
        if (next && scene.environment) {  // a switch keeps how bright and turned
          next->intensity = scene.environment->intensity;
          next->rotation = scene.environment->rotation;
        }
        scene.environment = std::move(next);
      }
    }
    if (!scene.environment) return;
    if (e.intensity) scene.environment->intensity = *e.intensity;
    if (e.rotation) scene.environment->rotation = *e.rotation;
  }

  void operator()(const FocusEdit& e) const {
    if (e.node) find_node(scene, *e.node);  // an unknown name is refused like any edit's
  }

  void operator()(const DuplicateEdit& e) const { apply_duplicate(scene, e); }
  void operator()(const DeleteEdit& e) const { apply_delete(scene, e); }
  void operator()(const ImportEdit& e) const { apply_import(scene, e); }
  void operator()(const DeformEdit& e) const { apply_deform(scene, e); }
  void operator()(const StructureEdit& e) const { apply_structure(scene, e); }
  void operator()(const VariantEdit& e) const {
    select_material_variant(scene, find_material_variant(scene, e.variant));
  }
};

// Builds the inverse of an edit from the scene before it (see inverse_edit).
struct Inverter {
  const Scene& scene;

  Edit operator()(const TransformEdit& e) const {
    return TransformEdit{e.node, std::nullopt, scene.nodes[find_node(scene, e.node)].local, {}, {}};
  }

  Edit operator()(const MaterialEdit& e) const {
    const MaterialParameters& block = scene.materials[find_material(scene, e.material)].params;
    MaterialEdit inverse{e.material, {}};
    for (const ParameterValue& p : e.set) {
      const MaterialParameter* parameter = find_material_parameter(p.key);
      if (!parameter || int(p.values.size()) != parameter->components)
        throw InputError("invalid material parameter '" + p.key + "'");
      std::vector<float> old(size_t(parameter->components));
      std::memcpy(old.data(), reinterpret_cast<const char*>(&block) + parameter->offset,
                  old.size() * sizeof(float));
      inverse.set.push_back({p.key, std::move(old)});
    }
    // Every entry holds its key's value before the edit, so a key set twice restores alike.
    return inverse;
  }

  Edit operator()(const LightEdit& e) const {
    const Node& node = scene.nodes[find_node(scene, e.node)];
    if (node.light < 0) throw InputError("node '" + e.node + "' has no light");
    const PunctualLight& light = scene.lights[size_t(node.light)];
    return LightEdit{e.node, light.intensity, light.color, light.range};
  }

  Edit operator()(const VisibilityEdit& e) const {
    return VisibilityEdit{e.node, scene.nodes[find_node(scene, e.node)].visible};
  }

  Edit operator()(const CameraEdit& e) const {
    check_camera_edit(scene, e);
    // Without a camera node the edit creates one holding the default camera: restoring that
    // matrix (and the default's pinhole) renders the same view.
    const int node = scene.camera_node();
    CameraEdit inverse;
    if (e.use) inverse.use = "#" + std::to_string(node);
    const Camera camera = resolve_camera(scene);
    if (e.translate || e.matrix)
      inverse.matrix =
          node >= 0 ? scene.nodes[size_t(node)].local : default_view(scene).camera_to_world;
    if (e.aperture_radius) inverse.aperture_radius = camera.aperture_radius;
    if (e.focus_distance) inverse.focus_distance = camera.focus_distance;
    return inverse;
  }

  Edit operator()(const EnvironmentEdit& e) const {
    check_environment_edit(scene, e);
    if (!e.restore) edited_sky(scene, e);
    if (e.source || e.sets_sun() || e.restore) {
      EnvironmentEdit inverse;
      inverse.restore = std::make_shared<const std::optional<Environment>>(scene.environment);
      return inverse;
    }
    return EnvironmentEdit{.intensity = scene.environment->intensity,
                           .rotation = scene.environment->rotation};
  }

  Edit operator()(const FocusEdit& e) const {
    if (e.node) find_node(scene, *e.node);
    return e;  // the scene is the same before and after
  }

  Edit operator()(const DuplicateEdit& e) const {
    check_duplicate(scene, e);
    return structure_undo(scene);
  }
  Edit operator()(const DeleteEdit& e) const {
    find_node(scene, e.node);
    return structure_undo(scene);
  }
  // (The file is read when the import is applied: a bad one is refused then, changing nothing.)
  Edit operator()(const ImportEdit&) const { return structure_undo(scene); }
  Edit operator()(const DeformEdit& e) const {
    check_deform(scene, e);
    const Node& node = scene.nodes[find_node(scene, e.node)];
    return DeformEdit{e.node, glm::mat4(1.0f),
                      std::make_shared<const Mesh>(scene.meshes[size_t(node.mesh)])};
  }
  Edit operator()(const StructureEdit&) const { return structure_undo(scene); }
  Edit operator()(const VariantEdit& e) const {
    find_material_variant(scene, e.variant);
    return VariantEdit{scene.active_variant < 0
                           ? std::string()
                           : scene.material_variants[size_t(scene.active_variant)]};
  }
};

}  // namespace

size_t find_node(const Scene& scene, const std::string& name) {
  const size_t node = find_by_name(
      scene.nodes, name, [](const Node& n) { return n.name; }, "node");
  const std::vector<bool> in_scene = scene.reachable_nodes();
  if (in_scene[node]) return node;
  // A deleted node of that name (or one the file keeps out of its scene): look for a live one.
  for (size_t n = 0; n < scene.nodes.size(); ++n)
    if (in_scene[n] && scene.nodes[n].name == name) return n;
  throw InputError("no node named '" + name + "' in the scene");
}

Edit inverse_edit(const Scene& scene, const Edit& edit) {
  return std::visit(Inverter{scene}, edit);
}

void apply_edit(Scene& scene, const Edit& edit) {
  // A scene built in code has no default camera until its first edit: the view from before it.
  fix_default_camera(scene);
  check_edit_values(edit);
  const bool geometry = edit_moves_geometry(edit) && !std::holds_alternative<StructureEdit>(edit);
  if (!geometry && !std::holds_alternative<CameraEdit>(edit)) {
    std::visit(Applier{scene}, edit);
    return;
  }
  // Applied, then checked (scene/scene_limits.h): a move or camera that leaves the range the
  // renderer computes in is refused, and the scene is put back exactly as it was.
  const Edit revert = std::holds_alternative<DeformEdit>(edit) ? inverse_edit(scene, edit)
                                                               : Edit(structure_undo(scene));
  std::visit(Applier{scene}, edit);
  try {
    check_scene_limits(scene, "edit " + describe(edit), geometry);
  } catch (const InputError&) {
    std::visit(Applier{scene}, revert);
    throw;
  }
}

std::string describe(const Edit& edit) {
  struct Describer {
    std::string operator()(const TransformEdit& e) const { return "transform " + e.node; }
    std::string operator()(const MaterialEdit& e) const { return "material " + e.material; }
    std::string operator()(const LightEdit& e) const { return "light " + e.node; }
    std::string operator()(const VisibilityEdit& e) const {
      return std::string(e.visible ? "show " : "hide ") + e.node;
    }
    std::string operator()(const CameraEdit&) const { return "camera"; }
    std::string operator()(const EnvironmentEdit& e) const {
      if (e.source) return "environment " + e.source->filename().string();
      return e.sets_sun() ? "environment sun" : "environment";
    }
    std::string operator()(const DuplicateEdit& e) const {
      return "duplicate " + e.node + (e.as.empty() ? "" : " as " + e.as);
    }
    std::string operator()(const DeleteEdit& e) const { return "delete " + e.node; }
    std::string operator()(const ImportEdit& e) const {
      return "import " + e.file.filename().string();
    }
    std::string operator()(const DeformEdit& e) const { return "deform " + e.node; }
    std::string operator()(const StructureEdit&) const { return "restore nodes"; }
    std::string operator()(const VariantEdit& e) const {
      return e.variant.empty() ? "default materials" : "variant " + e.variant;
    }
    std::string operator()(const FocusEdit& e) const {
      if (e.clear) return "focus clear";
      std::string text = "focus";
      if (e.node) text += " " + *e.node;
      if (e.pixel) {
        char disc[96];
        std::snprintf(disc, sizeof disc, " pixel (%g, %g) radius %g", e.pixel->x, e.pixel->y,
                      e.radius);
        text += disc;
      }
      return text;
    }
  };
  return std::visit(Describer{}, edit);
}

std::vector<std::string> material_parameter_names() {
  std::vector<std::string> names;
  for (const MaterialParameter& p : material_parameters()) names.push_back(p.name);
  return names;
}

}  // namespace hipr
