#pragma once
// Fitting a scene's texels into what one storage buffer of the device addresses
// (maxStorageBufferRange: 128 MiB on lavapipe, 4 GiB on desktop GPUs): when they do not fit,
// the largest images are halved (on the device only; the scene keeps its texels) until they do.
#include <cstdint>
#include <vector>

#include "hipr/scene.h"

namespace hipr {

// Per image, how many times to halve it so that all texels (RGBA8, one uint32 each) number at
// most `max_texels`: the image with the most texels halves first. All zeros when they fit.
std::vector<uint8_t> texture_halvings(const std::vector<Image>& images, uint64_t max_texels);

// The image's RGBA8 texels halved `halvings` times (each step a 2x2 box average, a side never
// below 1), as packed uint32s; `width` and `height` get the size.
std::vector<uint32_t> halved_texels(const Image& image, uint8_t halvings, uint32_t& width,
                                    uint32_t& height);

}  // namespace hipr
