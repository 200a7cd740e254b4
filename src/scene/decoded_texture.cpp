#include "scene/decoded_texture.h"

#include <utility>

namespace hipr::gltf {

std::string texture_size_problem(int64_t width, int64_t height, size_t max_pixels, int max_side) {
  if (width < 1 || height < 1) return "image has no pixels";
  if (width > max_side || height > max_side || uint64_t(width) * uint64_t(height) > max_pixels)
    return "is " + std::to_string(width) + "x" + std::to_string(height) + ", beyond hipr's limit";
  return "";
}

void store_texels(tinygltf::Image* image, int width, int height, int channels,
                  std::vector<unsigned char> pixels) {
  image->width = width;
  image->height = height;
  image->component = channels;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image = std::move(pixels);
}

}  // namespace hipr::gltf
