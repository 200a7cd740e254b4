#pragma once
// What every extension-image decoder (webp_decode, avif_decode, dds_decode) shares: the size
// check made before any pixel is decoded, and the hand-over of the decoded 8-bit texels.
#include <tiny_gltf.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hipr::gltf {

// Empty when a `width` x `height` image is within `max_side` and `max_pixels`; otherwise why not
// ("is WxH, beyond hipr's limit"). A side below 1 is "image has no pixels".
std::string texture_size_problem(int64_t width, int64_t height, size_t max_pixels, int max_side);

// Stores `pixels` (rows top first, `channels` 8-bit values per texel, packed) into `image`.
void store_texels(tinygltf::Image* image, int width, int height, int channels,
                  std::vector<unsigned char> pixels);

}  // namespace hipr::gltf
