#pragma once
// GPU radix sort (shaders/radix_sort.comp): stable, ascending 32-bit keys with 32-bit values,
// any count up to the capacity. Keys and values live in `keys` / `values` before and after.
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"

namespace hipr {

class RadixSorter {
 public:
  RadixSorter(const vk::Context& ctx, uint32_t capacity);

  // Records the four 8-bit passes (with barriers) for the first `count` entries.
  void record(VkCommandBuffer cmd, uint32_t count) const;

  vk::Buffer keys, values;

 private:
  // The buffers of radix_sort.comp (the same for its three stages).
  std::vector<vk::BufferBinding> bindings() const;

  uint32_t m_capacity;
  vk::Buffer m_keys_alt, m_values_alt, m_histogram;
  vk::ComputePipeline m_histogram_pass, m_scan_pass, m_scatter_pass;
};

}  // namespace hipr
