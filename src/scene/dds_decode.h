#pragma once
// DDS textures (MSFT_texture_dds) decoded here, from memory: the kinds dds_header.h accepts,
// block-compressed BC1-BC5 or uncompressed with channel masks. Only the top level is read (hipr
// builds its own mip chain). hipr decodes them itself so that no third-party reader sees the
// bytes: the one it used trusted the header (dds_header.h says what fuzzing found).
#include <tiny_gltf.h>

#include <cstddef>
#include <string>

namespace hipr::gltf {

// Decodes into `image` as 8-bit texels: BC1-BC3 as RGBA, BC4 as one channel, BC5 as two (R, G);
// uncompressed as its channels (R, G, B; luminance; alpha last when it has one). `max_pixels`
// and `max_side` bound the size. False with `err` set when the bytes are not such a file.
bool decode_dds(tinygltf::Image* image, const unsigned char* bytes, size_t size, size_t max_pixels,
                int max_side, std::string* err);

}  // namespace hipr::gltf
