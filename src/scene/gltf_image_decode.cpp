#include "scene/gltf_image_decode.h"

#include "image/image_signature.h"
#include "scene/avif_decode.h"
#include "scene/dds_decode.h"
#include "scene/webp_decode.h"

namespace hipr::gltf {

bool needs_extension_decoder(const unsigned char* bytes, size_t size) {
  const std::optional<ImageFormat> format = image_format_of(bytes, size);
  return format == ImageFormat::Webp || format == ImageFormat::Dds || format == ImageFormat::Avif;
}

bool decode_extension_image(tinygltf::Image* image, const unsigned char* bytes, size_t size,
                            size_t max_pixels, int max_side, std::string* err) {
  const std::optional<ImageFormat> format = image_format_of(bytes, size);
  if (format == ImageFormat::Webp)
    return decode_webp(image, bytes, size, max_pixels, max_side, err);
  if (format == ImageFormat::Dds) return decode_dds(image, bytes, size, max_pixels, max_side, err);
  if (format == ImageFormat::Avif)
    return decode_avif(image, bytes, size, max_pixels, max_side, err);
  if (err) *err = "is not WebP, DDS or AVIF";
  return false;
}

}  // namespace hipr::gltf
