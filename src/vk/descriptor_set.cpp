#include "vk/descriptor_set.h"

#include "vk/check.h"

namespace hipr::vk {
namespace {

VkDescriptorType descriptor_type(BindingKind kind) {
  return kind == BindingKind::AccelerationStructure ? VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR
                                                    : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

std::vector<BindingSlot> buffer_slots(const std::vector<BufferBinding>& buffers) {
  std::vector<BindingSlot> slots;
  for (const BufferBinding& b : buffers) slots.push_back({b.binding});
  return slots;
}

}  // namespace

DescriptorSet::DescriptorSet(const Context& ctx, const std::vector<BindingSlot>& slots)
    : m_ctx(ctx) {
  const VkDevice device = ctx.device();
  std::vector<VkDescriptorSetLayoutBinding> layout_bindings;
  uint32_t buffer_count = 0, tlas_count = 0;
  for (const BindingSlot& slot : slots) {
    layout_bindings.push_back(
        {slot.binding, descriptor_type(slot.kind), 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    (slot.kind == BindingKind::AccelerationStructure ? tlas_count : buffer_count)++;
  }
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = uint32_t(layout_bindings.size());
  set_info.pBindings = layout_bindings.data();
  VK_CHECK(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &m_layout));

  std::vector<VkDescriptorPoolSize> sizes;
  if (buffer_count) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffer_count});
  if (tlas_count) sizes.push_back({VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, tlas_count});
  // A pool must have at least one size entry, even for a set without bindings.
  if (sizes.empty()) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1});
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = uint32_t(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VK_CHECK(vkCreateDescriptorPool(device, &pool_info, nullptr, &m_pool));
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = m_pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &m_layout;
  VK_CHECK(vkAllocateDescriptorSets(device, &alloc, &m_set));
}

DescriptorSet::DescriptorSet(const Context& ctx, const std::vector<BufferBinding>& buffers)
    : DescriptorSet(ctx, buffer_slots(buffers)) {
  for (const BufferBinding& b : buffers)
    if (b.buffer) bind_buffer(b.binding, *b.buffer);
}

DescriptorSet::~DescriptorSet() {
  const VkDevice device = m_ctx.device();
  if (m_pool) vkDestroyDescriptorPool(device, m_pool, nullptr);
  if (m_layout) vkDestroyDescriptorSetLayout(device, m_layout, nullptr);
}

void DescriptorSet::bind_buffer(uint32_t binding, const Buffer& buffer) {
  VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = m_set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(m_ctx.device(), 1, &write, 0, nullptr);
}

void DescriptorSet::bind_acceleration_structure(uint32_t binding, VkAccelerationStructureKHR tlas) {
  VkWriteDescriptorSetAccelerationStructureKHR as_info{
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
  as_info.accelerationStructureCount = 1;
  as_info.pAccelerationStructures = &tlas;
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, &as_info};
  write.dstSet = m_set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  vkUpdateDescriptorSets(m_ctx.device(), 1, &write, 0, nullptr);
}

}  // namespace hipr::vk
