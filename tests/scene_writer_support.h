#pragma once
// Shared by the save_scene tests (scene_writer_test.cpp, gltf_validator_test.cpp): comparing
// scenes field by field, and the edits they save.
#include <string>
#include <vector>

#include "hipr/edits.h"
#include "hipr/scene.h"

namespace hipr::test {

// Non-fatal expectations that `got` (reloaded) equals `want` (edited): nodes (transforms to the
// bit), hierarchy, meshes, every material parameter, textures, images, lights, cameras; and
// extensions_used when `same_extensions` (an edit may add extensions to the file).
void expect_same_scene(const Scene& want, const Scene& got, bool same_extensions);

// Sets every editable OpenPBR parameter of `material`: variant 0 at its minimum (weights and
// colours 0), variants 1 and 2 at different values inside its range (colours above 1 where the
// range allows, rotations negative).
MaterialEdit every_parameter_edit(const std::string& material, int variant);

// Edits of every kind for any scene: move the first mesh node, hide the last, change material
// 0's colour and roughness and two parameters glTF cannot hold, change the first light, move
// the camera (adding one to a scene without).
std::vector<Edit> typical_edits(const Scene& scene);

struct SharedScene {
  std::string file;  // under the shared scenes folder
};
// The shared scenes save_scene is checked on.
std::vector<SharedScene> shared_scenes_to_save();

}  // namespace hipr::test
