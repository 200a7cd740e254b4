#include "image/environment_loader.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

#include "core/error.h"
#include "core/log.h"

namespace hipr {

Environment load_environment(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError("environment map not found: " + path.string());
  auto input = OIIO::ImageInput::open(path.string());
  if (!input) throw InputError("cannot read environment map " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1 || int64_t(spec.width) * spec.height > (int64_t(1) << 28))
    throw InputError("environment map " + path.string() + " has an unusable size");
  std::vector<float> pixels(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw InputError("cannot decode environment map " + path.string() + ": " + input->geterror());

  Environment env;
  env.path = path;
  env.width = uint32_t(spec.width);
  env.height = uint32_t(spec.height);
  env.texels.resize(size_t(spec.width) * size_t(spec.height));
  size_t repaired = 0;
  for (size_t i = 0; i < env.texels.size(); ++i) {
    const float* p = &pixels[i * size_t(spec.nchannels)];
    glm::vec3 c = spec.nchannels >= 3 ? glm::vec3(p[0], p[1], p[2]) : glm::vec3(p[0]);
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(c[k]) || c[k] < 0.0f) {
        c[k] = 0.0f;
        ++repaired;
      }
    }
    env.texels[i] = c;
  }
  if (repaired) log::warn(path.string() + ": " + std::to_string(repaired) + " negative or non-finite texel values set to 0");
  return env;
}

}  // namespace hipr
