#pragma once
// The window's swapchain and the one frame in flight. A frame is one command buffer: the
// viewer records its display pass and UI into its own frame image, then blit_to_swapchain
// copies that image into the acquired swapchain image, and end_frame submits and presents.
// One frame in flight is enough: the path tracer's own submissions wait for the GPU anyway.
#include <vulkan/vulkan.h>

#include <optional>
#include <vector>

#include "vk/context.h"
#include "vk/image.h"

namespace hipr::vk {

class Swapchain {
 public:
  // `extent`: the window's framebuffer size in pixels (the surface's own size wins when it
  // reports one).
  Swapchain(const Context& ctx, VkExtent2D extent);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  VkExtent2D extent() const { return m_extent; }
  uint32_t image_count() const { return uint32_t(m_images.size()); }
  uint32_t min_image_count() const { return m_min_image_count; }
  VkPresentModeKHR present_mode() const { return m_present_mode; }

  // After a window resize, or when begin_frame/end_frame reported the swapchain out of date.
  void recreate(VkExtent2D extent);

  struct Frame {
    VkCommandBuffer cmd = VK_NULL_HANDLE;  // begun, one-time submit
    uint32_t image_index = 0;
  };
  // Waits for the previous frame, acquires an image and begins the frame's command buffer.
  // nullopt: the swapchain no longer matches the window (recreate it and skip this frame).
  std::optional<Frame> begin_frame();
  // Records a copy of `source` (TRANSFER_SRC_OPTIMAL) into the frame's swapchain image, scaled
  // to fit when sizes differ, and its transition for presentation.
  void blit_to_swapchain(const Frame& frame, const Image& source) const;
  // Ends, submits and presents. false: the swapchain is out of date or suboptimal (recreate).
  bool end_frame(const Frame& frame);
  // Waits until the last submitted frame finished on the GPU (before touching what it reads).
  void wait_idle() const;

 private:
  void create(VkExtent2D extent);
  void destroy_swapchain();
  void create_sync();
  void destroy_sync();

  const Context& m_ctx;
  VkSwapchainKHR m_swapchain = VK_NULL_HANDLE;
  VkExtent2D m_extent{0, 0};
  VkFormat m_format = VK_FORMAT_UNDEFINED;
  VkPresentModeKHR m_present_mode = VK_PRESENT_MODE_FIFO_KHR;
  uint32_t m_min_image_count = 2;
  std::vector<VkImage> m_images;
  std::vector<VkSemaphore> m_ready_to_present;  // one per swapchain image
  VkSemaphore m_acquired = VK_NULL_HANDLE;
  VkFence m_frame_done = VK_NULL_HANDLE;
  VkCommandPool m_pool = VK_NULL_HANDLE;
  VkCommandBuffer m_cmd = VK_NULL_HANDLE;
};

}  // namespace hipr::vk
