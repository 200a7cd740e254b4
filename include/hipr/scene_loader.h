#pragma once
// Loading a glTF 2.0 scene (.gltf with its files, or .glb): src/scene/scene_loader.cpp.
#include <filesystem>
#include <string>
#include <vector>

#include "hipr/scene.h"

namespace hipr {

// Values of SceneLoadOptions::environment that name no file.
inline constexpr const char* kAutoEnvironment =
    "auto";  // the studio when nothing in the scene emits
inline constexpr const char* kNoEnvironment = "none";

struct SceneLoadOptions {
  // An equirectangular .hdr/.exr, "studio" or "sky" (built in: image/builtin_environments.h),
  // "auto" (the studio when the scene has no light, else none), or "none"; empty = none. (A file
  // with one of these names is reached as ./studio.)
  std::filesystem::path environment;
  float environment_intensity = 1.0f;
  float environment_rotation_degrees = 0.0f;
  SkyParameters sky;
  // The camera node to look through (--camera): its index among the scene's cameras or a name
  // (find_camera_node); empty: the first.
  std::string camera;
  // The KHR_materials_variants variant to show (--variant): its name or index; empty: the
  // primitives' default materials.
  std::string variant;
};

// Loads a .gltf/.glb scene. Throws InputError (one line) for anything wrong with the input;
// problems that have a sensible fallback (a missing texture image) are logged as warnings.
Scene load_scene(const std::filesystem::path& path, const SceneLoadOptions& options = {});

// A glTF extension the loader understands (used fully or in part) and what hipr makes of it.
struct GltfExtension {
  std::string name;
  std::string meaning;  // one line: what it maps to (README, "glTF extensions")
};
const std::vector<GltfExtension>& gltf_extension_table();

// The names of gltf_extension_table(); a scene that *requires* any other is refused.
const std::vector<std::string>& supported_gltf_extensions();

}  // namespace hipr
