#pragma once
// HiPR's three stages on the GPU, attached to one render's device state (RenderState): stage 1
// (the G-buffer + ActiveTilesPass, LightReachPass for light edits, ReprojectPass for camera
// edits), stage 2 (the trace kernel with discovery on) and stage 3 (SchedulePass). Made on
// first use (hipr_stages): plain renders never pay for them; kept with the render, so every
// scheduler of it reuses their kernels.
#include <cstdint>
#include <optional>
#include <vector>

#include "hipr/active_tiles_pass.h"
#include "hipr/hipr_stage_runner.h"
#include "hipr/light_reach_pass.h"
#include "hipr/progressive_renderer.h"
#include "hipr/reproject_pass.h"
#include "hipr/schedule_pass.h"
#include "render/render_state.h"
#include "render/trace_pass.h"
#include "shaders/shared/abi.h"

namespace hipr {

class HiprStages final : public HiprStageRunner, public RenderExtension {
 public:
  // The first edit needs a "before": the G-buffer as the engine last rendered it, or (never
  // rendered) of the scene as it is now.
  explicit HiprStages(RenderState& state);

  uint32_t stage1_visibility(const ChangeSet& changes) override;
  void set_reprojection(bool reproject) override { m_reprojection = reproject; }
  void stage2_discover(uint32_t offset, uint32_t count, uint32_t samples_per_pixel,
                       std::optional<DisplayRule> then_resolve = std::nullopt) override;
  void build_schedule() override;
  void set_focus(const Focus& focus) override;
  uint32_t stage1_focus() override;
  uint32_t seeded_tiles() const override { return m_seeded; }
  uint32_t lead_tiles() const override { return m_lead_tiles; }
  uint32_t discovered_tiles() const override;

  // Stage 2's kernel and the light reach's follow the trace kernels' features.
  void kernel_features_changed(uint32_t features) override;
  // Binds the scene's buffers that an edit replaced (GpuScene::layout_generation) again.
  void scene_buffers_replaced() override { m_discovery.rebind(); }
  // Dispatches stage 2's and stage 3's kernels over no tile and the light reach over no light
  // (they compile, nothing changes); makes the reprojection's kernel and copy. Only where
  // kernels are compiled early (RenderSettings::compile_kernels_early).
  void warm_up();

 private:
  // Records stage 1's carry (kCarry* mode) and marking, then counts the active tiles. With
  // `reproject_from` (a camera edit and nothing else) the display is reprojected from that view
  // into the new G-buffer's first. `moved`: the edit moved geometry (ActiveTilesPass::record).
  uint32_t mark_tiles(const ChangeSet& changes, uint32_t carry_mode, bool render_gbuffer,
                      const Camera* reproject_from = nullptr, bool moved = false);

  RenderState& m_state;
  ActiveTilesPass m_active;
  LightReachPass m_reach;
  ReprojectPass m_reproject;
  TracePass m_discovery;
  SchedulePass m_schedule;
  Focus m_focus;              // marked by every stage 1
  uint32_t m_seeded = 0;      // active tiles with a change or focus score at the last stage 1
  uint32_t m_lead_tiles = 0;  // of them, tiles with a pixel that leads after the edit
  bool m_reprojection = true;
};

// The HiPR stages of a render's device state, made (and attached to it) on first use.
HiprStages& hipr_stages(RenderState& state);
// Those of hipr's renderer; throws InputError for a renderer without a device state (another
// progressive renderer gives the HiPR policy its own stages: make_hipr_policy).
HiprStages& hipr_stages(ProgressiveRenderer& renderer);

}  // namespace hipr
