#pragma once
// A VkBuffer with its own memory. Device-local buffers are filled through a staging copy when
// the memory is not host-visible (real GPUs); on lavapipe every buffer is mapped directly.
#include <vulkan/vulkan.h>

#include <cstddef>
#include <span>
#include <vector>

#include "vk/context.h"

namespace hipr::vk {

enum class MemoryUse {
  Device,    // GPU reads/writes; host access through upload()/download()
  Readback,  // GPU writes, host reads often (mapped)
  // Small buffers the host touches often, writing them at edits and steps or reading them after
  // steps (counters): device memory the host can map where the device has it (a discrete GPU's
  // BAR window, integrated GPUs, lavapipe), so upload() and download() are copies to and from
  // mapped memory with no staging buffer and no submission; else as Device.
  Shared,
};

class Buffer {
 public:
  Buffer() = default;
  // Size 0 is rounded up to 4 bytes: bindings must never be left without a buffer.
  Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
         MemoryUse use = MemoryUse::Device);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return m_buffer; }
  VkDeviceSize size() const { return m_size; }
  VkDeviceAddress address() const { return m_address; }
  explicit operator bool() const { return m_buffer != VK_NULL_HANDLE; }

  void upload(const void* data, VkDeviceSize size, VkDeviceSize offset = 0);
  void download(void* data, VkDeviceSize size, VkDeviceSize offset = 0) const;
  template <typename T>
  void upload(std::span<const T> values) {
    upload(values.data(), values.size_bytes());
  }
  template <typename T>
  std::vector<T> download_all() const {
    std::vector<T> values(m_size / sizeof(T));
    download(values.data(), values.size() * sizeof(T));
    return values;
  }
  // Fills with zero bytes (device-side).
  void clear();

 private:
  void release();

  const Context* m_ctx = nullptr;
  VkBuffer m_buffer = VK_NULL_HANDLE;
  VkDeviceMemory m_memory = VK_NULL_HANDLE;
  VkDeviceSize m_size = 0;
  VkDeviceAddress m_address = 0;
  VkDeviceSize m_allocated = 0;  // bytes of m_memory (device_bytes_in_use)
  void* m_mapped = nullptr;
};

// Bytes copied between host and device by every Buffer's upload() and download() since the
// process started: the one place such copies happen, so counting here counts them all (the
// viewer reports them per frame).
uint64_t host_transfer_bytes();

// Bytes of device memory every live Buffer holds (acceleration structures live in Buffers too):
// what shows whether repeated edits leak.
uint64_t device_bytes_in_use();

// Device memory allocations made for Buffers since the process started (staging buffers
// included): each costs a driver call that takes far longer on a discrete GPU than on lavapipe,
// so what an edit's scene update allocates is counted, not timed.
uint64_t buffer_allocations();

// Those tallies and queue_submissions() at one moment: what a piece of work cost is the
// difference of two.
struct DeviceCounts {
  uint64_t transfer_bytes = 0, allocations = 0, submissions = 0;
  static DeviceCounts now() {
    return {host_transfer_bytes(), buffer_allocations(), queue_submissions()};
  }
  DeviceCounts operator-(const DeviceCounts& o) const {
    return {transfer_bytes - o.transfer_bytes, allocations - o.allocations,
            submissions - o.submissions};
  }
  DeviceCounts& operator+=(const DeviceCounts& o) {
    transfer_bytes += o.transfer_bytes, allocations += o.allocations, submissions += o.submissions;
    return *this;
  }
};

// Creates a storage buffer holding `values` (at least one element's worth of bytes).
template <typename T>
Buffer make_storage_buffer(const Context& ctx, const std::vector<T>& values,
                           VkBufferUsageFlags extra_usage = 0, MemoryUse use = MemoryUse::Device) {
  Buffer buffer(ctx, values.size() * sizeof(T),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT | extra_usage,
                use);
  if (!values.empty()) buffer.upload(values.data(), values.size() * sizeof(T));
  return buffer;
}

// Writes `values` at the start of `buffer` where they fit (kernels take counts from elsewhere,
// never from a buffer's size), else makes it anew, half again as big as needed so that a table
// that grows edit by edit is not reallocated at each. True when the buffer was replaced (its
// descriptors must be rewritten).
template <typename T>
bool write_storage_buffer(const Context& ctx, Buffer& buffer, const std::vector<T>& values,
                          VkBufferUsageFlags extra_usage = 0, MemoryUse use = MemoryUse::Shared) {
  const VkDeviceSize bytes = values.size() * sizeof(T);
  const bool replaced = !buffer || buffer.size() < bytes;
  if (replaced)
    buffer = Buffer(ctx, bytes + bytes / 2, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | extra_usage, use);
  if (bytes) buffer.upload(values.data(), bytes);
  return replaced;
}

}  // namespace hipr::vk
