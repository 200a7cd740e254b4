#pragma once
// Path guiding's training (docs/method.md#path-guiding): for the scene state the frame
// parameters describe, paths from every pixel (the trace kernel's training variant) splat the
// radiance each vertex received into its grid cell's direction bins, and guide_build.comp turns
// the sums into each cell's CDF. Runs at load and at every edit, before any sample of the new
// state, so every schedule renders each state with the same guide.
#include <cstdint>

#include "hipr/renderer.h"
#include "render/film.h"
#include "render/gpu_scene.h"
#include "render/tile_state.h"
#include "render/trace_pass.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class GuidePass {
 public:
  GuidePass(const vk::Context& ctx, GpuScene& scene, const TileState& tiles, const Film& film,
            const vk::Buffer& display, const RenderSettings& settings, uint32_t features);

  void set_features(uint32_t features) { m_training.set_features(features); }
  void rebind() { m_training.rebind(); }

  // Learns the guide of the scene as it is now (one submission; waits for it).
  void train();
  // Dispatches both kernels over nothing, so that drivers compiling at the first dispatch
  // (lavapipe) do it now and not inside the first timed training.
  void warm_up();

 private:
  const vk::Context& m_ctx;
  const GpuScene& m_scene;
  uint32_t m_training_spp;
  TracePass m_training;
  vk::ComputePipeline m_build;
};

}  // namespace hipr
