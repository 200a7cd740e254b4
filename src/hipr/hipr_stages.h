#pragma once
// HiPR's three stages on the GPU, wired to the renderer's shared state: stage 1
// (GBufferPass + ActiveTilesPass, LightReachPass for light edits, ReprojectPass for camera edits), stage 2 (DiscoveryPass: the trace kernel with discovery on)
// and stage 3 (SchedulePass). Made on first use: plain renders never pay for them.
#include <cstdint>
#include <optional>
#include <vector>

#include "hipr/active_tiles_pass.h"
#include "hipr/light_reach_pass.h"
#include "hipr/reproject_pass.h"
#include "hipr/progressive_renderer.h"
#include "hipr/resolve_pass.h"
#include "hipr/schedule_pass.h"
#include "render/trace_pass.h"
#include "shaders/shared/abi.h"

namespace hipr {

// The scheduler's round targets (ProgressiveRenderer::set_sample_target): 0 for none.
struct SampleTarget {
  uint32_t round = 0;
  uint32_t focus = 0;
  uint32_t lead = 0;
};

// What the stages share with the rest of the renderer.
struct RenderParts {
  const vk::Context& ctx;
  const RenderSettings& settings;
  const GpuScene& scene;
  TileState& tiles;
  Film& film;
  GBufferPass& gbuffers;
  const ResolvePass& resolve;
  const SampleTarget& sample_target;
};

class HiprStages final : public HiprStageRunner {
 public:
  // Renders the G-buffer of the scene as it is now, so the first edit has a "before".
  HiprStages(const RenderParts& parts, uint32_t kernel_features);

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

  // Recompiles stage 2's kernel with other kernel features.
  void set_kernel_features(uint32_t features) {
    m_discovery.set_features(features);
    m_reach.set_kernel_features(features);
  }
  // Binds the scene's buffers that an edit replaced (GpuScene::layout_generation) again.
  void rebind_scene_buffers() { m_discovery.rebind(); }
  // Dispatches stage 2's and stage 3's kernels over no tile and the light reach over no light
  // (they compile, nothing changes); makes the reprojection's kernel and copy.
  void record_warm_up(VkCommandBuffer cmd);
  // Per tile: the discovery weight W(T).
  std::vector<double> tile_weights() const;
  const vk::Buffer& tile_weights_buffer() const { return m_tile_weights; }  // uint64 per tile

 private:
  // Records stage 1's carry (kCarry* mode) and marking, then counts the active tiles. With
  // `reproject_from` (a camera edit and nothing else) the display is reprojected from that view
  // into the new G-buffer's first. `moved`: the edit moved geometry (ActiveTilesPass::record).
  uint32_t mark_tiles(const ChangeSet& changes, uint32_t carry_mode, bool render_gbuffer,
                      const Camera* reproject_from = nullptr, bool moved = false);

  RenderParts m_parts;
  vk::Buffer m_tile_weights;  // uint64 per tile: W(T) x abi::kWeightScale
  ActiveTilesPass m_active;
  LightReachPass m_reach;
  ReprojectPass m_reproject;
  TracePass m_discovery;
  SchedulePass m_schedule;
  Focus m_focus;          // marked by every stage 1
  uint32_t m_seeded = 0;  // active tiles with a change or focus score at the last stage 1
  uint32_t m_lead_tiles = 0;  // of them, tiles with a pixel that leads after the edit
  bool m_reprojection = true;
};

// A trace push that lets every workgroup leave at once (bit 31 is no kTile* flag): a dispatch
// that compiles the kernel and renders nothing.
abi::TracePush no_tile_push(const TracePass& pass, uint32_t tile_count);

}  // namespace hipr
