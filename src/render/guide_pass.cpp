#include "render/guide_pass.h"

#include "shaders/shared/bindings/guide.h"

namespace hipr {

namespace {

GpuScene& with_guide(GpuScene& scene) {
  scene.reserve_guide();
  return scene;
}

}  // namespace

GuidePass::GuidePass(const vk::Context& ctx, GpuScene& scene, const TileState& tiles,
                     const Film& film, const vk::Buffer& display, const RenderSettings& settings,
                     uint32_t features)
    : m_ctx(ctx),
      m_scene(with_guide(scene)),
      m_training_spp(settings.guide_training_spp),
      m_training(ctx, scene, tiles, film, display, settings, features, {}, true),
      m_build(
          ctx, "guide_build.comp", {},
          {{abi::kGuideBuildCounts, &scene.guide_counts}, {abi::kGuideBuildGuide, &scene.guide}},
          sizeof(uint32_t)) {}

void GuidePass::train() {
  const uint32_t cells = m_scene.frame().guideCells;
  if (cells == 0) return;
  m_ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, m_scene.guide_counts.handle(), 0, VK_WHOLE_SIZE, 0);
    vk::transfer_to_compute_barrier(cmd);
    m_training.record_training(cmd, m_training_spp);
    vk::compute_to_compute_barrier(cmd);
    m_build.dispatch(cmd, &cells, (cells + abi::kWorkgroupSize - 1) / abi::kWorkgroupSize);
    vk::compute_to_compute_barrier(cmd);
  });
}

void GuidePass::warm_up() {
  const uint32_t no_cells = 0;
  m_ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    m_training.record_training(cmd, 0);
    m_build.dispatch(cmd, &no_cells, 1);
  });
}

}  // namespace hipr
