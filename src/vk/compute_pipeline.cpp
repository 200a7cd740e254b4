#include "vk/compute_pipeline.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "vk/check.h"

namespace hipr::vk {
namespace {

VkDescriptorType descriptor_type(BindingKind kind) {
  return kind == BindingKind::AccelerationStructure ? VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR
                                                    : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

}  // namespace

ComputePipeline::ComputePipeline(const Context& ctx, const std::string& entry,
                                 const ShaderDefines& defines, std::vector<BindingSlot> bindings,
                                 uint32_t push_constant_size)
    : m_ctx(ctx), m_bindings(std::move(bindings)), m_push_size(push_constant_size) {
  const VkDevice device = ctx.device();
  const CompiledShader shader = compile_compute_shader(entry, defines);
  m_from_cache = shader.from_cache;

  std::vector<VkDescriptorSetLayoutBinding> layout_bindings;
  uint32_t buffer_count = 0, tlas_count = 0;
  for (const BindingSlot& slot : m_bindings) {
    layout_bindings.push_back({slot.binding, descriptor_type(slot.kind), 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    (slot.kind == BindingKind::AccelerationStructure ? tlas_count : buffer_count)++;
  }
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = uint32_t(layout_bindings.size());
  set_info.pBindings = layout_bindings.data();
  VK_CHECK(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &m_set_layout));

  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, m_push_size};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &m_set_layout;
  layout_info.pushConstantRangeCount = m_push_size ? 1 : 0;
  layout_info.pPushConstantRanges = &push;
  VK_CHECK(vkCreatePipelineLayout(device, &layout_info, nullptr, &m_layout));

  VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  module_info.codeSize = shader.spirv.size() * sizeof(uint32_t);
  module_info.pCode = shader.spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device, &module_info, nullptr, &module));
  VkComputePipelineCreateInfo pipeline_info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  pipeline_info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  pipeline_info.stage.module = module;
  pipeline_info.stage.pName = "main";
  pipeline_info.layout = m_layout;
  const VkResult result = vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &m_pipeline);
  vkDestroyShaderModule(device, module, nullptr);
  VK_CHECK(result);

  std::vector<VkDescriptorPoolSize> sizes;
  if (buffer_count) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffer_count});
  if (tlas_count) sizes.push_back({VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, tlas_count});
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = uint32_t(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VK_CHECK(vkCreateDescriptorPool(device, &pool_info, nullptr, &m_pool));
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = m_pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &m_set_layout;
  VK_CHECK(vkAllocateDescriptorSets(device, &alloc, &m_set));
}

ComputePipeline::~ComputePipeline() {
  const VkDevice device = m_ctx.device();
  if (m_pool) vkDestroyDescriptorPool(device, m_pool, nullptr);
  if (m_pipeline) vkDestroyPipeline(device, m_pipeline, nullptr);
  if (m_layout) vkDestroyPipelineLayout(device, m_layout, nullptr);
  if (m_set_layout) vkDestroyDescriptorSetLayout(device, m_set_layout, nullptr);
}

void ComputePipeline::bind_buffer(uint32_t binding, const Buffer& buffer) {
  VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = m_set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(m_ctx.device(), 1, &write, 0, nullptr);
}

void ComputePipeline::bind_acceleration_structure(uint32_t binding, VkAccelerationStructureKHR tlas) {
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

void ComputePipeline::dispatch(VkCommandBuffer cmd, const void* push_constants, uint32_t groups) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout, 0, 1, &m_set, 0, nullptr);
  if (m_push_size)
    vkCmdPushConstants(cmd, m_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, m_push_size, push_constants);
  if (groups == 0) return;
  // Folded into rows when wider than the device allows; shaders/common/dispatch.glsl unfolds.
  const uint32_t width = std::min(groups, m_ctx.max_dispatch_width());
  const uint32_t rows = (groups - 1) / width + 1;
  if (rows > m_ctx.max_dispatch_height())
    throw InputError("a dispatch of " + std::to_string(groups) + " workgroups is more than " + m_ctx.device_name() +
                     " can run: use a smaller image or larger tiles");
  vkCmdDispatch(cmd, width, rows, 1);
}

void compute_to_compute_barrier(VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       0, 1, &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace hipr::vk
