#include "vk/buffer.h"

#include <atomic>
#include <cstring>
#include <utility>

#include "core/error.h"
#include "vk/check.h"
#include "vk/staging.h"

namespace hipr::vk {
namespace {

std::atomic<uint64_t> g_transferred{0};   // host_transfer_bytes()
std::atomic<uint64_t> g_device_bytes{0};  // device_bytes_in_use()
std::atomic<uint64_t> g_allocations{0};   // buffer_allocations()

uint32_t find_memory_type(const Context& ctx, uint32_t allowed, VkMemoryPropertyFlags wanted,
                          VkMemoryPropertyFlags fallback) {
  VkPhysicalDeviceMemoryProperties props;
  vkGetPhysicalDeviceMemoryProperties(ctx.physical_device(), &props);
  for (VkMemoryPropertyFlags flags : {wanted, fallback}) {
    for (uint32_t i = 0; i < props.memoryTypeCount; ++i) {
      if ((allowed & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
    }
  }
  throw InternalError("no suitable Vulkan memory type");
}

bool is_host_visible(const Context& ctx, uint32_t type_index) {
  VkPhysicalDeviceMemoryProperties props;
  vkGetPhysicalDeviceMemoryProperties(ctx.physical_device(), &props);
  const VkMemoryPropertyFlags host =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  return (props.memoryTypes[type_index].propertyFlags & host) == host;
}

}  // namespace

Buffer::Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use)
    : m_ctx(&ctx), m_size(size == 0 ? 4 : size) {
  usage |= VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
           VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = m_size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VK_CHECK(vkCreateBuffer(ctx.device(), &info, nullptr, &m_buffer));

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(ctx.device(), m_buffer, &req);
  const VkMemoryPropertyFlags host =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  const uint32_t device_type =
      find_memory_type(ctx, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
  uint32_t type = device_type;
  if (use == MemoryUse::Readback)
    type =
        find_memory_type(ctx, req.memoryTypeBits, host | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, host);
  else if (use == MemoryUse::Shared)
    type = find_memory_type(ctx, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | host,
                            VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);

  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, &flags};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = type;
  try {
    VkResult result = vkAllocateMemory(ctx.device(), &alloc, nullptr, &m_memory);
    // The mappable device memory of a discrete GPU is a small heap (256 MB without resizable
    // BAR): when it is full, a shared buffer lives in device memory like the others.
    if (result != VK_SUCCESS && use == MemoryUse::Shared && type != device_type) {
      type = alloc.memoryTypeIndex = device_type;
      m_memory = VK_NULL_HANDLE;
      result = vkAllocateMemory(ctx.device(), &alloc, nullptr, &m_memory);
    }
    if (result != VK_SUCCESS) m_memory = VK_NULL_HANDLE;  // nothing for release() to free
    VK_CHECK(result);
    m_allocated = req.size;
    g_device_bytes += m_allocated;
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    VK_CHECK(vkBindBufferMemory(ctx.device(), m_buffer, m_memory, 0));
    // Staged device memory: device buffers are reached through copies, as on a discrete GPU.
    const bool map =
        is_host_visible(ctx, type) && !(use == MemoryUse::Device && ctx.staged_device_memory());
    if (map) VK_CHECK(vkMapMemory(ctx.device(), m_memory, 0, VK_WHOLE_SIZE, 0, &m_mapped));
  } catch (...) {
    release();
    throw;
  }
  VkBufferDeviceAddressInfo address{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
  address.buffer = m_buffer;
  m_address = vkGetBufferDeviceAddress(ctx.device(), &address);
}

Buffer::~Buffer() { release(); }

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    m_ctx = other.m_ctx;
    m_buffer = std::exchange(other.m_buffer, VK_NULL_HANDLE);
    m_memory = std::exchange(other.m_memory, VK_NULL_HANDLE);
    m_size = std::exchange(other.m_size, 0);
    m_address = std::exchange(other.m_address, 0);
    m_allocated = std::exchange(other.m_allocated, 0);
    m_mapped = std::exchange(other.m_mapped, nullptr);
  }
  return *this;
}

void Buffer::release() {
  if (!m_ctx) return;
  if (m_buffer) vkDestroyBuffer(m_ctx->device(), m_buffer, nullptr);
  if (m_memory) vkFreeMemory(m_ctx->device(), m_memory, nullptr);  // also unmaps
  g_device_bytes -= m_allocated;
  m_allocated = 0;
  m_buffer = VK_NULL_HANDLE;
  m_memory = VK_NULL_HANDLE;
  m_mapped = nullptr;
}

void Buffer::upload(const void* data, VkDeviceSize size, VkDeviceSize offset) {
  if (size == 0) return;
  if (offset + size > m_size) throw InternalError("buffer upload out of range");
  g_transferred.fetch_add(size, std::memory_order_relaxed);
  if (m_mapped) {
    std::memcpy(static_cast<char*>(m_mapped) + offset, data, size);
    return;
  }
  Buffer temporary;
  Buffer& staging = m_ctx->staging().for_copy(*m_ctx, size, temporary);
  staging.upload(data, size);
  m_ctx->submit_and_wait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, offset, size};
    vkCmdCopyBuffer(cmd, staging.handle(), m_buffer, 1, &region);
  });
}

void Buffer::download(void* data, VkDeviceSize size, VkDeviceSize offset) const {
  if (size == 0) return;
  if (offset + size > m_size) throw InternalError("buffer download out of range");
  g_transferred.fetch_add(size, std::memory_order_relaxed);
  if (m_mapped) {
    std::memcpy(data, static_cast<const char*>(m_mapped) + offset, size);
    return;
  }
  Buffer temporary;
  Buffer& staging = m_ctx->staging().for_copy(*m_ctx, size, temporary);
  m_ctx->submit_and_wait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{offset, 0, size};
    vkCmdCopyBuffer(cmd, m_buffer, staging.handle(), 1, &region);
  });
  staging.download(data, size);
}

void Buffer::clear() {
  m_ctx->submit_and_wait(
      [&](VkCommandBuffer cmd) { vkCmdFillBuffer(cmd, m_buffer, 0, VK_WHOLE_SIZE, 0); });
}

uint64_t host_transfer_bytes() { return g_transferred.load(std::memory_order_relaxed); }
uint64_t device_bytes_in_use() { return g_device_bytes.load(std::memory_order_relaxed); }
uint64_t buffer_allocations() { return g_allocations.load(std::memory_order_relaxed); }

}  // namespace hipr::vk
