#include "image/png_chunks.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "core/error.h"

namespace hipr {
namespace {

constexpr std::array<unsigned char, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr uint32_t kMaxChunkLength = 0x7fffffff;  // PNG: a length is at most 2^31 - 1
constexpr uintmax_t kChunkHead = 8;               // length and type
constexpr uintmax_t kChunkCrc = 4;

uint32_t big_endian_u32(const unsigned char* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

// The chunk type as text for a message; bytes outside letters as '?' (a hostile file's are
// anything).
std::string type_name(const unsigned char* type) {
  std::string name(reinterpret_cast<const char*>(type), 4);
  for (char& c : name)
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'))) c = '?';
  return name;
}

}  // namespace

void scan_png_chunks(const std::filesystem::path& path) {
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) throw InputError("PNG file " + path.string() + " cannot be read");
  std::array<unsigned char, kSignature.size()> signature{};
  if (!in.read(reinterpret_cast<char*>(signature.data()), std::streamsize(signature.size())) ||
      signature != kSignature)
    return;
  uintmax_t at = kSignature.size();
  while (size - at >= kChunkHead) {
    std::array<unsigned char, kChunkHead> head{};
    if (!in.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size())))
      throw InputError("PNG file " + path.string() + " cannot be read");
    at += kChunkHead;
    const uint32_t length = big_endian_u32(head.data());
    const std::string type = type_name(head.data() + 4);
    if (length > kMaxChunkLength || uintmax_t(length) + kChunkCrc > size - at)
      throw InputError("PNG file " + path.string() + " has a " + type + " chunk of " +
                       std::to_string(length) + " bytes that runs past the end of the file (" +
                       std::to_string(size - at) + " bytes left, its CRC included)");
    if (std::memcmp(head.data() + 4, "IEND", 4) == 0) return;
    at += length + kChunkCrc;
    in.seekg(std::streamoff(at));
  }
}

}  // namespace hipr
