#pragma once
// Progressive path tracing of listed tiles (trace_tiles.comp): every pixel of a listed tile
// gets `spp` samples added to its accumulation, with sample indices that continue its count, so
// the image never depends on tile order. With discovery on (HiPR's stage 2, DiscoveryPass) the
// kernel also gives tiles the weight of the secondary vertices the camera sees in them.
#include <cstdint>
#include <memory>
#include <vector>

#include "hipr/renderer.h"
#include "render/film.h"
#include "render/gpu_scene.h"
#include "render/tile_state.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class TracePass {
 public:
  // `features`: the kernel features (render/kernel_features.h) to compile with. `discovery`:
  // stage 2's extra buffers (shaders/shared/bindings/trace.h), empty for plain progressive tracing.
  // `display`: the display texels (DisplayTexel per pixel), whose stale estimates weigh the
  // difference records' sums. `guide_training`: the kernel variant that trains the path guide
  // (render/guide_pass.h) instead of adding samples.
  TracePass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles, const Film& film,
            const vk::Buffer& display, const RenderSettings& settings, uint32_t features,
            std::vector<vk::BufferBinding> discovery = {}, bool guide_training = false);

  // Recompiles the kernel with other features (an edit brought in a new one).
  void set_features(uint32_t features);
  // Binds the listed buffers again (after an edit replaced some: GpuScene::layout_generation).
  void rebind();

  // Parameters of a dispatch over schedule entries [offset, offset + count).
  abi::TracePush push(uint32_t offset, uint32_t count, uint32_t samples_per_pixel) const;
  void record(VkCommandBuffer cmd, const abi::TracePush& push) const;
  // The training variant: `samples_per_pixel` training paths from every pixel of the frame.
  void record_training(VkCommandBuffer cmd, uint32_t samples_per_pixel) const;

 private:
  void compile();

  const vk::Context& m_ctx;
  const GpuScene& m_scene;
  RenderSettings m_settings;
  uint32_t m_features;
  std::vector<vk::BufferBinding> m_bindings;
  bool m_difference;
  bool m_discovery;
  bool m_guide_training;
  std::unique_ptr<vk::ComputePipeline> m_pipeline;
};

// A stride coprime to `count`, near count * 0.618, for the workgroup scatter mapping (llvmpipe
// gives each thread a contiguous block of workgroups: scattering keeps every core busy).
uint32_t scatter_stride(uint32_t count);

}  // namespace hipr
