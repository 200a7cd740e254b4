#pragma once
// A compute pipeline with one descriptor set of storage buffers (and optionally one TLAS) plus
// push constants. Passes describe their bindings; nothing outside src/vk fills Vk*CreateInfo.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/shader_compiler.h"

namespace hipr::vk {

enum class BindingKind { StorageBuffer, AccelerationStructure };

struct BindingSlot {
  uint32_t binding;
  BindingKind kind = BindingKind::StorageBuffer;
};

class ComputePipeline {
 public:
  ComputePipeline(const Context& ctx, const std::string& entry, const ShaderDefines& defines,
                  std::vector<BindingSlot> bindings, uint32_t push_constant_size);
  ~ComputePipeline();
  ComputePipeline(const ComputePipeline&) = delete;
  ComputePipeline& operator=(const ComputePipeline&) = delete;

  void bind_buffer(uint32_t binding, const Buffer& buffer);
  void bind_acceleration_structure(uint32_t binding, VkAccelerationStructureKHR tlas);

  // Records bind + push constants + dispatch of `groups` workgroups (1D).
  void dispatch(VkCommandBuffer cmd, const void* push_constants, uint32_t groups) const;
  bool compiled_from_cache() const { return m_from_cache; }

 private:
  const Context& m_ctx;
  std::vector<BindingSlot> m_bindings;
  uint32_t m_push_size = 0;
  bool m_from_cache = false;
  VkDescriptorSetLayout m_set_layout = VK_NULL_HANDLE;
  VkPipelineLayout m_layout = VK_NULL_HANDLE;
  VkPipeline m_pipeline = VK_NULL_HANDLE;
  VkDescriptorPool m_pool = VK_NULL_HANDLE;
  VkDescriptorSet m_set = VK_NULL_HANDLE;
};

// Barrier between consecutive compute dispatches that read each other's buffer writes.
void compute_to_compute_barrier(VkCommandBuffer cmd);

}  // namespace hipr::vk
