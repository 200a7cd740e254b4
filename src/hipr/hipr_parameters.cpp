#include "hipr/hipr_parameters.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/error.h"

namespace hipr {

void set_hipr_weights(const std::vector<float>& values, float* out, const std::string& what) {
  float sum = 0.0f;
  for (float v : values) {
    if (!std::isfinite(v) || v < 0.0f)
      throw InputError(what + " weights must be finite and non-negative");
    sum += v;
  }
  if (!(sum > 0.0f)) throw InputError(what + " weights must not all be zero");
  for (size_t i = 0; i < values.size(); ++i) out[i] = values[i] / sum;
}

const std::vector<std::string>& hipr_preset_names() {
  static const std::vector<std::string> names = {"default", "lookdev", "glass", "mirror"};
  return names;
}

// The paper's use cases: look development favours diffuse + direct response, a glass
// interior caustics + transmission, a mirror-heavy set the specular lobe.
void apply_hipr_preset(const std::string& name, HiprParameters& h) {
  const HiprParameters defaults;
  if (name.empty() || name == "default") {
    std::copy(std::begin(defaults.w_lobe), std::end(defaults.w_lobe), h.w_lobe);
    std::copy(std::begin(defaults.w_path), std::end(defaults.w_path), h.w_path);
  } else if (name == "lookdev") {
    set_hipr_weights({0.55f, 0.25f, 0.15f, 0.05f}, h.w_lobe, "--preset");
    set_hipr_weights({0.7f, 0.25f, 0.05f}, h.w_path, "--preset");
  } else if (name == "glass") {
    set_hipr_weights({0.15f, 0.15f, 0.3f, 0.4f}, h.w_lobe, "--preset");
    set_hipr_weights({0.3f, 0.2f, 0.5f}, h.w_path, "--preset");
  } else if (name == "mirror") {
    set_hipr_weights({0.1f, 0.2f, 0.6f, 0.1f}, h.w_lobe, "--preset");
    set_hipr_weights({0.6f, 0.25f, 0.15f}, h.w_path, "--preset");
  } else {
    throw InputError("unknown --preset '" + name + "' (default, lookdev, glass, mirror)");
  }
}

}  // namespace hipr
