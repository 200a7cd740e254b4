#pragma once
// HiPR stage 3 (schedule_keys.comp + RadixSorter): a sort key per tile (active tiles by change
// score, then discovered tiles by weight, then the rest by distance to the active set), sorted
// on the GPU into the schedule the trace pass renders from.
#include <cstdint>

#include "render/gpu_scene.h"
#include "render/radix_sorter.h"
#include "render/tile_state.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class SchedulePass {
 public:
  SchedulePass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles,
               const vk::Buffer& tile_weights, const vk::Buffer& tile_change,
               const vk::Buffer& tile_focus);

  // Records the keys, the sort and the copy of the sorted tile ids into the schedule.
  void record(VkCommandBuffer cmd) const;
  // Records the keys and the sort alone, on the pass's own buffers (the schedule is untouched):
  // a dispatch of every kernel, so drivers that compile at first dispatch do it now.
  void record_warm_up(VkCommandBuffer cmd) const;

 private:
  void record_sort(VkCommandBuffer cmd) const;

  const TileState& m_tiles;
  vk::Buffer m_row_distance;  // uint per tile: columns to the nearest active tile in its row
  RadixSorter m_sorter;
  vk::ComputePipeline m_keys;
};

}  // namespace hipr
