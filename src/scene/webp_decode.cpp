#include "scene/webp_decode.h"

#include <webp/decode.h>

#include <vector>

#include "scene/decoded_texture.h"

namespace hipr::gltf {

bool decode_webp(tinygltf::Image* image, const unsigned char* bytes, size_t size, size_t max_pixels,
                 int max_side, std::string* err) {
  const auto fail = [&](const std::string& why) {
    if (err) *err = why;
    return false;
  };
  WebPBitstreamFeatures features;
  if (WebPGetFeatures(bytes, size, &features) != VP8_STATUS_OK)
    return fail("is not a WebP image libwebp can read");
  if (std::string why = texture_size_problem(features.width, features.height, max_pixels, max_side);
      !why.empty())
    return fail(why);
  const int channels = features.has_alpha ? 4 : 3;
  const size_t row = size_t(features.width) * size_t(channels);
  std::vector<unsigned char> pixels(row * size_t(features.height));
  // libwebp checks the picture against the buffer it is given before writing a texel.
  const uint8_t* decoded =
      channels == 4 ? WebPDecodeRGBAInto(bytes, size, pixels.data(), pixels.size(), int(row))
                    : WebPDecodeRGBInto(bytes, size, pixels.data(), pixels.size(), int(row));
  if (!decoded) return fail("libwebp cannot decode it");
  store_texels(image, features.width, features.height, channels, std::move(pixels));
  return true;
}

}  // namespace hipr::gltf
