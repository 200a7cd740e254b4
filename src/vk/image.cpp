#include "vk/image.h"

#include <utility>

#include "core/error.h"
#include "vk/check.h"

namespace hipr::vk {
namespace {

uint32_t device_local_memory_type(const Context& ctx, uint32_t allowed) {
  VkPhysicalDeviceMemoryProperties props;
  vkGetPhysicalDeviceMemoryProperties(ctx.physical_device(), &props);
  for (VkMemoryPropertyFlags wanted :
       {VkMemoryPropertyFlags(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT), VkMemoryPropertyFlags(0)})
    for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
      if ((allowed & (1u << i)) && (props.memoryTypes[i].propertyFlags & wanted) == wanted)
        return i;
  throw InternalError("no Vulkan memory type for an image");
}

VkImageMemoryBarrier image_barrier(VkImage image, VkImageLayout from, VkImageLayout to,
                                   VkAccessFlags src, VkAccessFlags dst) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = src;
  barrier.dstAccessMask = dst;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  return barrier;
}

}  // namespace

Image::Image(const Context& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage)
    : m_ctx(&ctx), m_extent(extent), m_format(format) {
  if (extent.width == 0 || extent.height == 0)
    throw InternalError("an image needs a non-zero size");
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.width, extent.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  try {
    VK_CHECK(vkCreateImage(ctx.device(), &info, nullptr, &m_image));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(ctx.device(), m_image, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = device_local_memory_type(ctx, req.memoryTypeBits);
    VK_CHECK(vkAllocateMemory(ctx.device(), &alloc, nullptr, &m_memory));
    VK_CHECK(vkBindImageMemory(ctx.device(), m_image, m_memory, 0));
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = m_image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VK_CHECK(vkCreateImageView(ctx.device(), &view, nullptr, &m_view));
  } catch (...) {
    release();
    throw;
  }
}

Image::~Image() { release(); }

Image::Image(Image&& other) noexcept { *this = std::move(other); }

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    release();
    m_ctx = other.m_ctx;
    m_image = std::exchange(other.m_image, VK_NULL_HANDLE);
    m_memory = std::exchange(other.m_memory, VK_NULL_HANDLE);
    m_view = std::exchange(other.m_view, VK_NULL_HANDLE);
    m_extent = std::exchange(other.m_extent, VkExtent2D{0, 0});
    m_format = std::exchange(other.m_format, VK_FORMAT_UNDEFINED);
  }
  return *this;
}

void Image::release() {
  if (!m_ctx) return;
  if (m_view) vkDestroyImageView(m_ctx->device(), m_view, nullptr);
  if (m_image) vkDestroyImage(m_ctx->device(), m_image, nullptr);
  if (m_memory) vkFreeMemory(m_ctx->device(), m_memory, nullptr);
  m_view = VK_NULL_HANDLE;
  m_image = VK_NULL_HANDLE;
  m_memory = VK_NULL_HANDLE;
}

void record_buffer_to_image(VkCommandBuffer cmd, const Buffer& source, const Image& image) {
  VkBufferMemoryBarrier written{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  written.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  written.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  written.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  written.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  written.buffer = source.handle();
  written.size = VK_WHOLE_SIZE;
  // The previous frame's content is not needed: UNDEFINED lets the driver drop it. The source
  // stage includes transfer so the last frame's copy out of the image is ordered before.
  const VkImageMemoryBarrier to_dst =
      image_barrier(image.handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    0, VK_ACCESS_TRANSFER_WRITE_BIT);
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 1, &written, 1, &to_dst);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {image.extent().width, image.extent().height, 1};
  vkCmdCopyBufferToImage(cmd, source.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         1, &region);
}

std::vector<uint8_t> read_image_rgba8(const Context& ctx, const Image& image) {
  const VkExtent2D e = image.extent();
  const VkDeviceSize bytes = VkDeviceSize(e.width) * e.height * 4;
  Buffer staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback);
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {e.width, e.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           staging.handle(), 1, &region);
  });
  std::vector<uint8_t> pixels(bytes);
  staging.download(pixels.data(), bytes);
  return pixels;
}

}  // namespace hipr::vk
