#pragma once
// EXT_meshopt_compression: bufferViews stored as meshoptimizer streams, decoded with Debian's
// libmeshoptimizer into the bufferView's own bytes before any accessor is read. The decoded
// bytes usually live in a "fallback" buffer that has a length but no data at all (given its size
// here: gltf_parser_input.h stubbed it for the parser).
#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "scene/gltf_parser_input.h"

namespace hipr::gltf {

// Gives the fallback buffers their size, then decodes every compressed bufferView (checked
// against its buffers, its mode and filter) into place. Throws InputError naming the first
// bufferView that is malformed or whose stream does not decode.
void decode_meshopt_views(tinygltf::Model& model, const std::vector<FallbackBuffer>& fallbacks,
                          const std::string& name);

}  // namespace hipr::gltf
