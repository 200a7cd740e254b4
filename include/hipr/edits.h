#pragma once
// Scene edits: what an artist does in the viewer or an edit script describes
// (docs/method.md#command-line-and-edit-scripts). Edits name nodes and materials by glTF name or
// "#index"; anything unknown is an InputError naming it, never silently ignored.
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "hipr/scene.h"

namespace hipr {

// Either `matrix` alone, or any of translate, rotate and scale, composed with the node's
// current local transform by transformed_local (docs/method.md, "transform").
struct TransformEdit {
  std::string node;
  std::optional<glm::vec3> translate;  // added to the node's current local translation
  std::optional<glm::mat4> matrix;     // replaces the local transform
  std::optional<glm::vec3> rotate;     // Euler degrees about the parent's x, y, z (in that order)
                                       // through the node's origin
  std::optional<glm::vec3> scale;      // factors along the node's own axes (nonzero)
};

// The local transform a transform edit gives a node whose local transform is `local`:
// `matrix` when set; else T(t + translate) * R(rotate) * L * S(scale), where t is the current
// translation and L the rest of `local` (rotation about the node's origin in its parent's axes,
// scale along its own axes, so a turned object is stretched, never sheared). Throws InputError
// for a scale factor that is zero, non-finite or beyond 1e6 (or below 1e-6) in size.
glm::mat4 transformed_local(const glm::mat4& local, const TransformEdit& edit);
// The rotation of R(rotate) for Euler degrees (x first, then y, then z, about fixed axes).
glm::mat4 euler_rotation(const glm::vec3& degrees);

// A local transform as the viewer's Selection panel shows it: T * R(rotation) * S(scale).
// local_pose takes a matrix apart (a shear, which glTF cannot hold in TRS either, is dropped;
// a mirrored matrix shows a negative x scale); compose_pose puts one together.
struct LocalPose {
  glm::vec3 translation{0.0f};
  glm::vec3 rotation_degrees{0.0f};  // as euler_rotation takes them
  glm::vec3 scale{1.0f};
};
LocalPose local_pose(const glm::mat4& local);
glm::mat4 compose_pose(const LocalPose& pose);

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

// The view: move the camera node (translate or matrix), look through another camera node
// (`use`: a node name or "#index" whose node carries a camera), open or close its thin lens.
// The lens belongs to the glTF camera the node shows (Camera::aperture_radius). `use` goes
// alone (so its undo is a switch back). Without a camera in the file the default view becomes
// a camera node first.
struct CameraEdit {
  std::optional<glm::vec3> translate;
  std::optional<glm::mat4> matrix;
  std::optional<std::string> use;
  std::optional<float> aperture_radius;  // >= 0, world units
  std::optional<float> focus_distance;   // > 0, along the view axis
};

// What lights the scene from afar, and how bright and turned. Scripts give the rotation in
// degrees; it is kept in radians here, as in Environment, so an undo restores it exactly.
struct EnvironmentEdit {
  bool sets_sun() const { return sun_elevation_degrees || sun_azimuth_degrees || turbidity; }

  // Switches the environment: "studio" or "sky" (built in), "none", or an equirectangular
  // .hdr/.exr file (relative to the current directory; load_edit_script makes a script's
  // paths relative to the script). Intensity and rotation carry over unless set here (1 and 0
  // after "none").
  std::optional<std::filesystem::path> source;
  // The sky's sun and haze (SkyParameters), each kept as it is when not set (the defaults when
  // switching to the sky from another). Without a source they re-make the current sky: an
  // InputError when the environment is not the sky, or a value is out of range.
  std::optional<float> sun_elevation_degrees;
  std::optional<float> sun_azimuth_degrees;
  std::optional<float> turbidity;
  std::optional<float> intensity;
  std::optional<float> rotation;  // radians about +Y
  // Made by inverse_edit only: the exact environment to put back (empty = none), so an undo
  // neither reads a file again nor re-makes a sky. Takes the place of source and the sun.
  std::shared_ptr<const std::optional<Environment>> restore;
};

// Not a change of the scene: where the user looks (docs/method.md#focus), a seed for HiPR's
// order. A script's focus ops add seeds (a node and its subtree, or a disc on screen, weighted)
// until one clears them; EditPipeline hands them to the scheduler. Applying one to a scene
// changes nothing (it checks the node's name), so its inverse is itself.
struct FocusEdit {
  std::optional<std::string> node;
  std::optional<glm::vec2> pixel;  // a disc's centre in pixels (x right, y down)
  float radius = 0.0f;             // the disc's radius in pixels
  float weight = 1.0f;
  bool clear = false;  // drops every seed (and adds none)
};

// Geometry edits (docs/method.md#geometry-edits). Nodes keep their indices through all of them:
// copies and imports are appended, a delete detaches the node from its parent (and drops it
// from the end of the list when an edit appended it there), and the inverses put back exactly
// the hierarchy before. A scene without a camera keeps its view through them
// (Scene::default_camera), whatever they do to its bounds.

// A copy of the node and its subtree beside it (the same parent), moved by `translate` in the
// parent's frame. Copies share the meshes; a copied light is a light of its own. The copy is
// named `as` (empty: "<node>.1", ".2"... whichever is free), its descendants "<as>/<name>".
struct DuplicateEdit {
  std::string node;
  std::string as;
  glm::vec3 translate{0.0f};
};

// Removes the node and its subtree from the scene.
struct DeleteEdit {
  std::string node;
};

// Adds a glTF file's default scene as one new root node `as` (empty: the file's stem) at
// `translate`: its meshes, materials, textures and punctual lights come along, its cameras and
// environment do not. load_edit_script makes a script's path relative to the script's folder
// and refuses one that leaves it.
struct ImportEdit {
  std::filesystem::path file;
  std::string as;
  glm::vec3 translate{0.0f};
};

// Transforms the vertices of the node's mesh by `matrix` (in the mesh's own frame): a change of
// the geometry, which every node using the mesh shows.
struct DeformEdit {
  std::string node;
  glm::mat4 matrix{1.0f};
  // Made by inverse_edit only: the mesh to put back (exactly, instead of the inverse matrix).
  std::shared_ptr<const Mesh> restore;
};

// Shows a KHR_materials_variants variant: its name (or index in `hipr info`'s list), or empty for
// the primitives' default materials. Every primitive the variant maps takes that material.
struct VariantEdit {
  std::string variant;
};

// What a duplicate, delete or import changes: the hierarchy, the lights and cameras (small,
// copied whole) and how many meshes, materials, textures and images there are (those only grow).
struct SceneStructure {
  std::vector<Node> nodes;
  std::vector<uint32_t> root_nodes;
  std::vector<std::vector<uint32_t>> children;
  std::vector<PunctualLight> lights;
  std::vector<Camera> cameras;
  std::vector<std::string> extensions_used;
  std::string content_hash;
  size_t meshes = 0, materials = 0, textures = 0, images = 0;
};

// Made by inverse_edit only (the undo of a duplicate, delete or import): puts the structure back.
struct StructureEdit {
  std::shared_ptr<const SceneStructure> restore;
};

// "emission" edits are material edits restricted to emission keys.
using Edit = std::variant<TransformEdit, MaterialEdit, LightEdit, VisibilityEdit, CameraEdit,
                          EnvironmentEdit, FocusEdit, DuplicateEdit, DeleteEdit, ImportEdit,
                          DeformEdit, StructureEdit, VariantEdit>;

// Whether the edit is a focus op (no change of the scene).
inline bool is_focus(const Edit& edit) { return std::holds_alternative<FocusEdit>(edit); }

// Parses an edit script; throws InputError (naming the file and the edit) on any problem.
std::vector<Edit> load_edit_script(const std::filesystem::path& path);
// `base`: the folder an environment "source" file is relative to (empty: the current one).
std::vector<Edit> parse_edit_script(const std::string& json_text, const std::string& name,
                                    const std::filesystem::path& base = {});

// The node an edit names: its glTF name (the first of that name in the scene) or "#index";
// throws InputError, also for a node that is not in the scene (deleted).
size_t find_node(const Scene& scene, const std::string& name);

// The variant `name` names: a variant's name, else its index in Scene::material_variants; -1
// for an empty name (the default materials). Throws InputError listing the variants otherwise.
int find_material_variant(const Scene& scene, const std::string& name);
// Shows variant `variant` (-1: the defaults): sets every primitive's material.
void select_material_variant(Scene& scene, int variant);

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
