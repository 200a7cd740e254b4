#include "image/png_chunks.h"

#include <array>
#include <cstring>
#include <string_view>

#include "core/error.h"
#include "core/log.h"

namespace hipr {
namespace {

constexpr uintmax_t kSignatureBytes = 8;
constexpr uint32_t kMaxChunkLength = 0x7fffffff;  // PNG: a length is at most 2^31 - 1
constexpr uintmax_t kChunkHead = 8;               // length and type
constexpr uintmax_t kChunkCrc = 4;

uint32_t big_endian_u32(const unsigned char* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

}  // namespace

void scan_png_chunks(std::istream& in, uintmax_t size, const std::string& named) {
  uintmax_t at = kSignatureBytes;
  in.clear();
  in.seekg(std::streamoff(at));
  while (size >= at && size - at >= kChunkHead) {
    std::array<unsigned char, kChunkHead> head{};
    if (!in.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size())))
      throw InputError("cannot read " + named);
    at += kChunkHead;
    const uint32_t length = big_endian_u32(head.data());
    // A hostile file's type bytes are anything: escaped for the message.
    const std::string type =
        log::printable_line(std::string_view(reinterpret_cast<const char*>(head.data() + 4), 4));
    if (length > kMaxChunkLength || uintmax_t(length) + kChunkCrc > size - at)
      throw InputError(named + " has a " + type + " chunk of " + std::to_string(length) +
                       " bytes that runs past the end of the file (" + std::to_string(size - at) +
                       " bytes left, its CRC included)");
    if (std::memcmp(head.data() + 4, "IEND", 4) == 0) return;
    at += length + kChunkCrc;
    in.seekg(std::streamoff(at));
  }
}

}  // namespace hipr
