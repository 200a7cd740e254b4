#pragma once
// Scene edits: what an artist does in the viewer or an edit script describes
// (docs/method.md#command-line-and-edit-scripts). Edits name nodes and materials by glTF name or
// "#index"; anything unknown is an InputError naming it, never silently ignored.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "hipr/scene.h"

namespace hipr {

struct TransformEdit {
  std::string node;
  std::optional<glm::vec3> translate;  // added to the node's current local translation
  std::optional<glm::mat4> matrix;     // replaces the local transform
};

// OpenPBR parameter name -> value (1 number or 3 for colours).
struct ParameterValue {
  std::string key;
  std::vector<float> values;
};

struct MaterialEdit {
  std::string material;
  std::vector<ParameterValue> set;
};

struct LightEdit {
  std::string node;
  std::optional<float> intensity;
  std::optional<glm::vec3> color;
  std::optional<float> range;
};

struct VisibilityEdit {
  std::string node;
  bool visible = true;
};

struct CameraEdit {
  std::optional<glm::vec3> translate;
  std::optional<glm::mat4> matrix;
};

// The environment map's radiance multiplier and rotation. Scripts give the rotation in
// degrees; it is kept in radians here, as in Environment, so an undo restores it exactly.
struct EnvironmentEdit {
  std::optional<float> intensity;
  std::optional<float> rotation;  // radians about +Y
};

// "emission" edits are material edits restricted to emission keys.
using Edit = std::variant<TransformEdit, MaterialEdit, LightEdit, VisibilityEdit, CameraEdit,
                          EnvironmentEdit>;

// Parses an edit script; throws InputError (naming the file and the edit) on any problem.
std::vector<Edit> load_edit_script(const std::filesystem::path& path);
std::vector<Edit> parse_edit_script(const std::string& json_text, const std::string& name);

// The node an edit names: its glTF name (the first of that name) or "#index"; throws InputError.
size_t find_node(const Scene& scene, const std::string& name);

// Applies one edit to the scene; throws InputError for an unknown node, material or key.
void apply_edit(Scene& scene, const Edit& edit);

// The edit that, applied after `edit`, restores `scene` as it is now (before `edit`): the
// previous matrix, parameter values, light settings, visibility or environment. It looks up
// every name and key as apply_edit does, so it throws the same InputError for an edit that
// apply_edit would refuse (and computing it first keeps a refused edit from half-applying).
Edit inverse_edit(const Scene& scene, const Edit& edit);

// A short human-readable description ("transform tall_block").
std::string describe(const Edit& edit);

// OpenPBR parameter names an edit may set.
std::vector<std::string> material_parameter_names();

}  // namespace hipr
