#pragma once
// The difference records (abi::DifferenceRecord, shaders/common/difference.glsl) read back on
// the CPU, for inspection and tests: per pixel, the difference estimate C = stale + sum d / c.
#include <cstdint>
#include <vector>

#include "hipr/image.h"
#include "shaders/shared/abi.h"

namespace hipr {

// Per pixel, the difference estimate C = stale + sum_i d_i / c after an edit
// (docs/method.md#the-difference-estimate): the stale estimate where a pixel has none (c = 0).
struct DifferenceEstimates {
  ImageRGB image;
  std::vector<uint32_t> differenced;  // c: samples compared with the old scene's
  std::vector<uint8_t> changed;       // 1: some difference is not zero
};

// Per pixel, from the film's counts, the records and the display's stale estimates.
DifferenceEstimates difference_estimates(uint32_t width, uint32_t height,
                                         const std::vector<abi::PixelAccum>& accum,
                                         const std::vector<abi::DifferenceRecord>& records,
                                         const std::vector<abi::DisplayTexel>& display);

}  // namespace hipr
