#pragma once
// HiPR stage 1 around the G-buffer. carry_tiles.comp first: tiles an earlier edit ranked and
// that are not re-rendered yet keep their rank, the rest restart. mark_active.comp then, with
// the G-buffer of the edited scene and the one before: a tile is active where an element of the
// changed set E is visible in either, or where the screen shows a surface the pixel no longer
// sees; each active tile gets a change score (pixels showing a changed element, twice where
// the pixel's surface changed).
#include <cstdint>
#include <vector>

#include "hipr/scene_diff.h"
#include "render/film.h"
#include "render/gbuffer_pass.h"
#include "render/gpu_scene.h"
#include "render/tile_state.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class ActiveTilesPass {
 public:
  ActiveTilesPass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles, const Film& film,
                  const GBufferPass& gbuffers, const vk::Buffer& display, const vk::Buffer& tile_weights, uint32_t pixels);

  // Marks the GeometryRecords of the changed instances (the set E the kernels test).
  void set_changed(const GpuScene& scene, const ChangeSet& changes);
  // Records the tile state the edit starts from (before the G-buffer is rendered); with
  // `everything` every tile is active (an edit no G-buffer can localize).
  void record_carry(VkCommandBuffer cmd, bool everything) const;
  // Records the marking (after the G-buffer of the edited scene is rendered).
  void record(VkCommandBuffer cmd) const;

  vk::Buffer changed_records;  // uint per GeometryRecord: 1 = in E (stage 2 reads it too)
  vk::Buffer tile_change;      // uint per tile: the change score (stage 3 orders by it)

 private:
  uint32_t m_pixels, m_tiles;
  vk::ComputePipeline m_carry, m_mark_active;
};

}  // namespace hipr
