#include "render/exposure_meter.h"

#include "image/auto_exposure.h"
#include "render/film.h"
#include "shaders/shared/bindings/exposure.h"

namespace hipr {

ExposureMeter::ExposureMeter(const vk::Context& ctx, const vk::Buffer& display, uint32_t width,
                             uint32_t height)
    : m_ctx(ctx),
      m_pixels(width * height),
      // The kernel's atomics land in device memory (mapped where the device allows).
      m_histogram(ctx, abi::kMeterBins * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                  vk::MemoryUse::Shared),
      m_meter(ctx, "meter_exposure.comp", {},
              {{abi::kMeterDisplay, &display}, {abi::kMeterHistogram, &m_histogram}},
              sizeof(uint32_t)) {}

std::vector<uint32_t> ExposureMeter::histogram() const {
  m_ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, m_histogram.handle(), 0, VK_WHOLE_SIZE, 0);
    vk::transfer_to_compute_barrier(cmd);
    m_meter.dispatch(cmd, &m_pixels, groups_for(m_pixels, abi::kMeterWorkgroupSize));
  });
  return m_histogram.download_all<uint32_t>();
}

float ExposureMeter::metered_ev() const {
  return histogram_exposure_ev(
      LuminanceHistogram{histogram(), float(abi::kMeterLowestStop), float(abi::kMeterBinsPerStop)});
}

}  // namespace hipr
