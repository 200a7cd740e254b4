#pragma once
// The DDS files hipr decodes (MSFT_texture_dds, dds_decode.h): a header checked field by field
// before a texel is read. (OpenImageIO 2.4's DDS reader, which hipr used before, trusted it:
// fuzzing found a division by zero on DXT2 and DXT4, and probing an endless loop on texels of 0
// bits or a channel whose mask is 0.)
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace hipr::gltf {

// What a checked header says about the top level, whose texels start at byte kDdsTexelsAt.
struct DdsLayout {
  enum class Kind { Bc1, Bc2, Bc3, Bc4, Bc5, Uncompressed };
  Kind kind = Kind::Uncompressed;
  uint32_t width = 0, height = 0;
  // Uncompressed only: bytes a texel, the DDS_PIXELFORMAT flags, and the R, G, B, A masks (the
  // luminance mask is R's).
  uint32_t texel_bytes = 0, format_flags = 0;
  std::array<uint32_t, 4> masks{};
};
constexpr size_t kDdsTexelsAt = 128;
// DDS_PIXELFORMAT flags that say which channels an uncompressed texel has.
constexpr uint32_t kDdsAlphaPixels = 0x1, kDdsAlphaOnly = 0x2, kDdsRgb = 0x40,
                   kDdsLuminance = 0x20000;

// "" when the bytes are a DDS file of the kinds real glTF assets ship and hipr decodes, with
// `layout` filled: one 2D image (no cube map, no volume), block-compressed as BC1, BC2, BC3
// (DXT1, DXT3, DXT5), BC4 or BC5 (ATI1/BC4U, ATI2/BC5U), or uncompressed with 8, 16, 24 or 32
// bits a texel, a mask for every channel its flags name and every mask within the texel; its top
// level wholly inside the bytes, and no more mip levels than its size has. Otherwise why not, for
// a warning ("... is DXT2, which ...").
std::string read_dds_header(const unsigned char* bytes, size_t size, DdsLayout* layout);

}  // namespace hipr::gltf
