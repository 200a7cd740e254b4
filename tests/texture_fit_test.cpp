// Texels that do not fit one storage buffer of the device: the largest images halve first, and
// a halved image is the 2x2 box average of the one before.
#include <gtest/gtest.h>

#include "render/texture_fit.h"

namespace hipr {
namespace {

Image solid(uint32_t w, uint32_t h, uint8_t value) {
  Image image;
  image.width = w;
  image.height = h;
  image.rgba8.assign(size_t(w) * h * 4, value);
  return image;
}

TEST(TextureFit, NothingHalvesWhenEverythingFits) {
  const std::vector<Image> images = {solid(4, 4, 1), solid(2, 2, 1)};
  EXPECT_EQ(texture_halvings(images, 20), (std::vector<uint8_t>{0, 0}));
}

TEST(TextureFit, TheLargestImagesHalveFirst) {
  const std::vector<Image> images = {solid(2, 2, 1), solid(8, 8, 1), solid(4, 4, 1)};
  // 4 + 64 + 16 = 84 texels into 24: the 8x8 halves to 4x4 (36), then, tied with the other 4x4,
  // the first of them to 2x2 (24).
  EXPECT_EQ(texture_halvings(images, 24), (std::vector<uint8_t>{0, 2, 0}));
  // Nothing fits in 2 texels but single texels: every image halves down to one.
  EXPECT_EQ(texture_halvings(images, 2), (std::vector<uint8_t>{1, 3, 2}));
}

TEST(TextureFit, HalvingAveragesBoxesOfFour) {
  Image image = solid(2, 3, 0);
  const uint8_t values[6] = {0, 100, 200, 40, 255, 255};  // per texel, all channels
  for (size_t t = 0; t < 6; ++t)
    for (int c = 0; c < 4; ++c) image.rgba8[t * 4 + size_t(c)] = values[t];
  uint32_t w = 0, h = 0;
  const std::vector<uint32_t> texels = halved_texels(image, 1, w, h);
  ASSERT_EQ(w, 1u);
  ASSERT_EQ(h, 1u);
  EXPECT_EQ(texels[0] & 0xff, (0u + 100 + 200 + 40 + 2) / 4);  // the top 2x2
}

}  // namespace
}  // namespace hipr
