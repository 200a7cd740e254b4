#include "hipr/active_tiles_pass.h"

#include <algorithm>
#include <cmath>

#include "render/film.h"
#include "shaders/shared/bindings/visibility.h"

namespace hipr {

ActiveTilesPass::ActiveTilesPass(const vk::Context& ctx, const GpuScene& scene,
                                 const TileState& tiles, const Film& film,
                                 const GBufferPass& gbuffers, const vk::Buffer& display,
                                 const vk::Buffer& tile_weights, uint32_t pixels)
    : changed_records(ctx, std::max<size_t>(scene.record_count(), 1) * 4,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Shared),
      tile_change(ctx, size_t(tiles.count()) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      tile_focus(ctx, size_t(tiles.count()) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      m_ctx(ctx),
      m_focus_discs(ctx, sizeof(abi::FocusDisc) * abi::kMaxFocusDiscs,
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Shared),
      m_pixels(pixels),
      m_tiles(tiles.count()),
      m_carry(ctx, "carry_tiles.comp", {},
              {{abi::kCarryAccumulation, &film.accumulation},
               {abi::kCarryTileFlags, &tiles.flags},
               {abi::kCarryTileWeights, &tile_weights},
               {abi::kCarryTileChange, &tile_change},
               {abi::kCarryTileFocus, &tile_focus}},
              sizeof(uint32_t), &scene.descriptor_set()),
      m_mark_active(ctx, "mark_active.comp", {},
                    {{abi::kMarkActiveGBuffer, &gbuffers.current},
                     {abi::kMarkActivePrevious, &gbuffers.previous},
                     {abi::kMarkActiveChangedRecords, &changed_records},
                     {abi::kMarkActiveTileFlags, &tiles.flags},
                     {abi::kMarkActiveTileChange, &tile_change},
                     {abi::kMarkActiveDisplay, &display},
                     {abi::kMarkActiveFocusDiscs, &m_focus_discs},
                     {abi::kMarkActiveTileFocus, &tile_focus},
                     {abi::kMarkActivePixelLead, &tiles.pixel_lead}},
                    4 * sizeof(uint32_t), &scene.descriptor_set()) {
  tile_change.clear();
  tile_focus.clear();
  m_focus_discs.clear();
}

void ActiveTilesPass::record_carry(VkCommandBuffer cmd, uint32_t mode) const {
  m_carry.dispatch(cmd, &mode, groups_for(m_tiles));
}

namespace {

// A seed's weight in the kernels' fixed point (at least one unit: a seed never weighs nothing).
uint32_t fixed_focus_weight(float weight) {
  const float scaled = std::round(weight * abi::kFocusWeightScale);
  return uint32_t(std::clamp(scaled, 1.0f, float(abi::kFocusWeightMax)));
}

}  // namespace

bool ActiveTilesPass::set_changed(const GpuScene& scene, const ChangeSet& changes,
                                  const Focus& focus) {
  // One pass over the records: per instance whether it is in E and its summed focus weight,
  // then each record looks up its own.
  const std::vector<uint32_t>& record_instance = scene.record_instance();
  size_t instances = 1;
  for (uint32_t instance : record_instance)
    if (instance != abi::kInvalidIndex) instances = std::max<size_t>(instances, instance + 1);
  std::vector<uint8_t> in_changed_set(instances, 0);
  std::vector<uint32_t> focus_weight(instances, 0);
  for (uint32_t instance : changes.instances)
    if (instance < instances) in_changed_set[instance] = 1;
  std::vector<abi::FocusDisc> discs;
  for (const FocusSeed& seed : focus.seeds) {
    const uint32_t weight = fixed_focus_weight(seed.weight);
    for (uint32_t instance : seed.instances)
      if (instance < instances)
        focus_weight[instance] = std::min(focus_weight[instance] + weight, abi::kFocusPixelMax);
    if (seed.pixel && discs.size() < abi::kMaxFocusDiscs)
      discs.push_back({*seed.pixel, seed.radius, weight});
  }
  std::vector<uint32_t> records(std::max<size_t>(record_instance.size(), 1), 0);
  for (size_t r = 0; r < record_instance.size(); ++r) {
    const uint32_t instance = record_instance[r];
    records[r] =
        instance == abi::kInvalidIndex
            ? abi::kRecordChanged
            : (in_changed_set[instance] ? abi::kRecordChanged : 0u) |
                  focus_weight[instance] << abi::kFocusWeightShift |
                  (scene.record_view_dependent(uint32_t(r)) ? abi::kRecordViewDependent : 0u);
  }
  bool replaced = false;
  if (changed_records.size() < records.size() * 4) {
    // Records only grow (GpuScene reuses free ones): twice as many leaves room for the next.
    changed_records = vk::Buffer(m_ctx, records.size() * 2 * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                 vk::MemoryUse::Shared);
    m_mark_active.bind_buffer(abi::kMarkActiveChangedRecords, changed_records);
    replaced = true;
  }
  changed_records.upload(records.data(), records.size() * 4);
  m_disc_count = uint32_t(discs.size());
  if (!discs.empty()) m_focus_discs.upload(discs.data(), discs.size() * sizeof(abi::FocusDisc));
  return replaced;
}

void ActiveTilesPass::record(VkCommandBuffer cmd, bool everything, bool reprojected,
                             bool moved) const {
  const uint32_t push[4] = {m_disc_count, everything ? 1u : 0u, reprojected ? 1u : 0u,
                            moved ? 1u : 0u};
  m_mark_active.dispatch(cmd, push, groups_for(m_pixels));
}

}  // namespace hipr
