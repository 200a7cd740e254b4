#pragma once
// One descriptor set of storage buffers (and optionally acceleration structures) with its own
// layout and pool. A pass owns one for its own bindings; GpuScene owns the scene's, which every
// kernel that reads the scene binds as its second set (shaders/shared/bindings/scene.h).
#include <vulkan/vulkan.h>

#include <vector>

#include "vk/buffer.h"
#include "vk/context.h"

namespace hipr::vk {

enum class BindingKind { StorageBuffer, AccelerationStructure };

struct BindingSlot {
  uint32_t binding;
  BindingKind kind = BindingKind::StorageBuffer;
};

// A storage buffer and the binding it goes to: a pass lists each of its buffers once, and the
// layout and the descriptor writes both come from that list.
struct BufferBinding {
  uint32_t binding;
  const Buffer* buffer;  // nullptr: bound later (bind_buffer), before the first dispatch
};

class DescriptorSet {
 public:
  DescriptorSet(const Context& ctx, const std::vector<BindingSlot>& slots);
  // A set of storage buffers, laid out and written from one list.
  DescriptorSet(const Context& ctx, const std::vector<BufferBinding>& buffers);
  ~DescriptorSet();
  DescriptorSet(const DescriptorSet&) = delete;
  DescriptorSet& operator=(const DescriptorSet&) = delete;

  void bind_buffer(uint32_t binding, const Buffer& buffer);
  void bind_acceleration_structure(uint32_t binding, VkAccelerationStructureKHR tlas);

  VkDescriptorSetLayout layout() const { return m_layout; }
  VkDescriptorSet handle() const { return m_set; }

 private:
  const Context& m_ctx;
  VkDescriptorSetLayout m_layout = VK_NULL_HANDLE;
  VkDescriptorPool m_pool = VK_NULL_HANDLE;
  VkDescriptorSet m_set = VK_NULL_HANDLE;
};

}  // namespace hipr::vk
