#pragma once
// The DDS files hipr hands to OpenImageIO's DDS reader (MSFT_texture_dds): a header checked
// field by field first, because that reader trusts it. Fuzzing found a division by zero on the
// block formats it does not implement (DXT2, DXT4), and probing found an endless loop on
// uncompressed texels of 0 bits or with a channel whose mask is 0; each would take down or hang
// the viewer for one bad texture.
#include <cstddef>
#include <string>

namespace hipr::gltf {

// Empty when the bytes are a DDS file of the kinds real glTF assets ship and the reader decodes:
// one 2D image (no cube map, no volume), block-compressed as BC1, BC2, BC3 (DXT1, DXT3, DXT5),
// BC4 or BC5 (ATI1/BC4U, ATI2/BC5U), or uncompressed with 8, 16, 24 or 32 bits a texel, a mask
// for every channel its flags name and every mask within the texel; its top level wholly inside the
// bytes, and no more mip levels than its size has. Otherwise why not, for a warning ("... is DXT2,
// which ...").
std::string dds_header_problem(const unsigned char* bytes, size_t size);

}  // namespace hipr::gltf
