#pragma once
// WebP textures (EXT_texture_webp) decoded with libwebp from memory. The size the bitstream
// claims is read and checked before anything is allocated, and libwebp writes into a buffer of
// exactly that size, which it is told.
#include <tiny_gltf.h>

#include <cstddef>
#include <string>

namespace hipr::gltf {

// Decodes into `image` as 8-bit RGB, or RGBA when the file has alpha. `max_pixels` and
// `max_side` bound the size read from the header. False with `err` set when the bytes cannot be
// read.
bool decode_webp(tinygltf::Image* image, const unsigned char* bytes, size_t size, size_t max_pixels,
                 int max_side, std::string* err);

}  // namespace hipr::gltf
