#include "render/texture_fit.h"

#include <algorithm>
#include <cstring>

namespace hipr {
namespace {

uint32_t halved(uint32_t side, uint8_t times) { return std::max(side >> times, 1u); }

uint64_t texels_of(const Image& image, uint8_t times) {
  return uint64_t(halved(image.width, times)) * halved(image.height, times);
}

}  // namespace

std::vector<uint8_t> texture_halvings(const std::vector<Image>& images, uint64_t max_texels) {
  std::vector<uint8_t> halvings(images.size(), 0);
  uint64_t total = 0;
  for (const Image& image : images) total += texels_of(image, 0);
  while (total > max_texels) {
    size_t largest = 0;
    for (size_t i = 1; i < images.size(); ++i)
      if (texels_of(images[i], halvings[i]) > texels_of(images[largest], halvings[largest]))
        largest = i;
    const uint64_t before = texels_of(images[largest], halvings[largest]);
    if (before <= 1) break;  // every image is one texel: nothing left to halve
    ++halvings[largest];
    total -= before - texels_of(images[largest], halvings[largest]);
  }
  return halvings;
}

std::vector<uint32_t> halved_texels(const Image& image, uint8_t halvings, uint32_t& width,
                                    uint32_t& height) {
  width = image.width;
  height = image.height;
  std::vector<uint8_t> rgba = image.rgba8;
  for (uint8_t step = 0; step < halvings; ++step) {
    const uint32_t w = std::max(width / 2, 1u), h = std::max(height / 2, 1u);
    std::vector<uint8_t> next(size_t(w) * h * 4);
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x)
        for (int c = 0; c < 4; ++c) {
          unsigned sum = 0;
          for (uint32_t dy = 0; dy < 2; ++dy)
            for (uint32_t dx = 0; dx < 2; ++dx) {
              const uint32_t sx = std::min(2 * x + dx, width - 1);
              const uint32_t sy = std::min(2 * y + dy, height - 1);
              sum += rgba[(size_t(sy) * width + sx) * 4 + size_t(c)];
            }
          next[(size_t(y) * w + x) * 4 + size_t(c)] = uint8_t((sum + 2) / 4);
        }
    rgba = std::move(next);
    width = w;
    height = h;
  }
  std::vector<uint32_t> texels(size_t(width) * height);
  std::memcpy(texels.data(), rgba.data(), texels.size() * 4);
  return texels;
}

}  // namespace hipr
