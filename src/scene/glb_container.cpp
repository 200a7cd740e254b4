#include "scene/glb_container.h"

#include <cstring>

#include "core/error.h"

namespace hipr::gltf {
namespace {

constexpr uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

uint32_t read_u32(const std::vector<unsigned char>& bytes, size_t offset) {
  uint32_t value;
  std::memcpy(&value, bytes.data() + offset, 4);
  return value;  // glTF is little-endian, as is every platform we build for
}

}  // namespace

bool looks_like_glb(const std::vector<unsigned char>& bytes) {
  return bytes.size() >= 4 && read_u32(bytes, 0) == kMagic;
}

void check_glb_container(const std::vector<unsigned char>& bytes, const std::string& name) {
  const auto fail = [&](const std::string& why) {
    throw InputError(name + ": invalid GLB: " + why);
  };
  if (bytes.size() < 12) fail("file is shorter than the 12-byte header");
  if (read_u32(bytes, 0) != kMagic) fail("magic is not 'glTF'");
  if (read_u32(bytes, 4) != 2)
    fail("container version " + std::to_string(read_u32(bytes, 4)) + " (expected 2)");
  const uint64_t total = read_u32(bytes, 8);
  if (total != bytes.size())
    fail("header length " + std::to_string(total) + " != file size " +
         std::to_string(bytes.size()));

  uint64_t offset = 12;
  int chunk = 0;
  while (offset < total) {
    if (offset + 8 > total) fail("chunk " + std::to_string(chunk) + " header runs past the end");
    const uint64_t length = read_u32(bytes, size_t(offset));
    const uint32_t type = read_u32(bytes, size_t(offset + 4));
    if (offset + 8 + length > total)
      fail("chunk " + std::to_string(chunk) + " length " + std::to_string(length) +
           " runs past the end of the file");
    if (chunk == 0 && type != kChunkJson) fail("first chunk is not JSON");
    if (chunk == 1 && type != kChunkBin) fail("second chunk is not BIN");
    offset += 8 + length;
    ++chunk;
  }
  if (chunk == 0) fail("no JSON chunk");
}

}  // namespace hipr::gltf
