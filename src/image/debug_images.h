#pragma once
// Debug visualisations of the HiPR stages, as sRGB-ready linear images.
#include <cstdint>
#include <vector>

#include "image/image_io.h"

namespace hipr {

// Object ids (the paper's teaser, left): a stable colour per instance, black background.
ImageRGB object_id_image(const std::vector<uint32_t>& instance_per_pixel, uint32_t width,
                         uint32_t height);

// Tile weights as a heat map (log scale, black -> red -> yellow -> white); active tiles blue.
ImageRGB tile_weight_image(const std::vector<double>& weights, const std::vector<uint32_t>& flags,
                           uint32_t tiles_x, uint32_t tile_size, uint32_t width, uint32_t height);

// A per-pixel error as a heat map (black -> red -> yellow -> white over [0, scale]); pixels
// whose error is not finite are magenta.
ImageRGB error_heat_image(const std::vector<float>& error, float scale, uint32_t width,
                          uint32_t height);

// Masks: active tiles red, discovered tiles green, the rest dark grey.
ImageRGB tile_mask_image(const std::vector<uint32_t>& flags, uint32_t tiles_x, uint32_t tile_size,
                         uint32_t width, uint32_t height);

}  // namespace hipr
