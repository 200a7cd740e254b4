#include "render/difference_records.h"

#include <algorithm>

#include <glm/glm.hpp>

namespace hipr {
namespace {

struct DecodedDifference {
  glm::vec3 sum{0.0f};  // sum of d_i over the differenced samples
  uint32_t valid = 0;   // kept samples of the stale estimate's scene state
  bool changed = false;
};

DecodedDifference decode_difference(const abi::DifferenceRecord& record,
                                    const abi::DisplayTexel& texel) {
  DecodedDifference d;
  for (uint32_t k = 0; k < 3; ++k) d.sum[int(k)] = record.values[abi::kDifferenceSum + k];
  d.valid = (texel.flags >> abi::kDifferenceValidShift) & abi::kDifferenceValidMask;
  d.changed = record.values[abi::kDifferenceSquares] > 0.0f || d.sum != glm::vec3(0.0f);
  return d;
}

}  // namespace

DifferenceEstimates difference_estimates(uint32_t width, uint32_t height,
                                         const std::vector<abi::PixelAccum>& accum,
                                         const std::vector<abi::DifferenceRecord>& records,
                                         const std::vector<abi::DisplayTexel>& display) {
  DifferenceEstimates out;
  out.image = ImageRGB{width, height, std::vector<float>(size_t(width) * height * 3, 0.0f)};
  out.differenced.assign(size_t(width) * height, 0);
  out.changed.assign(size_t(width) * height, 0);
  for (size_t i = 0; i < out.differenced.size(); ++i) {
    const bool owed = (accum[i].count & abi::kPixelOwed) != 0;
    const uint32_t n = owed ? 0 : accum[i].count & abi::kPixelCountMask;
    const DecodedDifference d = decode_difference(records[i], display[i]);
    const uint32_t c = std::min(n, d.valid);
    glm::vec3 estimate = display[i].stale;
    if (c > 0) {
      estimate += d.sum / float(c);
      out.differenced[i] = c;
      out.changed[i] = d.changed ? 1 : 0;
    }
    for (int k = 0; k < 3; ++k) out.image.rgb[i * 3 + size_t(k)] = estimate[k];
  }
  return out;
}

}  // namespace hipr
