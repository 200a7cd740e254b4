#pragma once
// The viewer's automatic exposure measured on the device (meter_exposure.comp): a histogram of
// the display's lit luminances, read back as 4 KB, from which image/auto_exposure.h takes the
// metered percentile. Reading the display back instead cost 56 bytes a pixel.
#include <cstdint>
#include <vector>

#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"

namespace hipr {

class ExposureMeter {
 public:
  // `display`: abi::DisplayTexel per pixel, width x height of them.
  ExposureMeter(const vk::Context& ctx, const vk::Buffer& display, uint32_t width, uint32_t height);

  // The exposure in stops for what the display shows now (metered_exposure_ev's rule, to
  // 1/abi::kMeterBinsPerStop of a stop).
  float metered_ev() const;
  // The histogram itself (abi::kMeterBins counts), as metered_ev reads it.
  std::vector<uint32_t> histogram() const;

 private:
  const vk::Context& m_ctx;
  uint32_t m_pixels;
  vk::Buffer m_histogram;
  vk::ComputePipeline m_meter;
};

}  // namespace hipr
