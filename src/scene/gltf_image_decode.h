#pragma once
// Images stb cannot decode, read from memory (the bytes may come from a bufferView or a data:
// URI): WebP for EXT_texture_webp (libwebp, webp_decode.h), DDS for MSFT_texture_dds (hipr's own
// decoder, dds_decode.h), AVIF for EXT_texture_avif (libheif, avif_decode.h).
#include <tiny_gltf.h>

#include <cstddef>
#include <string>

namespace hipr::gltf {

// Whether the bytes start like a WebP, DDS or AVIF file (image_signature.h).
bool needs_extension_decoder(const unsigned char* bytes, size_t size);

// Decodes into `image` as 8-bit with 1 to 4 channels. `max_pixels` bounds the size read from
// the header before any pixel is decoded. False with `err` set when the image cannot be read.
bool decode_extension_image(tinygltf::Image* image, const unsigned char* bytes, size_t size,
                            size_t max_pixels, int max_side, std::string* err);

}  // namespace hipr::gltf
