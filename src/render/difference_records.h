#pragma once
// The difference records (abi::DifferenceRecord, shaders/common/difference.glsl) read back on
// the CPU, for inspection and tests: per pixel, the difference estimate C = stale + sum d / c.
#include <cstdint>
#include <vector>

#include "hipr/renderer.h"
#include "shaders/shared/abi.h"

namespace hipr {

// Per pixel, from the film's counts, the records and the display's stale estimates.
DifferenceEstimates difference_estimates(uint32_t width, uint32_t height,
                                         const std::vector<abi::PixelAccum>& accum,
                                         const std::vector<abi::DifferenceRecord>& records,
                                         const std::vector<abi::DisplayTexel>& display);

}  // namespace hipr
