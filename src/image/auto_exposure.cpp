#include "image/auto_exposure.h"

#include <algorithm>
#include <cmath>

namespace hipr {
namespace {

float exposure_for(float luminance) {
  const float ev = std::log2(kMeteredDisplayValue / luminance);
  return std::isfinite(ev) ? std::clamp(ev, kMinExposureEv, kMaxExposureEv) : 0.0f;
}

}  // namespace

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
  return exposure_for(lit[rank]);
}

float histogram_exposure_ev(const LuminanceHistogram& histogram) {
  uint64_t lit = 0;
  for (uint32_t count : histogram.counts) lit += count;
  if (lit == 0) return 0.0f;
  // The same rank as above: the first bin whose running count passes it.
  const uint64_t rank = std::min(lit - 1, uint64_t(kMeteredPercentile * float(lit)));
  uint64_t below = 0;
  size_t bin = 0;
  while (below + histogram.counts[bin] <= rank) below += histogram.counts[bin++];
  const float stop = histogram.lowest_stop + (float(bin) + 0.5f) / histogram.bins_per_stop;
  return exposure_for(std::exp2(stop));
}

}  // namespace hipr
