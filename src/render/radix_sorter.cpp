#include "render/radix_sorter.h"

#include "core/error.h"
#include "shaders/shared/bindings/schedule.h"

namespace hipr {
namespace {

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
      m_histogram(storage(
          ctx, size_t(abi::kSortRadix) * ((capacity + abi::kSortBlock - 1) / abi::kSortBlock) * 4)),
      m_histogram_pass(ctx, "radix_sort.comp", {{"HIPR_SORT_STAGE", "0"}}, bindings(),
                       sizeof(abi::SortPush)),
      m_scan_pass(ctx, "radix_sort.comp", {{"HIPR_SORT_STAGE", "1"}}, bindings(),
                  sizeof(abi::SortPush)),
      m_scatter_pass(ctx, "radix_sort.comp", {{"HIPR_SORT_STAGE", "2"}}, bindings(),
                     sizeof(abi::SortPush)) {}

std::vector<vk::BufferBinding> RadixSorter::bindings() const {
  return {{abi::kSortKeys, &keys},
          {abi::kSortValues, &values},
          {abi::kSortKeysAlt, &m_keys_alt},
          {abi::kSortValuesAlt, &m_values_alt},
          {abi::kSortHistogram, &m_histogram}};
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
