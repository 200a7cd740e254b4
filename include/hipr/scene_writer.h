#pragma once
// Saving an edited scene back to glTF (the viewer's "Save"). What goes where: README.md
// "Saving edited scenes"; the extras keys: src/scene/gltf_hipr_extras.h.
#include <filesystem>

#include "hipr/scene.h"

namespace hipr {
// Writes `scene` (as loaded by load_scene and then edited with apply_edit) as glTF 2.0 to `path`
// (.gltf or .glb). The original file (scene.source) supplies everything edits cannot change
// (meshes, buffers, images, samplers, extensions...); node transforms, node visibility,
// materials, punctual lights and the camera are written from `scene`. The write is atomic
// (temp file + rename, also for any side files). Throws InputError for a bad path/extension or
// an unreadable source.
void save_scene(const Scene& scene, const std::filesystem::path& path);
}  // namespace hipr
