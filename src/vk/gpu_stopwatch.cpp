#include "vk/gpu_stopwatch.h"

#include "vk/check.h"
#include "vk/context.h"

namespace hipr::vk {

GpuStopwatch::GpuStopwatch(const Context& ctx, uint32_t marks)
    : m_device(ctx.device()), m_marks(marks) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physical_device(), &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physical_device(), &count, families.data());
  const uint32_t valid_bits =
      ctx.queue_family() < count ? families[ctx.queue_family()].timestampValidBits : 0;
  if (valid_bits == 0 || marks == 0) return;
  m_valid_mask = valid_bits >= 64 ? ~uint64_t(0) : (uint64_t(1) << valid_bits) - 1;
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(ctx.physical_device(), &props);
  m_seconds_per_tick = double(props.limits.timestampPeriod) * 1e-9;

  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = marks;
  VK_CHECK(vkCreateQueryPool(m_device, &info, nullptr, &m_pool));
}

GpuStopwatch::~GpuStopwatch() {
  if (m_pool != VK_NULL_HANDLE) vkDestroyQueryPool(m_device, m_pool, nullptr);
}

void GpuStopwatch::reset(VkCommandBuffer cmd) const {
  if (supported()) vkCmdResetQueryPool(cmd, m_pool, 0, m_marks);
}

void GpuStopwatch::mark(VkCommandBuffer cmd, uint32_t index) const {
  if (supported() && index < m_marks)
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, m_pool, index);
}

std::optional<std::vector<double>> GpuStopwatch::read() const {
  if (!supported()) return std::nullopt;
  std::vector<uint64_t> ticks(m_marks);
  VK_CHECK(vkGetQueryPoolResults(m_device, m_pool, 0, m_marks, ticks.size() * sizeof(uint64_t),
                                 ticks.data(), sizeof(uint64_t),
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  std::vector<double> seconds(m_marks);
  for (uint32_t i = 0; i < m_marks; ++i)  // masked: the counter wraps at its valid bits
    seconds[i] = double((ticks[i] - ticks[0]) & m_valid_mask) * m_seconds_per_tick;
  return seconds;
}

}  // namespace hipr::vk
