#include "image/auto_exposure.h"

#include <algorithm>
#include <cmath>

namespace hipr {

float metered_exposure_ev(const std::vector<float>& rgb) {
  std::vector<float> lit;
  lit.reserve(rgb.size() / 3);
  for (size_t i = 0; i + 2 < rgb.size(); i += 3) {
    const float y = 0.2126f * rgb[i] + 0.7152f * rgb[i + 1] + 0.0722f * rgb[i + 2];
    if (std::isfinite(y) && y > 0.0f) lit.push_back(y);
  }
  if (lit.empty()) return 0.0f;
  const size_t rank = std::min(lit.size() - 1, size_t(kMeteredPercentile * float(lit.size())));
  std::nth_element(lit.begin(), lit.begin() + std::ptrdiff_t(rank), lit.end());
  const float ev = std::log2(kMeteredDisplayValue / lit[rank]);
  return std::isfinite(ev) ? std::clamp(ev, kMinExposureEv, kMaxExposureEv) : 0.0f;
}

}  // namespace hipr
