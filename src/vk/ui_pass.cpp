#include "vk/ui_pass.h"

#include "vk/check.h"

namespace hipr::vk {

UiPass::UiPass(const Context& ctx, VkFormat format) : m_ctx(ctx) {
  VkAttachmentDescription color{};
  color.format = format;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the rendered image is already there
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  const VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &reference;
  // Before: the copy that filled the image. After: the copy to the swapchain / read-back.
  VkSubpassDependency dependencies[2]{};
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[0].srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  dependencies[0].dstAccessMask =
      VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &color;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = dependencies;
  VK_CHECK(vkCreateRenderPass(ctx.device(), &info, nullptr, &m_render_pass));

  // The UI library needs one combined image sampler (its font atlas); a few spare sets.
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
  VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  pool.maxSets = 8;
  pool.poolSizeCount = 1;
  pool.pPoolSizes = &size;
  const VkResult result = vkCreateDescriptorPool(ctx.device(), &pool, nullptr, &m_pool);
  if (result != VK_SUCCESS) vkDestroyRenderPass(ctx.device(), m_render_pass, nullptr);
  VK_CHECK(result);
}

UiPass::~UiPass() {
  const VkDevice device = m_ctx.device();
  if (m_framebuffer) vkDestroyFramebuffer(device, m_framebuffer, nullptr);
  if (m_pool) vkDestroyDescriptorPool(device, m_pool, nullptr);
  if (m_render_pass) vkDestroyRenderPass(device, m_render_pass, nullptr);
}

void UiPass::set_target(const Image& target) {
  if (m_framebuffer) vkDestroyFramebuffer(m_ctx.device(), m_framebuffer, nullptr);
  m_framebuffer = VK_NULL_HANDLE;
  const VkImageView view = target.view();
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = m_render_pass;
  info.attachmentCount = 1;
  info.pAttachments = &view;
  info.width = target.extent().width;
  info.height = target.extent().height;
  info.layers = 1;
  VK_CHECK(vkCreateFramebuffer(m_ctx.device(), &info, nullptr, &m_framebuffer));
  m_extent = target.extent();
}

void UiPass::begin(VkCommandBuffer cmd) const {
  VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  info.renderPass = m_render_pass;
  info.framebuffer = m_framebuffer;
  info.renderArea = {{0, 0}, m_extent};
  vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
}

void UiPass::end(VkCommandBuffer cmd) const { vkCmdEndRenderPass(cmd); }

}  // namespace hipr::vk
