#include "image/environment_loader.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/log.h"
#include "image/exr_header.h"
#include "image/image_reader.h"

namespace hipr {

Environment load_environment(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError("environment map not found: " + path.string());
  // A header may claim any size. Up to 16384 x 8192 texels (the largest HDRIs offered) are read,
  // and no more than the file can hold (plausible_image_size): a claim beyond either is refused
  // before the texels are allocated.
  const uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec) throw InputError("cannot read environment map " + path.string() + ": " + ec.message());
  const auto check_claimed_size = [&](int64_t width, int64_t height) {
    const auto unusable = [&] {
      return InputError("environment map " + path.string() + " has an unusable size (" +
                        std::to_string(width) + "x" + std::to_string(height) + ")");
    };
    if (width < 1 || height < 1) throw unusable();
    if (!plausible_image_size(width, height, bytes))
      throw InputError("environment map " + path.string() + " claims more texels (" +
                       std::to_string(width) + "x" + std::to_string(height) + ") than its " +
                       std::to_string(bytes) + " bytes can hold");
    if (width * height > (int64_t(1) << 27)) throw unusable();  // sides <= 2^31 here: no overflow
  };
  // OpenEXR trusts its header's sizes while parsing it: it is checked here first.
  if (const auto window = scan_exr_header(path)) check_claimed_size(window->width, window->height);
  const auto input =
      open_image_reader(path, {ImageFormat::OpenExr, ImageFormat::Radiance}, "environment map");
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.nchannels < 1) throw InputError("environment map " + path.string() + " has no channels");
  check_claimed_size(spec.width, spec.height);
  // Only the first three channels (RGB; one is grey) are read, straight into the texels: a header
  // naming many channels costs nothing more.
  const int channels = std::min(spec.nchannels, 3);
  Environment env;
  env.path = path;
  env.width = uint32_t(spec.width);
  env.height = uint32_t(spec.height);
  env.texels.resize(size_t(spec.width) * size_t(spec.height));
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "texels are read as packed RGB floats");
  float* pixels = &env.texels[0].x;
  if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels, 3 * sizeof(float)))
    throw InputError("cannot decode environment map " + path.string() + ": " + input->geterror());

  size_t repaired = 0;
  for (glm::vec3& texel : env.texels) {
    glm::vec3 c = channels == 3 ? texel : glm::vec3(texel[0]);  // grey (or grey + alpha) maps
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(c[k]) || c[k] < 0.0f) {
        c[k] = 0.0f;
        ++repaired;
      }
    }
    texel = c;
  }
  if (repaired)
    log::warn(path.string() + ": " + std::to_string(repaired) +
              " negative or non-finite texel values set to 0");
  return env;
}

}  // namespace hipr
