#include "hipr/active_tiles_pass.h"

#include <algorithm>

#include "render/film.h"
#include "shaders/shared/bindings/visibility.h"

namespace hipr {

ActiveTilesPass::ActiveTilesPass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles, const Film& film,
                                 const GBufferPass& gbuffers, const vk::Buffer& display,
                                 const vk::Buffer& tile_weights, uint32_t pixels)
    : changed_records(ctx, std::max<size_t>(scene.record_count(), 1) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      tile_change(ctx, size_t(tiles.count()) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      m_pixels(pixels),
      m_tiles(tiles.count()),
      m_carry(ctx, "carry_tiles.comp", {},
              {{abi::kCarryAccumulation, &film.accumulation},
               {abi::kCarryTileFlags, &tiles.flags},
               {abi::kCarryTileWeights, &tile_weights},
               {abi::kCarryTileChange, &tile_change}},
              sizeof(uint32_t), &scene.descriptor_set()),
      m_mark_active(ctx, "mark_active.comp", {},
                    {{abi::kMarkActiveGBuffer, &gbuffers.current},
                     {abi::kMarkActivePrevious, &gbuffers.previous},
                     {abi::kMarkActiveChangedRecords, &changed_records},
                     {abi::kMarkActiveTileFlags, &tiles.flags},
                     {abi::kMarkActiveTileChange, &tile_change},
                     {abi::kMarkActiveDisplay, &display}},
                    0, &scene.descriptor_set()) {
  tile_change.clear();
}

void ActiveTilesPass::record_carry(VkCommandBuffer cmd, bool everything) const {
  const uint32_t push = everything ? 1u : 0u;
  m_carry.dispatch(cmd, &push, groups_for(m_tiles));
}

void ActiveTilesPass::set_changed(const GpuScene& scene, const ChangeSet& changes) {
  // One pass over the records: a flag per instance, then each record looks up its own.
  const std::vector<uint32_t>& record_instance = scene.record_instance();
  std::vector<bool> instance_changed;
  for (uint32_t instance : changes.instances) {
    if (instance >= instance_changed.size()) instance_changed.resize(instance + 1, false);
    instance_changed[instance] = true;
  }
  std::vector<uint32_t> changed(std::max<size_t>(record_instance.size(), 1), 0);
  for (size_t r = 0; r < record_instance.size(); ++r)
    changed[r] = record_instance[r] < instance_changed.size() && instance_changed[record_instance[r]] ? 1 : 0;
  changed_records.upload(changed.data(), changed.size() * 4);
}

void ActiveTilesPass::record(VkCommandBuffer cmd) const { m_mark_active.dispatch(cmd, nullptr, groups_for(m_pixels)); }

}  // namespace hipr
