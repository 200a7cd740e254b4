#pragma once
// glTF material -> OpenPBR parameter block (the mapping: gltf_material_table.cpp).
#include <tiny_gltf.h>

#include "hipr/scene.h"
#include "scene/gltf_textures.h"

namespace hipr::gltf {

// `file` names the scene in error messages.
Material convert_material(const tinygltf::Material& material, size_t index, TextureTable& textures,
                          const std::string& file);

}  // namespace hipr::gltf
