#pragma once
// Timestamps the GPU writes between the commands of one submission, so that a pass's cost is
// the device's own execution time: a wall clock around submit_and_wait also counts recording,
// the submission and the host waking from the fence, which on a GPU can outweigh a 1 ms pass.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace hipr::vk {

class Context;

class GpuStopwatch {
 public:
  // Room for `marks` timestamps. Where the queue has no timestamps (timestampValidBits 0) the
  // stopwatch records nothing and reads nothing.
  GpuStopwatch(const Context& ctx, uint32_t marks);
  ~GpuStopwatch();
  GpuStopwatch(const GpuStopwatch&) = delete;
  GpuStopwatch& operator=(const GpuStopwatch&) = delete;

  bool supported() const { return m_pool != VK_NULL_HANDLE; }
  // Records the reset of every mark: first in the command buffer, before any mark.
  void reset(VkCommandBuffer cmd) const;
  // Records mark `index`: the time by which every command recorded before it has finished.
  void mark(VkCommandBuffer cmd, uint32_t index) const;
  // Seconds from mark 0 to each mark (the first is 0), once the submission has completed;
  // nullopt where unsupported.
  std::optional<std::vector<double>> read() const;

 private:
  VkDevice m_device = VK_NULL_HANDLE;
  VkQueryPool m_pool = VK_NULL_HANDLE;
  uint32_t m_marks = 0;
  double m_seconds_per_tick = 0.0;
  uint64_t m_valid_mask = 0;
};

}  // namespace hipr::vk
