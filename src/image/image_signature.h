#pragma once
// The one place hipr reads an image file's magic bytes: what the first bytes say a file is, for
// the whole-image reader (image_reader.h) and for the glTF extension images (gltf_image_decode.h)
// alike. A file's name or MIME type is never trusted for it.
#include <cstddef>
#include <optional>

namespace hipr {

enum class ImageFormat { OpenExr, Radiance, Png, Webp, Dds, Avif };

// How many leading bytes image_format_of needs at most.
constexpr size_t kImageSignatureBytes = 12;

// The format whose signature the bytes start with: OpenEXR (76 2f 31 01), Radiance .hdr ("#?"),
// PNG, WebP ("RIFF", a size, "WEBP"), DDS ("DDS ") or AVIF (an ISO media file, "ftyp" at 4, of
// brand avif or avis); none for anything else.
std::optional<ImageFormat> image_format_of(const unsigned char* bytes, size_t size);

// The format as messages name it: "OpenEXR", "Radiance .hdr", "PNG", "WebP", "DDS", "AVIF".
const char* image_format_name(ImageFormat format);

}  // namespace hipr
