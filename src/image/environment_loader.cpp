#include "image/environment_loader.h"

#include <cmath>

#include "core/error.h"
#include "core/log.h"
#include "image/image_reader.h"

namespace hipr {

Environment load_environment(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError("environment map not found: " + path.string());
  // Up to 16384 x 8192 texels (the largest HDRIs offered) are read: a larger claim is refused
  // before the texels are allocated (open_image_reader checks every claim).
  const std::string what = "environment map " + path.string();
  const auto input = open_image_reader(path, {ImageFormat::OpenExr, ImageFormat::Radiance},
                                       "environment map", int64_t(1) << 27);
  Environment env;
  env.path = path;
  env.width = uint32_t(input->spec().width);
  env.height = uint32_t(input->spec().height);
  env.texels.resize(size_t(env.width) * size_t(env.height));
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "texels are read as packed RGB floats");
  read_rgb(*input, &env.texels[0].x, what);

  size_t repaired = 0;
  for (glm::vec3& texel : env.texels) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(texel[k]) || texel[k] < 0.0f) {
        texel[k] = 0.0f;
        ++repaired;
      }
    }
  }
  if (repaired)
    log::warn(path.string() + ": " + std::to_string(repaired) +
              " negative or non-finite texel values set to 0");
  return env;
}

}  // namespace hipr
