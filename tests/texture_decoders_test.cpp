// The extension-image decoders. hipr's own DDS decoder (dds_decode.h) against OpenImageIO's DDS
// reader, which hipr used before: random texels of every kind hipr accepts, on images whose size
// is no multiple of the 4 x 4 blocks, decode to the same channels and values. WebP (libwebp) and
// DDS: a size claimed beyond hipr's limits, or bytes cut short, are refused before a texel is
// written.
#include "scene/dds_decode.h"
#include "scene/webp_decode.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace hipr {
namespace {

struct Kind {
  std::string name;
  const char* four_cc;  // nullptr: uncompressed
  uint32_t format_flags, bits;
  std::array<uint32_t, 4> masks;  // R (or luminance), G, B, A
};

constexpr uint32_t kFourCc = 0x4, kRgb = 0x40, kAlpha = 0x1, kAlphaOnly = 0x2, kLuminance = 0x20000;

std::vector<unsigned char> random_dds(const Kind& kind, uint32_t w, uint32_t h, uint32_t seed) {
  std::vector<uint32_t> header(32, 0);
  std::memcpy(header.data(), "DDS ", 4);
  header[1] = 124;
  header[2] = 0x1 | 0x2 | 0x4 | 0x1000;
  header[3] = h;
  header[4] = w;
  header[19] = 32;
  header[20] = kind.format_flags;
  if (kind.four_cc) std::memcpy(&header[21], kind.four_cc, 4);
  header[22] = kind.bits;
  for (int k = 0; k < 4; ++k) header[23 + k] = kind.masks[k];
  header[27] = 0x1000;
  std::vector<unsigned char> bytes(128);
  std::memcpy(bytes.data(), header.data(), 128);
  const bool small_blocks =
      kind.four_cc && (std::string(kind.four_cc) == "DXT1" || std::string(kind.four_cc) == "ATI1" ||
                       std::string(kind.four_cc) == "BC4U");
  const size_t texel_bytes = kind.four_cc ? ((w + 3) / 4) * ((h + 3) / 4) * (small_blocks ? 8 : 16)
                                          : w * h * kind.bits / 8;
  std::mt19937 random(seed);
  for (size_t i = 0; i < texel_bytes; ++i) bytes.push_back(uint8_t(random()));
  return bytes;
}

struct Decoded {
  int width = 0, height = 0, channels = 0;
  std::vector<unsigned char> texels;
};

Decoded with_openimageio(std::vector<unsigned char> bytes) {
  OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
  auto input = OIIO::ImageInput::create("dds");
  EXPECT_TRUE(input && input->set_ioproxy(&memory));
  OIIO::ImageSpec spec;
  if (!input->open("texture.dds", spec, OIIO::ImageSpec())) {
    ADD_FAILURE() << input->geterror();
    return {};
  }
  Decoded d{spec.width, spec.height, spec.nchannels, {}};
  d.texels.resize(size_t(d.width) * d.height * d.channels);
  EXPECT_TRUE(input->read_image(0, 0, 0, d.channels, OIIO::TypeDesc::UINT8, d.texels.data()));
  return d;
}

Decoded with_hipr(const std::vector<unsigned char>& bytes) {
  tinygltf::Image image;
  std::string err;
  EXPECT_TRUE(gltf::decode_dds(&image, bytes.data(), bytes.size(), 1 << 20, 4096, &err)) << err;
  return {image.width, image.height, image.component, image.image};
}

TEST(DdsDecode, EveryAcceptedKindDecodesAsOpenImageIoDid) {
  const std::vector<Kind> kinds = {
      {"DXT1", "DXT1", kFourCc, 0, {}},
      {"DXT3", "DXT3", kFourCc, 0, {}},
      {"DXT5", "DXT5", kFourCc, 0, {}},
      {"ATI1", "ATI1", kFourCc, 0, {}},
      {"BC4U", "BC4U", kFourCc, 0, {}},
      {"ATI2", "ATI2", kFourCc, 0, {}},
      {"BC5U", "BC5U", kFourCc, 0, {}},
      {"BGRA8", nullptr, kRgb | kAlpha, 32, {0xff0000, 0xff00, 0xff, 0xff000000}},
      {"RGBX8", nullptr, kRgb, 32, {0xff, 0xff00, 0xff0000, 0}},
      {"BGR8", nullptr, kRgb, 24, {0xff0000, 0xff00, 0xff, 0}},
      {"R5G6B5", nullptr, kRgb, 16, {0xf800, 0x07e0, 0x001f, 0}},
      {"A4R4G4B4", nullptr, kRgb | kAlpha, 16, {0x0f00, 0x00f0, 0x000f, 0xf000}},
      {"A1R5G5B5", nullptr, kRgb | kAlpha, 16, {0x7c00, 0x03e0, 0x001f, 0x8000}},
      {"L8", nullptr, kLuminance, 8, {0xff, 0, 0, 0}},
      {"L8A8", nullptr, kLuminance | kAlpha, 16, {0xff, 0, 0, 0xff00}},
      {"A8", nullptr, kAlphaOnly, 8, {0, 0, 0, 0xff}},
  };
  for (const Kind& kind : kinds)
    for (const auto& [w, h] : {std::pair<uint32_t, uint32_t>{10, 7}, {1, 1}, {4, 4}}) {
      const std::vector<unsigned char> dds = random_dds(kind, w, h, w * 31 + h);
      const Decoded expected = with_openimageio(dds);
      const Decoded decoded = with_hipr(dds);
      const std::string what = kind.name + " " + std::to_string(w) + "x" + std::to_string(h);
      ASSERT_EQ(decoded.width, expected.width) << what;
      ASSERT_EQ(decoded.height, expected.height) << what;
      ASSERT_EQ(decoded.channels, expected.channels) << what;
      ASSERT_EQ(decoded.texels.size(), expected.texels.size()) << what;
      int worst = 0;
      for (size_t i = 0; i < decoded.texels.size(); ++i)
        worst = std::max(worst, std::abs(int(decoded.texels[i]) - int(expected.texels[i])));
      // Block formats interpolate between end points, and leave the rounding to the decoder:
      // OpenImageIO 2.4 truncates some values, hipr rounds each to the nearest (exact values
      // are checked below). Uncompressed channels are the same bit for bit.
      EXPECT_LE(worst, kind.four_cc ? 1 : 0) << what << ": largest difference out of 255";
    }
}

// One block each, worked by hand: interpolated values are the nearest integers.
TEST(DdsDecode, InterpolatedValuesRoundToTheNearest) {
  const auto one_block = [](const char* four_cc, std::vector<unsigned char> block) {
    std::vector<unsigned char> dds = random_dds({four_cc, four_cc, kFourCc, 0, {}}, 4, 4, 1);
    std::copy(block.begin(), block.end(), dds.begin() + 128);
    return with_hipr(dds);
  };
  // BC4: a0 = 210 > a1 = 83, eight values; texel 1 has index 4 ((4 * 210 + 3 * 83) / 7 =
  // 155.57), texel 2 index 3 ((5 * 210 + 2 * 83) / 7 = 173.71), texel 0 index 5.
  const Decoded bc4 = one_block("BC4U", {210, 83, 229, 82, 119, 10, 34, 84});
  ASSERT_EQ(bc4.channels, 1);
  EXPECT_EQ(bc4.texels[0], 137);  // (3 * 210 + 4 * 83) / 7 = 137.43
  EXPECT_EQ(bc4.texels[1], 156);
  EXPECT_EQ(bc4.texels[2], 174);
  // BC1 with c0 = 0x0ac8 <= c1 = 0x3412: three colours and transparent black. c0 expands to
  // (8, 89, 66), c1 to (49, 130, 148); index 2 is their midpoint, rounded half up.
  const Decoded bc1 = one_block("DXT1", {0xc8, 0x0a, 0x12, 0x34, 0b11100110, 0, 0, 0});
  ASSERT_EQ(bc1.channels, 4);
  const std::vector<unsigned char> first(bc1.texels.begin(), bc1.texels.begin() + 16);
  EXPECT_EQ(first, (std::vector<unsigned char>{29, 110, 107, 255, 49, 130, 148, 255, 29, 110, 107,
                                               255, 0, 0, 0, 0}))
      << "texels 0-3: indices 2, 1, 2, 3";
}

// A WebP file of the extended format (VP8X) whose canvas claims `width` x `height`, followed by
// no image: libwebp reads the size from the VP8X chunk alone.
std::vector<unsigned char> webp_canvas(uint32_t width, uint32_t height) {
  std::vector<unsigned char> bytes = {'R', 'I', 'F', 'F', 22, 0, 0, 0, 'W', 'E', 'B', 'P',
                                      'V', 'P', '8', 'X', 10, 0, 0, 0, 0,   0,   0,   0};
  for (const uint32_t side : {width - 1, height - 1})
    for (int k = 0; k < 3; ++k) bytes.push_back(uint8_t(side >> (8 * k)));
  return bytes;
}

TEST(WebpDecode, ASizeBeyondTheLimitsOrBytesCutShortAreRefused) {
  tinygltf::Image image;
  std::string err;
  // (libwebp itself refuses a canvas of 2^32 texels or more.)
  const std::vector<unsigned char> huge = webp_canvas(60000, 60000);
  EXPECT_FALSE(gltf::decode_webp(&image, huge.data(), huge.size(), 1 << 24, 16384, &err));
  EXPECT_NE(err.find("60000x60000, beyond hipr's limit"), std::string::npos) << err;
  EXPECT_TRUE(image.image.empty());
  // Within the limits, but there is no image after the header.
  const std::vector<unsigned char> empty = webp_canvas(64, 64);
  err.clear();
  EXPECT_FALSE(gltf::decode_webp(&image, empty.data(), empty.size(), 1 << 24, 16384, &err));
  EXPECT_FALSE(err.empty());
  EXPECT_TRUE(image.image.empty());
  for (size_t cut = 0; cut < empty.size(); ++cut) {
    err.clear();
    EXPECT_FALSE(gltf::decode_webp(&image, empty.data(), cut, 1 << 24, 16384, &err)) << cut;
    EXPECT_FALSE(err.empty()) << cut;
  }
}

TEST(DdsDecode, ASizeBeyondTheLimitsOrBytesCutShortAreRefused) {
  tinygltf::Image image;
  std::string err;
  const Kind bc1{"DXT1", "DXT1", kFourCc, 0, {}};
  const std::vector<unsigned char> dds = random_dds(bc1, 64, 64, 7);
  EXPECT_TRUE(gltf::decode_dds(&image, dds.data(), dds.size(), 64 * 64, 64, &err)) << err;
  EXPECT_FALSE(gltf::decode_dds(&image, dds.data(), dds.size(), 64 * 64 - 1, 64, &err));
  EXPECT_NE(err.find("64x64, beyond hipr's limit"), std::string::npos) << err;
  EXPECT_FALSE(gltf::decode_dds(&image, dds.data(), dds.size(), 64 * 64, 63, &err));
  // A header claiming 2^32 - 1 texels a side: refused from the header, whatever its bytes.
  std::vector<unsigned char> wide = dds;
  const uint32_t side = 0xffffffffu;
  std::memcpy(wide.data() + 16, &side, 4);
  EXPECT_FALSE(gltf::decode_dds(&image, wide.data(), wide.size(), 1 << 24, 16384, &err));
  EXPECT_FALSE(err.empty());
  // One byte short of the top level.
  EXPECT_FALSE(gltf::decode_dds(&image, dds.data(), dds.size() - 1, 1 << 24, 16384, &err));
  EXPECT_NE(err.find("past the end"), std::string::npos) << err;
}

}  // namespace
}  // namespace hipr
