#pragma once
// AVIF textures (EXT_texture_avif) decoded with libheif from memory. OpenImageIO 2.4's heif
// reader copied each row at the width the file's header claims from a decoded plane that may be
// narrower (a heap over-read, found by fuzzing); here the rows are copied at the decoded plane's
// own size and stride, and the header's claim only bounds what is decoded.
#include <tiny_gltf.h>

#include <cstddef>
#include <string>

namespace hipr::gltf {

// Decodes into `image` as 8-bit RGB or RGBA (with an alpha plane). `max_pixels` and `max_side`
// bound the size read from the file before anything is decoded, and the decoded image's too.
// False with `err` set when the bytes cannot be read.
bool decode_avif(tinygltf::Image* image, const unsigned char* bytes, size_t size, size_t max_pixels,
                 int max_side, std::string* err);

}  // namespace hipr::gltf
