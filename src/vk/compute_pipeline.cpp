#include "vk/compute_pipeline.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "vk/check.h"

namespace hipr::vk {
namespace {

void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags src_stage, VkAccessFlags src_access,
                    VkPipelineStageFlags dst_stage, VkAccessFlags dst_access) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace

ComputePipeline::ComputePipeline(const Context& ctx, const std::string& entry,
                                 const ShaderDefines& defines,
                                 const std::vector<BufferBinding>& bindings,
                                 uint32_t push_constant_size, const DescriptorSet* shared)
    : m_ctx(ctx), m_own(ctx, bindings), m_shared(shared), m_push_size(push_constant_size) {
  const VkDevice device = ctx.device();
  // Every kernel learns the device's traversal; only those that trace (traversal.glsl) read it.
  ShaderDefines all_defines = defines;
  all_defines.emplace_back("HIPR_SOFTWARE_TRAVERSAL", ctx.software_traversal() ? "1" : "0");
  const CompiledShader shader = compile_compute_shader(entry, all_defines);

  std::vector<VkDescriptorSetLayout> set_layouts = {m_own.layout()};
  if (m_shared) set_layouts.push_back(m_shared->layout());
  VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, m_push_size};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = uint32_t(set_layouts.size());
  layout_info.pSetLayouts = set_layouts.data();
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
  const VkResult result =
      vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &m_pipeline);
  vkDestroyShaderModule(device, module, nullptr);
  VK_CHECK(result);
}

ComputePipeline::~ComputePipeline() {
  const VkDevice device = m_ctx.device();
  if (m_pipeline) vkDestroyPipeline(device, m_pipeline, nullptr);
  if (m_layout) vkDestroyPipelineLayout(device, m_layout, nullptr);
}

void ComputePipeline::dispatch(VkCommandBuffer cmd, const void* push_constants,
                               uint32_t groups) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline);
  const VkDescriptorSet sets[2] = {m_own.handle(), m_shared ? m_shared->handle() : VK_NULL_HANDLE};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout, 0, m_shared ? 2 : 1, sets,
                          0, nullptr);
  if (m_push_size)
    vkCmdPushConstants(cmd, m_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, m_push_size, push_constants);
  if (groups == 0) return;
  // Folded into rows when wider than the device allows; shaders/common/dispatch.glsl unfolds.
  const uint32_t width = std::min(groups, m_ctx.max_dispatch_width());
  const uint32_t rows = (groups - 1) / width + 1;
  if (rows > m_ctx.max_dispatch_height())
    throw InputError("a dispatch of " + std::to_string(groups) + " workgroups is more than " +
                     m_ctx.device_name() + " can run: use a smaller image or larger tiles");
  vkCmdDispatch(cmd, width, rows, 1);
}

void compute_to_compute_barrier(VkCommandBuffer cmd) {
  memory_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                 VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

void transfer_to_compute_barrier(VkCommandBuffer cmd) {
  memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT,
                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                 VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

void compute_to_transfer_barrier(VkCommandBuffer cmd) {
  memory_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
}

}  // namespace hipr::vk
