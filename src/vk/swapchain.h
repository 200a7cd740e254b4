#pragma once
// The window's swapchain: present() blits the viewer's frame image into the acquired swapchain
// image (converting RGBA to the surface's order, scaling when sizes differ), then submits and
// presents it.
#include <vulkan/vulkan.h>

#include <vector>

#include "vk/context.h"
#include "vk/frame_commands.h"
#include "vk/presenter.h"

namespace hipr::vk {

class Swapchain final : public Presenter {
 public:
  // `extent`: the window's framebuffer size in pixels (the surface's own size wins when it
  // reports one).
  Swapchain(const Context& ctx, VkExtent2D extent);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  VkExtent2D extent() const override { return m_extent; }
  uint32_t image_count() const override { return uint32_t(m_images.size()); }
  uint32_t min_image_count() const override { return m_min_image_count; }
  std::string description() const override;

  void recreate(VkExtent2D extent) override;
  std::optional<PresentFrame> begin_frame() override;
  bool present(const PresentFrame& frame, const Image& image) override;
  void wait_idle() const override { m_commands.wait(); }

 private:
  void blit_to_swapchain(const PresentFrame& frame, const Image& source) const;
  void create(VkExtent2D extent);
  void destroy_swapchain();
  void create_sync();
  void destroy_sync();

  const Context& m_ctx;
  FrameCommands m_commands;
  VkSwapchainKHR m_swapchain = VK_NULL_HANDLE;
  VkExtent2D m_extent{0, 0};
  VkFormat m_format = VK_FORMAT_UNDEFINED;
  VkPresentModeKHR m_present_mode = VK_PRESENT_MODE_FIFO_KHR;
  uint32_t m_min_image_count = 2;
  std::vector<VkImage> m_images;
  std::vector<VkSemaphore> m_ready_to_present;  // one per swapchain image
  VkSemaphore m_acquired = VK_NULL_HANDLE;
};

}  // namespace hipr::vk
