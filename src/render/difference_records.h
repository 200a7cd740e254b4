#pragma once
// The difference records (abi::DifferenceRecord, shaders/common/difference.glsl) read back on
// the CPU, for inspection and tests: per pixel, the difference estimate C = stale + sum d / c.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "hipr/renderer.h"
#include "shaders/shared/abi.h"

namespace hipr {

struct DecodedDifference {
  glm::vec3 sum{0.0f};  // sum of d_i over the differenced samples
  uint32_t valid = 0;   // kept samples of the stale estimate's scene state
  bool changed = false;
};

DecodedDifference decode_difference(const abi::DifferenceRecord& record, const abi::DisplayTexel& texel);

// Per pixel, from the film's counts, the records and the display's stale estimates.
DifferenceEstimates difference_estimates(uint32_t width, uint32_t height, const std::vector<abi::PixelAccum>& accum,
                                         const std::vector<abi::DifferenceRecord>& records,
                                         const std::vector<abi::DisplayTexel>& display);

}  // namespace hipr
