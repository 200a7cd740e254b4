#include "scene/glb_container.h"

#include <algorithm>
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

std::vector<unsigned char> glb_with_json(const std::vector<unsigned char>& bytes,
                                         const std::string& json) {
  const size_t old_end = 20 + size_t(read_u32(bytes, 12));
  std::string chunk = json;
  chunk.resize((chunk.size() + 3) / 4 * 4,
               ' ');  // chunks are 4-byte aligned, JSON pads with spaces
  const size_t total = 20 + chunk.size() + (bytes.size() - old_end);
  if (total > UINT32_MAX) throw InputError("a GLB of more than 4 GiB cannot be written");
  std::vector<unsigned char> out(total);
  const auto put = [&](size_t at, uint32_t value) { std::memcpy(out.data() + at, &value, 4); };
  put(0, kMagic);
  put(4, 2);
  put(8, uint32_t(total));
  put(12, uint32_t(chunk.size()));
  put(16, kChunkJson);
  std::memcpy(out.data() + 20, chunk.data(), chunk.size());
  std::copy(bytes.begin() + std::ptrdiff_t(old_end), bytes.end(),
            out.begin() + std::ptrdiff_t(20 + chunk.size()));
  return out;
}

}  // namespace hipr::gltf
