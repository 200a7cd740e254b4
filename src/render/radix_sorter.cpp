#include "render/radix_sorter.h"

#include "core/error.h"
#include "shaders/shared/abi.h"

namespace hipr {
namespace {

std::vector<vk::BindingSlot> sort_bindings() {
  return {{abi::kBindingSortKeys}, {abi::kBindingSortValues}, {abi::kBindingSortKeysAlt},
          {abi::kBindingSortValuesAlt}, {abi::kBindingSortHistogram}};
}

vk::Buffer storage(const vk::Context& ctx, size_t bytes) {
  return vk::Buffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
}

}  // namespace

RadixSorter::RadixSorter(const vk::Context& ctx, uint32_t capacity)
    : keys(storage(ctx, size_t(capacity) * 4)),
      values(storage(ctx, size_t(capacity) * 4)),
      m_capacity(capacity),
      m_keys_alt(storage(ctx, size_t(capacity) * 4)),
      m_values_alt(storage(ctx, size_t(capacity) * 4)),
      m_histogram(storage(ctx, size_t(abi::kSortRadix) * ((capacity + abi::kSortBlock - 1) / abi::kSortBlock) * 4)),
      m_histogram_pass(ctx, "radix_sort.comp", {{"HIPR_SORT_STAGE", "0"}}, sort_bindings(), sizeof(abi::SortPush)),
      m_scan_pass(ctx, "radix_sort.comp", {{"HIPR_SORT_STAGE", "1"}}, sort_bindings(), sizeof(abi::SortPush)),
      m_scatter_pass(ctx, "radix_sort.comp", {{"HIPR_SORT_STAGE", "2"}}, sort_bindings(), sizeof(abi::SortPush)) {
  for (vk::ComputePipeline* pass : {&m_histogram_pass, &m_scan_pass, &m_scatter_pass}) {
    pass->bind_buffer(abi::kBindingSortKeys, keys);
    pass->bind_buffer(abi::kBindingSortValues, values);
    pass->bind_buffer(abi::kBindingSortKeysAlt, m_keys_alt);
    pass->bind_buffer(abi::kBindingSortValuesAlt, m_values_alt);
    pass->bind_buffer(abi::kBindingSortHistogram, m_histogram);
  }
}

void RadixSorter::record(VkCommandBuffer cmd, uint32_t count) const {
  if (count > m_capacity) throw InternalError("radix sort over capacity");
  if (count <= 1) return;
  abi::SortPush push{};
  push.count = count;
  push.groups = (count + abi::kSortBlock - 1) / abi::kSortBlock;
  for (uint32_t pass = 0; pass < 4; ++pass) {
    push.shift = 8 * pass;
    push.pingToPong = pass % 2 == 0 ? 1 : 0;  // four passes: the result ends in keys/values
    m_histogram_pass.dispatch(cmd, &push, push.groups);
    vk::compute_to_compute_barrier(cmd);
    m_scan_pass.dispatch(cmd, &push, 1);
    vk::compute_to_compute_barrier(cmd);
    m_scatter_pass.dispatch(cmd, &push, push.groups);
    vk::compute_to_compute_barrier(cmd);
  }
}

}  // namespace hipr
