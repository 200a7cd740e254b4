#pragma once
// HiPR stage 1 (mark_active.comp): with the G-buffer of the edited scene and the one before,
// a tile is active where an element of the changed set E is visible in either; each active
// tile gets a change score (pixels showing a changed element, twice where the pixel now shows
// another surface than before).
#include <cstdint>
#include <vector>

#include "hipr/scene_diff.h"
#include "render/gbuffer_pass.h"
#include "render/gpu_scene.h"
#include "render/tile_state.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class ActiveTilesPass {
 public:
  ActiveTilesPass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles, const GBufferPass& gbuffers,
                  uint32_t pixels);

  // Marks the GeometryRecords of the changed instances (the set E the kernels test).
  void set_changed(const GpuScene& scene, const ChangeSet& changes);
  // Records the marking (after the G-buffer of the edited scene is rendered).
  void record(VkCommandBuffer cmd) const;

  vk::Buffer changed_records;  // uint per GeometryRecord: 1 = in E (stage 2 reads it too)
  vk::Buffer tile_change;      // uint per tile: the change score (stage 3 orders by it)

 private:
  uint32_t m_pixels;
  vk::ComputePipeline m_mark_active;
};

}  // namespace hipr
