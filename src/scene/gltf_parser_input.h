#pragma once
// What tinygltf 2.7 would refuse in a valid compressed file, set aside before it parses and given
// back after: a meshopt "fallback" buffer has a length but no data (EXT_meshopt_compression), and
// a Draco primitive's index accessor has no bufferView (KHR_draco_mesh_compression). Both are
// filled by the decoders (gltf_meshopt.h, gltf_draco.h).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace hipr::gltf {

// The bytes a buffer must have once its compressed bufferViews are decoded into it.
struct FallbackBuffer {
  size_t index = 0;
  size_t byte_length = 0;
};

// A Draco primitive's "indices", removed from the JSON the parser reads.
struct DracoIndices {
  size_t mesh = 0;
  size_t primitive = 0;
  int accessor = -1;
};

struct ParserInput {
  std::optional<std::vector<unsigned char>> rewritten;  // empty: parse the file as it is
  std::vector<FallbackBuffer> fallbacks;
  std::vector<DracoIndices> draco_indices;
};

// The most bytes of fallback buffers one scene may ask for (the decoded size is the file's word).
inline constexpr size_t kMaxDecodedBytes = size_t(1) << 32;

// The file as tinygltf should read it: each meshopt fallback buffer a 4-byte placeholder, each
// Draco primitive without its "indices" (the document otherwise unchanged; a .glb keeps its BIN
// chunk). Throws InputError for fallback buffers larger in all than kMaxDecodedBytes.
ParserInput prepare_parser_input(const std::vector<unsigned char>& bytes, bool glb,
                                 const std::string& name);

}  // namespace hipr::gltf
