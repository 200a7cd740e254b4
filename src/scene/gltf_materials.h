#pragma once
// glTF material -> OpenPBR parameter block (the mapping: gltf_material_table.cpp).
#include <tiny_gltf.h>

#include "hipr/scene.h"
#include "scene/gltf_textures.h"

namespace hipr::gltf {

// `file` names the scene in error messages. The mapping of map_material_factors(), the
// textures, then the hipr_openpbr extras (gltf_hipr_extras.h).
Material convert_material(const tinygltf::Material& material, size_t index, TextureTable& textures,
                          const std::string& file);

// What a material's numbers alone map to: core factors, alpha mode, extension rows and rules,
// no textures (every slot kInvalidIndex) and no extras. `what` names it in error messages.
MaterialParameters map_material_factors(const tinygltf::Material& material,
                                        const std::string& what);

// glTF's default material (for primitives without one) as OpenPBR parameters.
MaterialParameters default_gltf_material_params();

}  // namespace hipr::gltf
