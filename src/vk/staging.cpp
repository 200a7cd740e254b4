#include "vk/staging.h"

#include <algorithm>

namespace hipr::vk {

Buffer& StagingBuffers::for_copy(const Context& ctx, VkDeviceSize size, Buffer& temporary) {
  constexpr VkBufferUsageFlags kUsage =
      VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (size > kKeptStagingBytes) {
    temporary = Buffer(ctx, size, kUsage, MemoryUse::Readback);
    return temporary;
  }
  // Grown by doubling up to the cap: a few growths, then never again.
  if (!m_kept || m_kept.size() < size)
    m_kept = Buffer(ctx, std::min(kKeptStagingBytes, std::max(size, 2 * m_kept.size())), kUsage,
                    MemoryUse::Readback);
  return m_kept;
}

}  // namespace hipr::vk
