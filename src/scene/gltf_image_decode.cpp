#include "scene/gltf_image_decode.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>

namespace hipr::gltf {

bool needs_oiio_decoder(const unsigned char* bytes, size_t size) {
  const auto starts = [&](size_t at, const char* tag) {
    const size_t n = std::strlen(tag);
    return size >= at + n && std::memcmp(bytes + at, tag, n) == 0;
  };
  return (starts(0, "RIFF") && starts(8, "WEBP")) || starts(0, "DDS ");
}

bool decode_with_oiio(tinygltf::Image* image, const unsigned char* bytes, size_t size,
                      size_t max_pixels, int max_side, std::string* err) {
  const auto fail = [&](const std::string& why) {
    if (err) *err = why;
    return false;
  };
  const bool webp = size >= 4 && std::memcmp(bytes, "RIFF", 4) == 0;
  const std::string format = webp ? "webp" : "dds";
  auto input = OIIO::ImageInput::create(format);
  if (!input) return fail("this OpenImageIO has no " + format + " reader");
  // The proxy must outlive the input: it is declared first, so it is destroyed last.
  OIIO::Filesystem::IOMemReader memory(const_cast<unsigned char*>(bytes), size);
  if (!input->set_ioproxy(&memory)) return fail("the " + format + " reader cannot read memory");
  OIIO::ImageSpec spec;
  if (!input->open("texture." + format, spec, OIIO::ImageSpec())) return fail(input->geterror());
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    return fail("image has no pixels");
  if (spec.width > max_side || spec.height > max_side ||
      size_t(spec.width) * size_t(spec.height) > max_pixels)
    return fail("is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                ", beyond hipr's limit");
  const int channels = std::min(spec.nchannels, 4);
  std::vector<unsigned char> pixels(size_t(spec.width) * size_t(spec.height) * size_t(channels));
  if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data()))
    return fail(input->geterror());
  input->close();
  image->width = spec.width;
  image->height = spec.height;
  image->component = channels;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image = std::move(pixels);
  return true;
}

}  // namespace hipr::gltf
