#include "image/debug_images.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "shaders/shared/abi.h"

namespace hipr {
namespace {

using Colour = std::array<float, 3>;

Colour id_colour(uint32_t id) {
  uint32_t h = id * 2654435761u + 0x9e3779b9u;
  h ^= h >> 15;
  h *= 0x2c1b3c6du;
  h ^= h >> 12;
  // Bright, saturated colours: each channel in [0.15, 1].
  return {0.15f + 0.85f * float(h & 0xff) / 255.0f, 0.15f + 0.85f * float((h >> 8) & 0xff) / 255.0f,
          0.15f + 0.85f * float((h >> 16) & 0xff) / 255.0f};
}

// v in [0, 1]: black -> red -> yellow -> white.
Colour heat_colour(float v) {
  return {std::min(1.0f, 3.0f * v), std::clamp(3.0f * v - 1.0f, 0.0f, 1.0f),
          std::clamp(3.0f * v - 2.0f, 0.0f, 1.0f)};
}

template <typename TileColour>
ImageRGB per_tile(uint32_t tiles_x, uint32_t tile_size, uint32_t width, uint32_t height,
                  TileColour colour_of) {
  ImageRGB image{width, height, std::vector<float>(size_t(width) * height * 3)};
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const Colour c = colour_of((y / tile_size) * tiles_x + x / tile_size);
      std::copy(c.begin(), c.end(),
                image.rgb.begin() + std::ptrdiff_t((size_t(y) * width + x) * 3));
    }
  return image;
}

}  // namespace

ImageRGB object_id_image(const std::vector<uint32_t>& ids, uint32_t width, uint32_t height) {
  ImageRGB image{width, height, std::vector<float>(size_t(width) * height * 3, 0.0f)};
  for (size_t i = 0; i < ids.size() && i < size_t(width) * height; ++i) {
    if (ids[i] == UINT32_MAX) continue;
    const Colour c = id_colour(ids[i]);
    std::copy(c.begin(), c.end(), image.rgb.begin() + std::ptrdiff_t(i * 3));
  }
  return image;
}

ImageRGB tile_weight_image(const std::vector<double>& weights, const std::vector<uint32_t>& flags,
                           uint32_t tiles_x, uint32_t tile_size, uint32_t width, uint32_t height) {
  const double max_weight =
      weights.empty() ? 0.0 : *std::max_element(weights.begin(), weights.end());
  return per_tile(tiles_x, tile_size, width, height, [&](uint32_t t) -> Colour {
    if (flags[t] & abi::kTileActive) return {0.1f, 0.3f, 1.0f};
    if (!(weights[t] > 0.0) || !(max_weight > 0.0)) return {0.0f, 0.0f, 0.0f};
    // Log scale over six decades below the maximum.
    return heat_colour(
        float(std::clamp(1.0 + std::log10(weights[t] / max_weight) / 6.0, 0.0, 1.0)));
  });
}

ImageRGB error_heat_image(const std::vector<float>& error, float scale, uint32_t width,
                          uint32_t height) {
  ImageRGB image{width, height, std::vector<float>(size_t(width) * height * 3, 0.0f)};
  for (size_t i = 0; i < error.size() && i < size_t(width) * height; ++i) {
    const Colour c = std::isfinite(error[i]) ? heat_colour(std::clamp(error[i] / scale, 0.0f, 1.0f))
                                             : Colour{1.0f, 0.0f, 1.0f};
    std::copy(c.begin(), c.end(), image.rgb.begin() + std::ptrdiff_t(i * 3));
  }
  return image;
}

ImageRGB tile_mask_image(const std::vector<uint32_t>& flags, uint32_t tiles_x, uint32_t tile_size,
                         uint32_t width, uint32_t height) {
  return per_tile(tiles_x, tile_size, width, height, [&](uint32_t t) -> Colour {
    if (flags[t] & abi::kTileActive) return {0.9f, 0.1f, 0.1f};
    if (flags[t] & abi::kTileDiscovered) return {0.1f, 0.8f, 0.2f};
    return {0.05f, 0.05f, 0.05f};
  });
}

}  // namespace hipr
