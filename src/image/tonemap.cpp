#include "image/tonemap.h"

#include <algorithm>
#include <cmath>

namespace hipr {

float srgb_encode(float x) {
  x = std::isfinite(x) ? std::clamp(x, 0.0f, 1.0f) : 0.0f;
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

std::vector<uint8_t> tonemap_srgb8(const std::vector<float>& rgb, float exposure_ev) {
  const float scale = std::exp2(exposure_ev);
  std::vector<uint8_t> out(rgb.size());
  for (size_t i = 0; i < rgb.size(); ++i)
    out[i] = uint8_t(std::lround(srgb_encode(rgb[i] * scale) * 255.0f));
  return out;
}

}  // namespace hipr
