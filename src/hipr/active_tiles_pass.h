#pragma once
// HiPR stage 1 around the G-buffer. carry_tiles.comp first: tiles an earlier edit ranked and
// that are not re-rendered yet keep their rank, the rest restart. mark_active.comp then, with
// the G-buffer of the edited scene and the one before: a tile is active where an element of the
// changed set E is visible in either, or where the screen shows a surface the pixel no longer
// sees; each active tile gets a change score (pixels showing a changed element, twice where
// the pixel's surface changed). The focus (docs/method.md#focus) makes the tiles where it is
// seen active too, with a focus score of its own.
#include <cstdint>
#include <vector>

#include "hipr/focus.h"
#include "hipr/scene_diff.h"
#include "render/film.h"
#include "render/gbuffer_pass.h"
#include "render/gpu_scene.h"
#include "render/tile_state.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class ActiveTilesPass {
 public:
  ActiveTilesPass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles,
                  const Film& film, const GBufferPass& gbuffers, const vk::Buffer& display,
                  const vk::Buffer& tile_weights, uint32_t pixels);

  // Marks the GeometryRecords of the changed instances (the set E the kernels test) and the
  // focus's records and discs with their weights.
  // Free records (an instance that left: ChangeSet::departed) count as changed, for the
  // G-buffer before the edit shows them. Returns whether changed_records was replaced (grown
  // with the scene's records): passes that bind it must bind it again.
  bool set_changed(const GpuScene& scene, const ChangeSet& changes, const Focus& focus);
  // Records the tile state the plan starts from (before the G-buffer is rendered): `mode` is
  // kCarryEdit, kCarryEverything (every tile active: an edit no G-buffer can localize) or
  // kCarryRefocus (no edit).
  void record_carry(VkCommandBuffer cmd, uint32_t mode) const;
  // Records the marking (after the G-buffer of the edited scene is rendered); `everything` as
  // record_carry's kCarryEverything (a surface shown wrongly then scores nothing);
  // `reprojected`: the display was just reprojected (a camera edit): view-dependent surfaces
  // score, and tiles whose pixels barely moved are marked to go last. `moved`: the edit moved,
  // showed, hid or deformed geometry: the pixels that show a changed element lead (kTileLead and
  // the pixel-lead bits), besides those whose surface changed.
  void record(VkCommandBuffer cmd, bool everything, bool reprojected = false,
              bool moved = false) const;

  // uint per GeometryRecord: kRecordChanged = in E, above it the focus weight (stage 2's
  // occlusion test reads it too: a focus's shadows are discovered as an edit's are)
  vk::Buffer changed_records;
  vk::Buffer tile_change;  // uint per tile: the change score (stage 3 orders by it)
  vk::Buffer tile_focus;   // uint per tile: the focus score (stage 3 orders by it after the change)

 private:
  const vk::Context& m_ctx;
  vk::Buffer m_focus_discs;  // abi::FocusDisc[kMaxFocusDiscs]
  uint32_t m_disc_count = 0;
  uint32_t m_pixels, m_tiles;
  vk::ComputePipeline m_carry, m_mark_active;
};

}  // namespace hipr
