#pragma once
// KHR_draco_mesh_compression: primitives whose vertices and indices are one Draco stream,
// decoded with Debian's libdraco before any accessor is read. The primitive's accessors (which
// describe the decoded data but have no bufferView) are pointed at the decoded values, as float
// attributes and 32-bit indices, in a buffer appended to the model.
#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "scene/gltf_parser_input.h"

namespace hipr::gltf {

// Throws InputError naming the first primitive whose extension is malformed, whose stream does
// not decode, or whose decoded attributes do not match their accessors. `indices`: the index
// accessors set aside for the parser, given back to their primitives first.
void decode_draco_primitives(tinygltf::Model& model, const std::vector<DracoIndices>& indices,
                             const std::string& name);

}  // namespace hipr::gltf
