#pragma once
// The staging buffer of a context's copies to and from device memory the host cannot map (a
// discrete GPU's): kept and grown rather than made for each copy, so that an upload or a
// read-back allocates nothing. Copies larger than kKeptStagingBytes (whole images) get a
// buffer of their own, freed after the copy, rather than holding that much host memory.
#include "vk/buffer.h"

namespace hipr::vk {

constexpr VkDeviceSize kKeptStagingBytes = VkDeviceSize(16) << 20;

class StagingBuffers {
 public:
  // A mapped buffer of at least `size` bytes for one copy; `temporary` holds it when it is not
  // the kept one, and must outlive the copy.
  Buffer& for_copy(const Context& ctx, VkDeviceSize size, Buffer& temporary);

 private:
  Buffer m_kept;
};

}  // namespace hipr::vk
