#include "vk/frame_commands.h"

#include "vk/check.h"

namespace hipr::vk {

FrameCommands::FrameCommands(const Context& ctx) : m_ctx(ctx) {
  try {
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = ctx.queue_family();
    VK_CHECK(vkCreateCommandPool(ctx.device(), &pool, nullptr, &m_pool));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = m_pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &alloc, &m_cmd));
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // the first frame has nothing to wait for
    VK_CHECK(vkCreateFence(ctx.device(), &fence, nullptr, &m_done));
  } catch (...) {
    if (m_pool) vkDestroyCommandPool(ctx.device(), m_pool, nullptr);
    throw;
  }
}

FrameCommands::~FrameCommands() {
  vkDeviceWaitIdle(m_ctx.device());
  vkDestroyFence(m_ctx.device(), m_done, nullptr);
  vkDestroyCommandPool(m_ctx.device(), m_pool, nullptr);
}

VkCommandBuffer FrameCommands::begin() {
  wait();
  VK_CHECK(vkResetCommandBuffer(m_cmd, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(m_cmd, &begin));
  return m_cmd;
}

void FrameCommands::submit(VkSubmitInfo submit) {
  VK_CHECK(vkEndCommandBuffer(m_cmd));
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &m_cmd;
  VK_CHECK(vkResetFences(m_ctx.device(), 1, &m_done));
  VK_CHECK(vkQueueSubmit(m_ctx.queue(), 1, &submit, m_done));
}

void FrameCommands::wait() const {
  VK_CHECK(vkWaitForFences(m_ctx.device(), 1, &m_done, VK_TRUE, UINT64_MAX));
}

}  // namespace hipr::vk
