#pragma once
// The scene model: what a glTF file (plus command-line additions such as an environment map)
// describes. Units: meters, radiance in nits (cd/m^2).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "hipr/material.h"

namespace hipr {

struct MeshPrimitive {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;   // unit length, one per position
  std::vector<glm::vec4> tangents;  // xyz unit, w = bitangent sign; one per position
  std::vector<glm::vec2> uvs;       // TEXCOORD_0, one per position (zeros when absent)
  std::vector<glm::vec2> uvs1;      // TEXCOORD_1, one per position (zeros when absent)
  std::vector<uint32_t> indices;    // triangle list
  uint32_t material = 0;            // the material shown: the active variant's, else the default
  // KHR_materials_variants: the material each variant listed gives the primitive (variant: an
  // index into Scene::material_variants); variants not listed show `default_material`.
  struct VariantMaterial {
    uint32_t variant = 0;
    uint32_t material = 0;
  };
  std::vector<VariantMaterial> variant_materials;
  uint32_t default_material = 0;
};

struct Mesh {
  std::string name;
  std::vector<MeshPrimitive> primitives;
  // A fingerprint of what the primitives hold (mesh_revision), set when they are made or changed
  // (a load, an import, a deform): what copies the mesh (the GPU's buffers, a diff's snapshot)
  // compare to tell whether it changed without comparing vertices. Equal for two loads of one
  // file, so their scenes diff as the same.
  uint64_t revision = 0;
};

// The fingerprint of the mesh's geometry: its primitives' vertices and indices (not their
// materials, which an import renumbers).
uint64_t mesh_revision(const Mesh& mesh);

struct Node {
  std::string name;
  int parent = -1;
  glm::mat4 local{1.0f};
  int mesh = -1;
  int camera = -1;
  int light = -1;
  bool visible = true;
  // Made by the loader for one EXT_mesh_gpu_instancing instance of its parent's mesh (the file
  // has no node for it): an ordinary node to edit and render, saved back into the extension.
  bool gpu_instance = false;
};

// One copy of a mesh: a node with a mesh, with its flattened world transform. Hidden ones
// (the node or an ancestor invisible) are listed too, so instance numbering survives edits.
struct Instance {
  uint32_t node = 0;
  uint32_t mesh = 0;
  glm::mat4 world{1.0f};
  bool visible = true;
};

// Decoded texels of one image, shared by every texture reference that samples it.
struct Image {
  std::string name;
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba8;  // row-major, top row first
  // A fingerprint of the texels (image_revision), set when they are decoded: what tells the GPU's
  // copy that the image at an index is another one (an import after an undone import).
  uint64_t revision = 0;
};

// The fingerprint of the image's size and texels.
uint64_t image_revision(const Image& image);

// One way a material reads an image: colour space, sampler, UV set and UV transform.
struct Texture {
  std::string name;
  uint32_t image = 0;                          // into Scene::images
  uint32_t flags = 0;                          // kTexture* (hipr/material.h)
  glm::vec3 uv_transform_u{1.0f, 0.0f, 0.0f};  // u' = dot(uv_transform_u, (u, v, 1))
  glm::vec3 uv_transform_v{0.0f, 1.0f, 0.0f};
};

struct Material {
  std::string name;
  MaterialParameters params;
};

enum class LightType { Point, Spot, Directional };

struct PunctualLight {
  std::string name;
  LightType type = LightType::Point;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;  // candela (point/spot) or lux (directional), as in KHR_lights_punctual
  float range = 0.0f;      // 0 = infinite
  float inner_cone = 0.0f;
  float outer_cone = 0.7853982f;
  bool operator==(const PunctualLight&) const = default;
};

struct Camera {
  std::string name;
  glm::mat4 camera_to_world{1.0f};  // camera looks down its local -Z, +Y up
  float yfov = 0.8f;                // vertical field of view, radians
  float znear = 0.01f;
  // Thin-lens depth of field (glTF has none: kept in the camera's extras.hipr_lens on save).
  // A radius of 0 is a pinhole; otherwise points at focus_distance along the view axis are
  // sharp (world units, > 0).
  float aperture_radius = 0.0f;
  float focus_distance = 1.0f;
};

// The built-in daylight sky (--env sky, image/builtin_environments.h): where the sun is and how
// hazy the air.
struct SkyParameters {
  float sun_elevation_degrees = 40.0f;  // above the horizon, 0..90
  float sun_azimuth_degrees = 30.0f;    // 0: behind the default camera (+Z), 90: toward +X
  float turbidity = 3.0f;               // haze: 2 clear, 6 hazy, 10 (the model's limit) murky

  bool operator==(const SkyParameters&) const = default;
};
// The range Preetham's model was fitted over.
inline constexpr float kMinTurbidity = 1.7f, kMaxTurbidity = 10.0f;

struct Environment {
  // The file it was read from, or the name of a built-in one ("studio", "sky").
  std::filesystem::path path;
  SkyParameters sky;  // what made it when it is the built-in sky
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<glm::vec3> texels;  // linear RGB, equirectangular, top row = +Y
  float intensity = 1.0f;
  float rotation = 0.0f;  // radians about +Y
};

// Default OpenPBR parameters (the spec's defaults), used for glTF's default material too.
MaterialParameters default_material_params();

// Whether rays may treat the material's triangles as opaque without an alpha test (the
// acceleration structures then mark them VK_GEOMETRY_OPAQUE_BIT_KHR).
bool material_is_opaque(const MaterialParameters& m);

// Whether what the material shows depends on where it is seen from enough that a view's image
// of it does not carry over to another view: refraction, a mirror-like or glossy metal, dielectric
// or coat (HiPR ranks such surfaces first after a camera move, docs/method.md#camera-moves).
// Rough reflections and sheen change with the view too, but slowly: they count as diffuse here.
bool material_is_view_dependent(const MaterialParameters& m);

// Whether the material emits: a positive emission luminance and a colour that is not black (an
// emission texture only multiplies them). NaN counts as not emitting.
bool material_emits(const MaterialParameters& m);

// The texture slots of a material (indices into Scene::textures or abi::kInvalidIndex), in a
// fixed order.
std::vector<uint32_t*> texture_slots(MaterialParameters& m);

struct Scene {
  std::filesystem::path source;
  std::string content_hash;  // of every byte read to build the scene
  std::vector<Node> nodes;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;  // what MaterialParameters texture slots refer to
  std::vector<Image> images;
  std::vector<PunctualLight> lights;
  std::vector<Camera> cameras;  // camera nodes reference these
  // The view of a scene without a camera node: framed around the scene as loaded (or as it was
  // before its first edit) and kept as it is through every edit, so that moving or hiding an
  // object moves the object, not the view. A camera edit turns it into a camera node; saving
  // writes it as one (src/scene/default_camera.h).
  std::optional<Camera> default_camera;
  std::optional<Environment> environment;
  std::vector<std::string> extensions_used;

  // Flattened node hierarchy: nodes with a mesh reachable from the default scene, in a fixed
  // depth-first order.
  std::vector<Instance> instances() const;
  glm::mat4 world_transform(uint32_t node) const;
  // Camera node to render from: `active_camera` when it is a camera node in the scene, else
  // the first node with a camera, or -1 (default_camera then).
  int camera_node() const;
  // The nodes in the scene that carry a camera, depth-first in scene order (what `hipr info`
  // lists and --camera INDEX counts).
  std::vector<uint32_t> camera_nodes() const;
  int active_camera = -1;  // a node chosen by --camera or a camera edit's "use"; -1: the first
  // KHR_materials_variants: the file's named material sets, and the one shown (-1: the
  // primitives' default materials). select_material_variant() sets it and the materials.
  std::vector<std::string> material_variants;
  int active_variant = -1;
  // EXT_mesh_gpu_instancing: per node carrying it, the instances' transforms as loaded (its
  // child nodes with `gpu_instance`, in order), so that an unedited save keeps the extension's
  // data as it was.
  struct GpuInstances {
    uint32_t node = 0;
    std::vector<glm::mat4> loaded;
  };
  std::vector<GpuInstances> gpu_instances;
  // World-space bounds of all instances (min, max); a unit box when empty.
  std::pair<glm::vec3, glm::vec3> bounds() const;
  std::vector<uint32_t> root_nodes;             // of the default scene
  std::vector<std::vector<uint32_t>> children;  // per node

  // Per node, whether it is in the scene: reachable from root_nodes. A deleted node is one no
  // longer reachable (edits detach it from its parent, so that nodes keep their indices; nodes
  // of the file that its default scene does not list are not in the scene either).
  std::vector<bool> reachable_nodes() const;
  // The nodes in the scene that carry a punctual light, in index order.
  std::vector<uint32_t> light_nodes() const;
  // How many nodes and punctual lights the file had: edits append after them and delete only
  // what they appended (the file's own deleted nodes stay, detached, so that saving can patch
  // the file's JSON by index).
  size_t loaded_node_count = 0;
  size_t loaded_light_count = 0;
  // Mesh::revision of each mesh the file had, as loaded (saving writes the deformed ones again).
  std::vector<uint64_t> loaded_mesh_revisions;
};

}  // namespace hipr
