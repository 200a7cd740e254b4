#include "hipr/reproject_pass.h"

#include <vector>

#include "render/film.h"
#include "render/frame_params.h"
#include "shaders/shared/bindings/visibility.h"

namespace hipr {

ReprojectPass::ReprojectPass(const vk::Context& ctx, const GpuScene& scene,
                             const GBufferPass& gbuffers, const vk::Buffer& display, uint32_t width,
                             uint32_t height)
    : m_ctx(ctx),
      m_scene(scene),
      m_gbuffers(gbuffers),
      m_display(display),
      m_width(width),
      m_height(height) {}

void ReprojectPass::prepare() {
  if (m_before) return;
  m_before = std::make_unique<vk::Buffer>(
      m_ctx, m_display.size(),
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  m_reproject = std::make_unique<vk::ComputePipeline>(
      m_ctx, "reproject_display.comp", vk::ShaderDefines{},
      std::vector<vk::BufferBinding>{{abi::kReprojectGBuffer, &m_gbuffers.current},
                                     {abi::kReprojectPrevious, &m_gbuffers.previous},
                                     {abi::kReprojectPreviousDisplay, m_before.get()},
                                     {abi::kReprojectDisplay, &m_display}},
      uint32_t(sizeof(abi::ViewFrame)), &m_scene.descriptor_set());
}

void ReprojectPass::record(VkCommandBuffer cmd, const Camera& before) {
  prepare();
  const VkBufferCopy copy{0, 0, m_display.size()};
  vkCmdCopyBuffer(cmd, m_display.handle(), m_before->handle(), 1, &copy);
  vk::transfer_to_compute_barrier(cmd);
  const abi::ViewFrame view = view_frame(before, float(m_width) / float(m_height));
  m_reproject->dispatch(cmd, &view, groups_for(m_width * m_height));
}

}  // namespace hipr
