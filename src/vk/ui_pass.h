#pragma once
// The render pass the viewer's UI draws in, on top of the frame image: it keeps what the
// display pass copied there (load, not clear) and leaves the image ready to be copied to the
// swapchain or read back for a screenshot. Also owns the descriptor pool the UI library
// allocates its font texture's descriptor from.
#include <vulkan/vulkan.h>

#include "vk/context.h"
#include "vk/image.h"

namespace hipr::vk {

class UiPass {
 public:
  UiPass(const Context& ctx, VkFormat format);
  ~UiPass();
  UiPass(const UiPass&) = delete;
  UiPass& operator=(const UiPass&) = delete;

  VkRenderPass render_pass() const { return m_render_pass; }
  VkDescriptorPool descriptor_pool() const { return m_pool; }

  // (Re)creates the framebuffer over `target` (TRANSFER_DST_OPTIMAL when the pass begins; left
  // TRANSFER_SRC_OPTIMAL when it ends). Call after the frame image was (re)made.
  void set_target(const Image& target);
  void begin(VkCommandBuffer cmd) const;
  void end(VkCommandBuffer cmd) const;

 private:
  const Context& m_ctx;
  VkRenderPass m_render_pass = VK_NULL_HANDLE;
  VkDescriptorPool m_pool = VK_NULL_HANDLE;
  VkFramebuffer m_framebuffer = VK_NULL_HANDLE;
  VkExtent2D m_extent{0, 0};
};

}  // namespace hipr::vk
