#include "render/gbuffer_pass.h"

#include "render/film.h"
#include "shaders/shared/bindings/visibility.h"

namespace hipr {

GBufferPass::GBufferPass(const vk::Context& ctx, const GpuScene& scene, uint32_t width,
                         uint32_t height)
    : current(ctx, size_t(width) * height * sizeof(abi::GBufferTexel),
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      previous(ctx, size_t(width) * height * sizeof(abi::GBufferTexel),
               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      m_ctx(ctx),
      m_scene(scene),
      m_width(width),
      m_height(height) {}

void GBufferPass::record(VkCommandBuffer cmd) {
  if (!m_visibility)
    m_visibility = std::make_unique<vk::ComputePipeline>(
        m_ctx, "visibility.comp", vk::ShaderDefines{},
        std::vector<vk::BufferBinding>{{abi::kVisibilityGBuffer, &current}}, 0,
        &m_scene.descriptor_set());
  m_visibility->dispatch(cmd, nullptr, groups_for(m_width * m_height));
  m_current = true;
}

void GBufferPass::record_keep_previous(VkCommandBuffer cmd) const {
  const VkBufferCopy copy{0, 0, current.size()};
  vkCmdCopyBuffer(cmd, current.handle(), previous.handle(), 1, &copy);
}

void GBufferPass::render() {
  m_ctx.submit_and_wait([&](VkCommandBuffer cmd) { record(cmd); });
}

GBufferPass::Hit GBufferPass::at(uint32_t x, uint32_t y) const {
  if (x >= m_width || y >= m_height) return {};
  abi::GBufferTexel texel{};
  current.download(&texel, sizeof texel, (VkDeviceSize(y) * m_width + x) * sizeof texel);
  if (texel.record == abi::kInvalidIndex) return {};
  return {texel.record, texel.depth};
}

}  // namespace hipr
