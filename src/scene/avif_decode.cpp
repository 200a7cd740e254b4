#include "scene/avif_decode.h"

#include <libheif/heif.h>

#include <cstring>
#include <memory>
#include <vector>

#include "scene/decoded_texture.h"

namespace hipr::gltf {
namespace {

struct ContextFree {
  void operator()(heif_context* c) const { heif_context_free(c); }
};
struct HandleRelease {
  void operator()(const heif_image_handle* h) const { heif_image_handle_release(h); }
};
struct ImageRelease {
  void operator()(const heif_image* i) const { heif_image_release(i); }
};

}  // namespace

bool decode_avif(tinygltf::Image* image, const unsigned char* bytes, size_t size, size_t max_pixels,
                 int max_side, std::string* err) {
  const auto fail = [&](const std::string& why) {
    if (err) *err = why;
    return false;
  };
  const auto failed = [](const heif_error& e) { return e.code != heif_error_Ok; };
  std::unique_ptr<heif_context, ContextFree> context(heif_context_alloc());
  if (!context) return fail("libheif cannot start");
  heif_context_set_maximum_image_size_limit(context.get(), max_side);
  // (The bytes outlive the context: both end in this call.)
  heif_error e = heif_context_read_from_memory_without_copy(context.get(), bytes, size, nullptr);
  if (failed(e)) return fail(e.message);
  heif_image_handle* raw_handle = nullptr;
  e = heif_context_get_primary_image_handle(context.get(), &raw_handle);
  if (failed(e)) return fail(e.message);
  const std::unique_ptr<const heif_image_handle, HandleRelease> handle(raw_handle);
  const int claimed_width = heif_image_handle_get_width(handle.get());
  const int claimed_height = heif_image_handle_get_height(handle.get());
  if (std::string why = texture_size_problem(claimed_width, claimed_height, max_pixels, max_side);
      !why.empty())
    return fail(why);

  const bool alpha = heif_image_handle_has_alpha_channel(handle.get()) != 0;
  heif_image* raw_image = nullptr;
  e = heif_decode_image(handle.get(), &raw_image, heif_colorspace_RGB,
                        alpha ? heif_chroma_interleaved_RGBA : heif_chroma_interleaved_RGB,
                        nullptr);
  if (failed(e)) return fail(e.message);
  const std::unique_ptr<const heif_image, ImageRelease> decoded(raw_image);
  // What was decoded, not what the header said.
  const int width = heif_image_get_width(decoded.get(), heif_channel_interleaved);
  const int height = heif_image_get_height(decoded.get(), heif_channel_interleaved);
  const int channels = alpha ? 4 : 3;
  int stride = 0;
  const uint8_t* plane =
      heif_image_get_plane_readonly(decoded.get(), heif_channel_interleaved, &stride);
  if (!plane || !texture_size_problem(width, height, max_pixels, max_side).empty() ||
      heif_image_get_bits_per_pixel(decoded.get(), heif_channel_interleaved) != 8 * channels ||
      stride < width * channels)
    return fail("decoded to no usable 8-bit RGB image");
  std::vector<unsigned char> pixels(size_t(width) * size_t(height) * size_t(channels));
  const size_t row = size_t(width) * size_t(channels);
  for (int y = 0; y < height; ++y)
    std::memcpy(pixels.data() + size_t(y) * row, plane + size_t(y) * size_t(stride), row);
  store_texels(image, width, height, channels, std::move(pixels));
  return true;
}

}  // namespace hipr::gltf
