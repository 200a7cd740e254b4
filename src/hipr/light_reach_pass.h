#pragma once
// HiPR stage 1 for punctual-light edits (light_reach.comp): the tiles whose visible surfaces a
// changed light reaches, before or after the edit, become active, scored by how much their
// direct light changes. The kernel shades (BSDF x light), so it is compiled with the scene's
// kernel features on the first light edit or warm-up, and again when they grow.
#include <cstdint>
#include <memory>

#include "hipr/scene_diff.h"
#include "render/gbuffer_pass.h"
#include "render/gpu_scene.h"
#include "render/tile_state.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class LightReachPass {
 public:
  LightReachPass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles,
                 const GBufferPass& gbuffers, const vk::Buffer& display,
                 const vk::Buffer& tile_change, uint32_t pixels, uint32_t kernel_features);

  // Whether stage 1 can follow every light the edit changed (at most abi::kMaxReachLights).
  static bool can_follow(const ChangeSet& changes);
  // Uploads the changed lights, before and after (can_follow must hold); compiles on first use.
  void set_changed(const ChangeSet& changes);
  // Records the marking (after the G-buffer of the edited scene is rendered); nothing without
  // changed lights.
  void record(VkCommandBuffer cmd) const;
  void set_kernel_features(uint32_t features);
  // Compiles the kernel now and dispatches it over no light (it returns at once), so the first
  // light edit does not wait for it (RenderSettings::compile_kernels_early).
  void record_warm_up(VkCommandBuffer cmd);

 private:
  const vk::Context& m_ctx;
  const GpuScene& m_scene;
  const TileState& m_tiles;
  const GBufferPass& m_gbuffers;
  const vk::Buffer& m_display;
  const vk::Buffer& m_tile_change;
  vk::Buffer m_lights;  // abi::Light[2 x kMaxReachLights]: before, then after
  uint32_t m_light_count = 0;
  uint32_t m_pixels;
  uint32_t m_features;
  std::unique_ptr<vk::ComputePipeline> m_reach;  // made on the first light edit (or warm-up)

  void make_pipeline();
};

}  // namespace hipr
