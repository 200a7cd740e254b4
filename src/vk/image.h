#pragma once
// A 2D colour image with its own memory and view: the viewer's frame (what the window shows,
// before it is copied to the swapchain), which a compute pass fills through a buffer copy, the
// UI draws on, and screenshots read back.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "vk/buffer.h"
#include "vk/context.h"

namespace hipr::vk {

class Image {
 public:
  Image() = default;
  Image(const Context& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage);
  ~Image();
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  VkImage handle() const { return m_image; }
  VkImageView view() const { return m_view; }
  VkExtent2D extent() const { return m_extent; }
  VkFormat format() const { return m_format; }
  explicit operator bool() const { return m_image != VK_NULL_HANDLE; }

 private:
  void release();

  const Context* m_ctx = nullptr;
  VkImage m_image = VK_NULL_HANDLE;
  VkDeviceMemory m_memory = VK_NULL_HANDLE;
  VkImageView m_view = VK_NULL_HANDLE;
  VkExtent2D m_extent{0, 0};
  VkFormat m_format = VK_FORMAT_UNDEFINED;
};

// Records: compute writes of `source` become visible to a copy of its first width x height
// 32-bit texels (row-major, tightly packed) into `image`, left in TRANSFER_DST_OPTIMAL (its
// previous content is discarded).
void record_buffer_to_image(VkCommandBuffer cmd, const Buffer& source, const Image& image);

// Reads back an RGBA8 image in TRANSFER_SRC_OPTIMAL layout (after the UI pass) as tightly
// packed rows, top row first. Waits for the GPU.
std::vector<uint8_t> read_image_rgba8(const Context& ctx, const Image& image);

}  // namespace hipr::vk
