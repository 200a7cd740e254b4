#include "image/image_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>

#include "core/error.h"
#include "core/file_util.h"
#include "image/image_reader.h"
#include "image/tonemap.h"

namespace hipr {
namespace fs = std::filesystem;
namespace {

// What hipr writes and compares: renders (OpenEXR, PNG) and references (also Radiance .hdr).
constexpr std::initializer_list<ImageFormat> kReadFormats = {ImageFormat::OpenExr, ImageFormat::Png,
                                                             ImageFormat::Radiance};
// The largest image compared: 16384 x 16384, the largest hipr renders.
constexpr int64_t kMaxImageTexels = int64_t(1) << 28;

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

bool is_supported_output(const fs::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".exr" || ext == ".png";
}

void write_image(const fs::path& path, const ImageRGB& image, const ImageMetadata& metadata,
                 const DisplayTransform& display) {
  const std::string ext = lower_extension(path);
  if (!is_supported_output(path))
    throw InputError("unsupported output format '" + ext + "' (use .exr or .png)");
  const bool exr = ext == ".exr";
  write_atomically(path, [&](const fs::path& temp) {
    auto out = OIIO::ImageOutput::create(exr ? "openexr" : "png");
    if (!out) throw InternalError("OpenImageIO has no " + ext + " writer");
    OIIO::ImageSpec spec(int(image.width), int(image.height), 3,
                         exr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
    if (exr) spec.attribute("compression", "zip");
    if (!out->open(temp.string(), spec))
      throw InputError("cannot write " + path.string() + ": " + out->geterror());
    bool ok;
    if (exr) {
      ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data());
    } else {
      const std::vector<uint8_t> srgb = tonemap_srgb8(image.rgb, display);
      ok = out->write_image(OIIO::TypeDesc::UINT8, srgb.data());
    }
    if (!out->close() || !ok)
      throw InputError("cannot write " + path.string() + ": " + out->geterror());
  });
}

void write_png8(const fs::path& path, uint32_t width, uint32_t height, uint32_t channels,
                const std::vector<uint8_t>& pixels) {
  if (lower_extension(path) != ".png") throw InputError("not a .png path: " + path.string());
  if ((channels != 3 && channels != 4) || pixels.size() != size_t(width) * height * channels)
    throw InternalError("write_png8: pixel count does not match the size");
  write_atomically(path, [&](const fs::path& temp) {
    auto out = OIIO::ImageOutput::create("png");
    if (!out) throw InternalError("OpenImageIO has no .png writer");
    OIIO::ImageSpec spec(int(width), int(height), int(channels), OIIO::TypeDesc::UINT8);
    // As they are: without the hint OpenImageIO takes RGBA for premultiplied and divides the
    // colours by alpha on the way out.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!out->open(temp.string(), spec))
      throw InputError("cannot write " + path.string() + ": " + out->geterror());
    const bool ok = out->write_image(OIIO::TypeDesc::UINT8, pixels.data());
    if (!out->close() || !ok)
      throw InputError("cannot write " + path.string() + ": " + out->geterror());
  });
}

ImageRGB read_image(const fs::path& path) {
  const std::string what = "image " + path.string();
  const auto input = open_image_reader(path, kReadFormats, "image", kMaxImageTexels);
  ImageRGB image;
  image.width = uint32_t(input->spec().width);
  image.height = uint32_t(input->spec().height);
  image.rgb.resize(size_t(image.width) * size_t(image.height) * 3);
  read_rgb(*input, image.rgb.data(), what);
  return image;
}

std::string read_image_attribute(const fs::path& path, const std::string& name) {
  try {
    return open_image_reader(path, kReadFormats, "image", kMaxImageTexels)
        ->spec()
        .get_string_attribute(name);
  } catch (const InputError&) {
    return "";
  }
}

}  // namespace hipr
