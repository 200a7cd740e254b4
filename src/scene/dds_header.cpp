#include "scene/dds_header.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string_view>

#include "core/log.h"

namespace hipr::gltf {
namespace {

// Offsets into the file: "DDS " then DDS_HEADER (124 bytes) with its DDS_PIXELFORMAT at 76.
constexpr size_t kHeaderEnd = kDdsTexelsAt;
constexpr size_t kSize = 4, kFlags = 8, kHeight = 12, kWidth = 16, kDepth = 24, kMipCount = 28;
constexpr size_t kFormatSize = 76, kFormatFlags = 80, kFourCc = 84, kBitCount = 88, kMasks = 92;
constexpr size_t kCaps2 = 112;

constexpr uint32_t kFlagDepth = 0x800000;
constexpr uint32_t kFlagMipCount = 0x20000;
constexpr uint32_t kFormatAlphaPixels = kDdsAlphaPixels, kFormatAlphaOnly = kDdsAlphaOnly,
                   kFormatFourCc = 0x4, kFormatRgb = kDdsRgb, kFormatLuminance = kDdsLuminance;
constexpr uint32_t kCaps2CubeMap = 0x200, kCaps2Volume = 0x200000;

uint32_t u32(const unsigned char* bytes, size_t at) {
  uint32_t v;
  std::memcpy(&v, bytes + at, 4);
  return v;  // (DDS is little-endian, as every machine hipr builds for)
}

struct BlockFormat {
  const char* four_cc;
  uint32_t block_bytes;  // per 4 x 4 texels
  DdsLayout::Kind kind;
};
using Kind = DdsLayout::Kind;
constexpr std::array<BlockFormat, 7> kBlockFormats{{{"DXT1", 8, Kind::Bc1},
                                                    {"DXT3", 16, Kind::Bc2},
                                                    {"DXT5", 16, Kind::Bc3},
                                                    {"ATI1", 8, Kind::Bc4},
                                                    {"BC4U", 8, Kind::Bc4},
                                                    {"ATI2", 16, Kind::Bc5},
                                                    {"BC5U", 16, Kind::Bc5}}};

}  // namespace

std::string read_dds_header(const unsigned char* bytes, size_t size, DdsLayout* layout) {
  if (size < kHeaderEnd || std::memcmp(bytes, "DDS ", 4) != 0)
    return "is too short for a DDS header";
  if (u32(bytes, kSize) != 124 || u32(bytes, kFormatSize) != 32)
    return "has a malformed DDS header";
  const uint64_t width = u32(bytes, kWidth), height = u32(bytes, kHeight);
  if (width == 0 || height == 0) return "is a DDS image without texels";
  // (So that the sizes below cannot overflow; Direct3D's largest texture is 16384 a side.)
  if (width > (1u << 24) || height > (1u << 24))
    return "is a DDS image larger than any texture (" + std::to_string(width) + "x" +
           std::to_string(height) + ")";
  if ((u32(bytes, kCaps2) & (kCaps2CubeMap | kCaps2Volume)) != 0 ||
      ((u32(bytes, kFlags) & kFlagDepth) != 0 && u32(bytes, kDepth) > 1))
    return "is a DDS cube map or volume, not a 2D texture";

  const uint32_t format = u32(bytes, kFormatFlags);
  uint64_t top_level_bytes = 0;
  if (format & kFormatFourCc) {
    const auto block = std::find_if(
        kBlockFormats.begin(), kBlockFormats.end(),
        [&](const BlockFormat& f) { return std::memcmp(bytes + kFourCc, f.four_cc, 4) == 0; });
    if (block == kBlockFormats.end())
      return "is DDS of format " +
             log::printable_line(
                 std::string_view(reinterpret_cast<const char*>(bytes + kFourCc), 4)) +
             ", which hipr does not decode (it decodes DXT1, DXT3, DXT5, ATI1/BC4U, ATI2/BC5U "
             "and uncompressed texels)";
    top_level_bytes = ((width + 3) / 4) * ((height + 3) / 4) * block->block_bytes;
    layout->kind = block->kind;
  } else if (format & (kFormatRgb | kFormatLuminance | kFormatAlphaOnly)) {
    const uint32_t bits = u32(bytes, kBitCount);
    if (bits != 8 && bits != 16 && bits != 24 && bits != 32)
      return "is uncompressed DDS of " + std::to_string(bits) +
             " bits a texel (hipr decodes 8, 16, 24 or 32)";
    // Every channel the flags name has a mask (the reader looks for a zero mask's lowest set bit
    // forever), and every mask fits in the texel.
    const auto mask = [&](size_t k) { return u32(bytes, kMasks + 4 * k); };
    const bool named_masks_set = (!(format & kFormatRgb) || (mask(0) && mask(1) && mask(2))) &&
                                 (!(format & kFormatLuminance) || mask(0)) &&
                                 (!(format & (kFormatAlphaPixels | kFormatAlphaOnly)) || mask(3));
    const uint32_t all = mask(0) | mask(1) | mask(2) | mask(3);
    if (!named_masks_set || (bits < 32 && (all >> bits) != 0))
      return "is uncompressed DDS whose channel masks do not fit its " + std::to_string(bits) +
             " bits";
    top_level_bytes = width * height * (bits / 8);
    layout->kind = Kind::Uncompressed;
    layout->texel_bytes = bits / 8;
    layout->format_flags = format;
    for (size_t k = 0; k < 4; ++k) layout->masks[k] = mask(k);
  } else {
    return "is DDS of no pixel format hipr decodes";
  }
  if (top_level_bytes > size - kHeaderEnd)
    return "is DDS whose texels run past the end of its bytes";
  if (u32(bytes, kFlags) & kFlagMipCount) {
    uint32_t levels = 1;
    for (uint64_t side = std::max(width, height); side > 1; side /= 2) ++levels;
    if (u32(bytes, kMipCount) > levels) return "is DDS with more mip levels than its size has";
  }
  layout->width = uint32_t(width);
  layout->height = uint32_t(height);
  return "";
}

}  // namespace hipr::gltf
