#pragma once
// An image of linear RGB radiance, as renders produce and the display shows.
#include <cstdint>
#include <vector>

namespace hipr {

struct ImageRGB {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> rgb;  // linear, row-major, top row first
};

}  // namespace hipr
