#include "vk/swapchain.h"

#include <algorithm>

#include "core/error.h"
#include "vk/check.h"

namespace hipr::vk {
namespace {

// The viewer writes sRGB-encoded bytes itself (the same tone map as PNG output), so the
// swapchain must store them unchanged: a UNORM format, not an _SRGB one.
VkSurfaceFormatKHR choose_format(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()));
  if (formats.empty()) throw InternalError("the window surface reports no formats");
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
    for (const VkSurfaceFormatKHR& f : formats)
      if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
  return formats[0];
}

// Rendering, not vsync, should pace the viewer: mailbox (no tearing), then immediate, then
// FIFO (always available).
VkPresentModeKHR choose_present_mode(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, modes.data()));
  for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
  return VK_PRESENT_MODE_FIFO_KHR;
}

}  // namespace

Swapchain::Swapchain(const Context& ctx, VkExtent2D extent) : m_ctx(ctx), m_commands(ctx) {
  if (!ctx.surface()) throw InternalError("a swapchain needs a context made with a window surface");
  try {
    create(extent);
  } catch (...) {
    destroy_sync();
    destroy_swapchain();
    throw;
  }
}

Swapchain::~Swapchain() {
  vkDeviceWaitIdle(m_ctx.device());
  destroy_sync();
  destroy_swapchain();
}

std::string Swapchain::description() const {
  switch (m_present_mode) {
    case VK_PRESENT_MODE_MAILBOX_KHR:
      return "window, mailbox presentation";
    case VK_PRESENT_MODE_IMMEDIATE_KHR:
      return "window, immediate presentation";
    default:
      return "window, FIFO presentation (vsync)";
  }
}

void Swapchain::create(VkExtent2D extent) {
  const VkPhysicalDevice physical = m_ctx.physical_device();
  const VkSurfaceKHR surface = m_ctx.surface();
  VkSurfaceCapabilitiesKHR caps;
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &caps));
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
    throw InternalError("the window surface cannot receive copies (no TRANSFER_DST usage)");
  const VkSurfaceFormatKHR format = choose_format(physical, surface);
  VkFormatProperties format_props;
  vkGetPhysicalDeviceFormatProperties(physical, format.format, &format_props);
  if (!(format_props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT))
    throw InternalError("the window surface's format cannot be a blit destination");
  m_format = format.format;
  m_present_mode = choose_present_mode(physical, surface);
  if (caps.currentExtent.width != UINT32_MAX) extent = caps.currentExtent;
  m_extent = {std::clamp(extent.width, caps.minImageExtent.width, caps.maxImageExtent.width),
              std::clamp(extent.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
  m_min_image_count = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) m_min_image_count = std::min(m_min_image_count, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface;
  info.minImageCount = m_min_image_count;
  info.imageFormat = format.format;
  info.imageColorSpace = format.colorSpace;
  info.imageExtent = m_extent;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha &
                                                          -caps.supportedCompositeAlpha);
  info.presentMode = m_present_mode;
  info.clipped = VK_TRUE;
  VK_CHECK(vkCreateSwapchainKHR(m_ctx.device(), &info, nullptr, &m_swapchain));
  uint32_t count = 0;
  VK_CHECK(vkGetSwapchainImagesKHR(m_ctx.device(), m_swapchain, &count, nullptr));
  m_images.resize(count);
  VK_CHECK(vkGetSwapchainImagesKHR(m_ctx.device(), m_swapchain, &count, m_images.data()));
  create_sync();
}

void Swapchain::create_sync() {
  VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VK_CHECK(vkCreateSemaphore(m_ctx.device(), &semaphore, nullptr, &m_acquired));
  m_ready_to_present.assign(m_images.size(), VK_NULL_HANDLE);
  for (VkSemaphore& s : m_ready_to_present)
    VK_CHECK(vkCreateSemaphore(m_ctx.device(), &semaphore, nullptr, &s));
}

void Swapchain::destroy_sync() {
  const VkDevice device = m_ctx.device();
  for (VkSemaphore s : m_ready_to_present)
    if (s) vkDestroySemaphore(device, s, nullptr);
  m_ready_to_present.clear();
  if (m_acquired) vkDestroySemaphore(device, m_acquired, nullptr);
  m_acquired = VK_NULL_HANDLE;
}

void Swapchain::destroy_swapchain() {
  if (m_swapchain) vkDestroySwapchainKHR(m_ctx.device(), m_swapchain, nullptr);
  m_swapchain = VK_NULL_HANDLE;
  m_images.clear();
}

void Swapchain::recreate(VkExtent2D extent) {
  VK_CHECK(vkDeviceWaitIdle(m_ctx.device()));
  // Fresh semaphores too: an acquire whose frame was skipped may have left one signalled.
  destroy_sync();
  destroy_swapchain();
  create(extent);
}

std::optional<PresentFrame> Swapchain::begin_frame() {
  wait_idle();
  uint32_t index = 0;
  const VkResult result = vkAcquireNextImageKHR(m_ctx.device(), m_swapchain, UINT64_MAX, m_acquired,
                                                VK_NULL_HANDLE, &index);
  // SUBOPTIMAL still acquired an image (and signals the semaphore): present it, then recreate.
  if (result == VK_ERROR_OUT_OF_DATE_KHR) return std::nullopt;
  if (result != VK_SUBOPTIMAL_KHR) VK_CHECK(result);
  return PresentFrame{m_commands.begin(), index};
}

void Swapchain::blit_to_swapchain(const PresentFrame& frame, const Image& source) const {
  const VkImage target = m_images[frame.image_index];
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = target;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  barrier.srcAccessMask = 0;
  barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  vkCmdPipelineBarrier(frame.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                       0, nullptr, 0, nullptr, 1, &barrier);
  // A blit rather than a copy: it converts RGBA to the swapchain's (often BGRA) order.
  VkImageBlit region{};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffsets[1] = {int32_t(source.extent().width), int32_t(source.extent().height), 1};
  region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstOffsets[1] = {int32_t(m_extent.width), int32_t(m_extent.height), 1};
  vkCmdBlitImage(frame.cmd, source.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = 0;
  barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  barrier.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  vkCmdPipelineBarrier(frame.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0, nullptr, 1,
                       &barrier);
}

bool Swapchain::present(const PresentFrame& frame, const Image& image) {
  blit_to_swapchain(frame, image);
  const VkPipelineStageFlags wait_stage =
      VK_PIPELINE_STAGE_TRANSFER_BIT;  // the blit writes the image
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &m_acquired;
  submit.pWaitDstStageMask = &wait_stage;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &m_ready_to_present[frame.image_index];
  m_commands.submit(submit);

  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &m_ready_to_present[frame.image_index];
  present.swapchainCount = 1;
  present.pSwapchains = &m_swapchain;
  present.pImageIndices = &frame.image_index;
  const VkResult result = vkQueuePresentKHR(m_ctx.queue(), &present);
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
  VK_CHECK(result);
  return true;
}

}  // namespace hipr::vk
