#pragma once
// The command buffer of the viewer's one frame in flight and the fence of its submission: what
// the window's swapchain and the off-screen (headless) presenter both record frames into.
#include <vulkan/vulkan.h>

#include "vk/context.h"

namespace hipr::vk {

class FrameCommands {
 public:
  explicit FrameCommands(const Context& ctx);
  ~FrameCommands();
  FrameCommands(const FrameCommands&) = delete;
  FrameCommands& operator=(const FrameCommands&) = delete;

  // Waits for the last submission, then resets and begins the command buffer (one-time submit).
  VkCommandBuffer begin();
  // Ends the command buffer and submits it with `submit`'s semaphores; the fence marks its end.
  void submit(VkSubmitInfo submit);
  // Waits until the last submission finished on the GPU.
  void wait() const;

 private:
  const Context& m_ctx;
  VkCommandPool m_pool = VK_NULL_HANDLE;
  VkCommandBuffer m_cmd = VK_NULL_HANDLE;
  VkFence m_done = VK_NULL_HANDLE;
};

}  // namespace hipr::vk
