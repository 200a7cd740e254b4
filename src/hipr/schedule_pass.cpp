#include "hipr/schedule_pass.h"

#include "render/film.h"
#include "shaders/shared/bindings/schedule.h"

namespace hipr {

SchedulePass::SchedulePass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles,
                           const vk::Buffer& tile_weights, const vk::Buffer& tile_change,
                           const vk::Buffer& tile_focus)
    : m_tiles(tiles),
      m_row_distance(ctx, size_t(tiles.count()) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      m_sorter(ctx, tiles.count()),
      m_keys(ctx, "schedule_keys.comp", {},
             {{abi::kKeysTileFlags, &tiles.flags},
              {abi::kKeysTileWeights, &tile_weights},
              {abi::kKeysRowDistance, &m_row_distance},
              {abi::kKeysTileChange, &tile_change},
              {abi::kKeysSortKeys, &m_sorter.keys},
              {abi::kKeysSortValues, &m_sorter.values},
              {abi::kKeysTileFocus, &tile_focus}},
             sizeof(uint32_t), &scene.descriptor_set()) {}

void SchedulePass::record_sort(VkCommandBuffer cmd) const {
  for (uint32_t pass = 0; pass < 2; ++pass) {  // 0: row distances, 1: keys
    m_keys.dispatch(cmd, &pass, groups_for(m_tiles.count()));
    vk::compute_to_compute_barrier(cmd);
  }
  m_sorter.record(cmd, m_tiles.count());
}

void SchedulePass::record(VkCommandBuffer cmd) const {
  record_sort(cmd);
  vk::compute_to_transfer_barrier(cmd);
  const VkBufferCopy copy{0, 0, VkDeviceSize(m_tiles.count()) * 4};
  vkCmdCopyBuffer(cmd, m_sorter.values.handle(), m_tiles.schedule.handle(), 1, &copy);
}

void SchedulePass::record_warm_up(VkCommandBuffer cmd) const { record_sort(cmd); }

}  // namespace hipr
