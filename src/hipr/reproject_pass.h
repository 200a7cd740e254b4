#pragma once
// HiPR stage 1 after a camera edit (reproject_display.comp): the display before the edit,
// reprojected into the new view, becomes each pixel's stale estimate and what the screen shows;
// pixels it cannot vouch for are marked rejected (docs/method.md#camera-moves).
#include <cstdint>
#include <memory>

#include "hipr/scene.h"
#include "render/gbuffer_pass.h"
#include "render/gpu_scene.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class ReprojectPass {
 public:
  ReprojectPass(const vk::Context& ctx, const GpuScene& scene, const GBufferPass& gbuffers,
                const vk::Buffer& display, uint32_t width, uint32_t height);

  // Records the reprojection from `before` (the camera of the previous G-buffer) into the view
  // the current G-buffer was rendered from. Run after the capture and the new G-buffer, before
  // mark_active.comp. The first call allocates the copy of the display it reads from.
  void record(VkCommandBuffer cmd, const Camera& before);
  // Allocates the copy and compiles the kernel now, so the first camera move does not wait for
  // them (RenderSettings::compile_kernels_early).
  void prepare();

 private:
  const vk::Context& m_ctx;
  const GpuScene& m_scene;
  const GBufferPass& m_gbuffers;
  const vk::Buffer& m_display;
  uint32_t m_width, m_height;
  std::unique_ptr<vk::Buffer> m_before;  // DisplayTexel per pixel: the display at the edit
  std::unique_ptr<vk::ComputePipeline> m_reproject;
};

}  // namespace hipr
