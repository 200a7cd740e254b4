#pragma once
// KHR_materials_variants as the loader reads it: the document's variant names, and per
// primitive which material each variant gives it (select_material_variant shows one).
#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "hipr/scene.h"

namespace hipr::gltf {

// The names in the document's extension ("variant N" for one without a name); none without it.
std::vector<std::string> variant_names(const tinygltf::Model& model, const std::string& name);

// The primitive's mappings, checked against the file's materials and `variant_count` variants.
// Throws InputError naming `what` for a malformed mapping.
std::vector<MeshPrimitive::VariantMaterial> variant_materials(const tinygltf::Model& model,
                                                              const tinygltf::Primitive& source,
                                                              size_t variant_count,
                                                              const std::string& what);

}  // namespace hipr::gltf
