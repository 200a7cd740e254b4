#pragma once
// Loading a glTF 2.0 scene (.gltf with its files, or .glb): src/scene/scene_loader.cpp.
#include <filesystem>
#include <string>
#include <vector>

#include "hipr/scene.h"

namespace hipr {

struct SceneLoadOptions {
  std::filesystem::path environment;  // equirect .hdr/.exr; empty = black background
  float environment_intensity = 1.0f;
  float environment_rotation_degrees = 0.0f;
};

// Loads a .gltf/.glb scene. Throws InputError (one line) for anything wrong with the input;
// problems that have a sensible fallback (a missing texture image) are logged as warnings.
Scene load_scene(const std::filesystem::path& path, const SceneLoadOptions& options = {});

// glTF extensions the loader understands (used fully or in part); a scene that *requires* any
// other is refused.
const std::vector<std::string>& supported_gltf_extensions();

}  // namespace hipr
