#include "scene/dds_decode.h"

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

#include "scene/dds_header.h"
#include "scene/decoded_texture.h"

namespace hipr::gltf {
namespace {

using Kind = DdsLayout::Kind;
using Block = std::array<std::array<uint8_t, 4>, 16>;  // 4 x 4 texels, row by row, RGBA

uint32_t little_endian(const unsigned char* bytes, size_t count) {
  uint32_t v = 0;
  for (size_t i = 0; i < count; ++i) v |= uint32_t(bytes[i]) << (8 * i);
  return v;
}

// BC1's colour half (also BC2's and BC3's, which always use four colours): two RGB565 end
// points, then 2-bit indices. With `three_colours` allowed and c0 <= c1, index 2 is the
// midpoint and index 3 transparent black.
void decode_colours(const unsigned char* at, bool three_colours, Block& out) {
  const uint32_t c0 = little_endian(at, 2), c1 = little_endian(at + 2, 2);
  const auto expand = [](uint32_t c) {
    const uint32_t r = (c >> 11) & 31, g = (c >> 5) & 63, b = c & 31;
    return std::array<uint32_t, 3>{(r << 3) | (r >> 2), (g << 2) | (g >> 4), (b << 3) | (b >> 2)};
  };
  const auto e0 = expand(c0), e1 = expand(c1);
  std::array<std::array<uint8_t, 4>, 4> palette{};
  for (int k = 0; k < 3; ++k) {
    palette[0][k] = uint8_t(e0[k]);
    palette[1][k] = uint8_t(e1[k]);
    if (three_colours && c0 <= c1) {
      palette[2][k] = uint8_t((e0[k] + e1[k] + 1) / 2);
      palette[3][k] = 0;
    } else {
      palette[2][k] = uint8_t((2 * e0[k] + e1[k] + 1) / 3);
      palette[3][k] = uint8_t((e0[k] + 2 * e1[k] + 1) / 3);
    }
  }
  palette[0][3] = palette[1][3] = palette[2][3] = 255;
  palette[3][3] = three_colours && c0 <= c1 ? 0 : 255;
  const uint32_t indices = little_endian(at + 4, 4);
  for (int i = 0; i < 16; ++i) out[i] = palette[(indices >> (2 * i)) & 3];
}

// BC3's alpha half, BC4 and each half of BC5: two 8-bit end points, then 3-bit indices; six
// values between them when a0 > a1, otherwise four and then 0 and 255.
void decode_values(const unsigned char* at, int channel, Block& out) {
  const uint32_t a0 = at[0], a1 = at[1];
  std::array<uint8_t, 8> values{uint8_t(a0), uint8_t(a1)};
  if (a0 > a1) {
    for (uint32_t i = 1; i < 7; ++i) values[i + 1] = uint8_t(((7 - i) * a0 + i * a1 + 3) / 7);
  } else {
    for (uint32_t i = 1; i < 5; ++i) values[i + 1] = uint8_t(((5 - i) * a0 + i * a1 + 2) / 5);
    values[6] = 0;
    values[7] = 255;
  }
  uint64_t indices = 0;
  for (int i = 0; i < 6; ++i) indices |= uint64_t(at[2 + i]) << (8 * i);
  for (int i = 0; i < 16; ++i) out[i][channel] = values[(indices >> (3 * i)) & 7];
}

// BC2's alpha half: sixteen 4-bit values.
void decode_explicit_alpha(const unsigned char* at, Block& out) {
  for (int i = 0; i < 16; ++i) out[i][3] = uint8_t(((at[i / 2] >> (4 * (i % 2))) & 15) * 17);
}

int block_channels(Kind kind) { return kind == Kind::Bc4 ? 1 : kind == Kind::Bc5 ? 2 : 4; }

std::vector<unsigned char> decode_blocks(const DdsLayout& layout, const unsigned char* texels) {
  const int channels = block_channels(layout.kind);
  const size_t block_bytes = layout.kind == Kind::Bc1 || layout.kind == Kind::Bc4 ? 8 : 16;
  const uint32_t blocks_x = (layout.width + 3) / 4, blocks_y = (layout.height + 3) / 4;
  std::vector<unsigned char> pixels(size_t(layout.width) * layout.height * size_t(channels));
  Block block{};
  for (uint32_t by = 0; by < blocks_y; ++by)
    for (uint32_t bx = 0; bx < blocks_x; ++bx) {
      const unsigned char* at = texels + (size_t(by) * blocks_x + bx) * block_bytes;
      switch (layout.kind) {
        case Kind::Bc1:
          decode_colours(at, true, block);
          break;
        case Kind::Bc2:
          decode_colours(at + 8, false, block);
          decode_explicit_alpha(at, block);
          break;
        case Kind::Bc3:
          decode_colours(at + 8, false, block);
          decode_values(at, 3, block);
          break;
        case Kind::Bc4:
          decode_values(at, 0, block);
          break;
        case Kind::Bc5:
          decode_values(at, 0, block);
          decode_values(at + 8, 1, block);
          break;
        case Kind::Uncompressed:
          break;
      }
      // The blocks on the right and bottom edges may reach past the image.
      for (uint32_t y = 0; y < 4 && by * 4 + y < layout.height; ++y)
        for (uint32_t x = 0; x < 4 && bx * 4 + x < layout.width; ++x)
          std::memcpy(&pixels[((size_t(by) * 4 + y) * layout.width + bx * 4 + x) * channels],
                      block[y * 4 + x].data(), size_t(channels));
    }
  return pixels;
}

// A channel value of `bits` bits as 8 bits. Up to 8 bits its bits repeat from the top, as
// hardware and most readers expand them (5 bits abcde: abcdeabc; exact for 1, 2, 4 and 8 bits);
// wider channels are rounded to the nearest of 256 steps.
uint8_t to_8_bits(uint32_t value, int bits) {
  if (bits > 8) {
    const uint64_t top = (uint64_t(1) << bits) - 1;
    return uint8_t((uint64_t(value) * 255 + top / 2) / top);
  }
  uint32_t out = 0;
  int filled = 0;
  for (; filled < 8; filled += bits) out = (out << bits) | value;
  return uint8_t(out >> (filled - 8));
}

// Where one channel of an uncompressed texel lies: its mask, the mask's lowest set bit and its
// width (read_dds_header refuses a zero mask for a channel the flags name).
struct ChannelField {
  uint32_t mask;
  int shift;
  int bits;
};

// The channels an uncompressed texel has: R, G, B or luminance, then alpha.
std::vector<ChannelField> channel_fields(const DdsLayout& layout) {
  std::vector<uint32_t> masks;
  if (layout.format_flags & kDdsRgb)
    masks = {layout.masks[0], layout.masks[1], layout.masks[2]};
  else if (layout.format_flags & kDdsLuminance)
    masks = {layout.masks[0]};
  if (layout.format_flags & (kDdsAlphaPixels | kDdsAlphaOnly)) masks.push_back(layout.masks[3]);
  std::vector<ChannelField> fields;
  for (const uint32_t mask : masks) {
    const int shift = std::countr_zero(mask);
    fields.push_back({mask, shift, int(std::bit_width(mask >> shift))});
  }
  return fields;
}

std::vector<unsigned char> decode_uncompressed(const DdsLayout& layout, const unsigned char* texels,
                                               const std::vector<ChannelField>& fields) {
  const size_t channels = fields.size();
  const size_t count = size_t(layout.width) * layout.height;
  std::vector<unsigned char> pixels(count * channels);
  for (size_t i = 0; i < count; ++i) {
    const uint32_t texel = little_endian(texels + i * layout.texel_bytes, layout.texel_bytes);
    for (size_t c = 0; c < channels; ++c)
      pixels[i * channels + c] =
          to_8_bits((texel & fields[c].mask) >> fields[c].shift, fields[c].bits);
  }
  return pixels;
}

}  // namespace

bool decode_dds(tinygltf::Image* image, const unsigned char* bytes, size_t size, size_t max_pixels,
                int max_side, std::string* err) {
  const auto fail = [&](const std::string& why) {
    if (err) *err = why;
    return false;
  };
  DdsLayout layout;
  if (std::string why = read_dds_header(bytes, size, &layout); !why.empty()) return fail(why);
  // (read_dds_header checked that the top level lies within the bytes.)
  if (std::string why = texture_size_problem(layout.width, layout.height, max_pixels, max_side);
      !why.empty())
    return fail(why);
  const int width = int(layout.width), height = int(layout.height);
  const unsigned char* texels = bytes + kDdsTexelsAt;
  if (layout.kind != Kind::Uncompressed) {
    store_texels(image, width, height, block_channels(layout.kind), decode_blocks(layout, texels));
    return true;
  }
  const std::vector<ChannelField> fields = channel_fields(layout);
  store_texels(image, width, height, int(fields.size()),
               decode_uncompressed(layout, texels, fields));
  return true;
}

}  // namespace hipr::gltf
