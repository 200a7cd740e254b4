#include "scene/gltf_image_decode.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>

#include "scene/avif_decode.h"
#include "scene/dds_header.h"

namespace hipr::gltf {

namespace {

bool starts(const unsigned char* bytes, size_t size, size_t at, const char* tag) {
  const size_t n = std::strlen(tag);
  return size >= at + n && std::memcmp(bytes + at, tag, n) == 0;
}

// The decoder for the bytes: WebP, DDS (OpenImageIO's readers), or AVIF (an ISO media file of
// brand avif or avis: libheif, avif_decode.h); empty for anything else.
std::string format_of(const unsigned char* bytes, size_t size) {
  if (starts(bytes, size, 0, "RIFF") && starts(bytes, size, 8, "WEBP")) return "webp";
  if (starts(bytes, size, 0, "DDS ")) return "dds";
  if (starts(bytes, size, 4, "ftyp") &&
      (starts(bytes, size, 8, "avif") || starts(bytes, size, 8, "avis")))
    return "heif";
  return "";
}

}  // namespace

bool needs_extension_decoder(const unsigned char* bytes, size_t size) {
  return !format_of(bytes, size).empty();
}

bool decode_extension_image(tinygltf::Image* image, const unsigned char* bytes, size_t size,
                            size_t max_pixels, int max_side, std::string* err) {
  const auto fail = [&](const std::string& why) {
    if (err) *err = why;
    return false;
  };
  const std::string format = format_of(bytes, size);
  if (format == "heif") return decode_avif(image, bytes, size, max_pixels, max_side, err);
  if (format == "dds")
    if (std::string why = dds_header_problem(bytes, size); !why.empty()) return fail(why);
  // The proxy must outlive the input: declared first, it is destroyed last.
  OIIO::Filesystem::IOMemReader memory(const_cast<unsigned char*>(bytes), size);
  auto input = OIIO::ImageInput::create(format);
  if (!input) return fail("this OpenImageIO has no " + format + " reader");
  const std::string name = "texture." + format;
  if (!input->supports("ioproxy") || !input->set_ioproxy(&memory))
    return fail("the " + format + " reader cannot read memory");
  OIIO::ImageSpec spec;
  if (!input->open(name, spec, OIIO::ImageSpec())) return fail(input->geterror());
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
