#pragma once
// A compute kernel: its pipeline, its own descriptor set of storage buffers (set 0) and push
// constants; kernels that read the scene also bind the scene's set (set 1, owned by GpuScene).
// Passes list their buffers once; nothing outside src/vk fills Vk*CreateInfo.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/descriptor_set.h"
#include "vk/shader_compiler.h"

namespace hipr::vk {

class ComputePipeline {
 public:
  // `bindings`: the kernel's own buffers (set 0). `shared`: a set bound as set 1 at every
  // dispatch (read when dispatching, so rebinding its buffers needs no new pipeline), or none.
  ComputePipeline(const Context& ctx, const std::string& entry, const ShaderDefines& defines,
                  const std::vector<BufferBinding>& bindings, uint32_t push_constant_size,
                  const DescriptorSet* shared = nullptr);
  ~ComputePipeline();
  ComputePipeline(const ComputePipeline&) = delete;
  ComputePipeline& operator=(const ComputePipeline&) = delete;

  // Points a binding of the kernel's own set at another buffer (one that was replaced).
  void bind_buffer(uint32_t binding, const Buffer& buffer) { m_own.bind_buffer(binding, buffer); }

  // Records bind + push constants + dispatch of `groups` workgroups (1D).
  void dispatch(VkCommandBuffer cmd, const void* push_constants, uint32_t groups) const;

 private:
  const Context& m_ctx;
  DescriptorSet m_own;
  const DescriptorSet* m_shared;
  uint32_t m_push_size = 0;
  VkPipelineLayout m_layout = VK_NULL_HANDLE;
  VkPipeline m_pipeline = VK_NULL_HANDLE;
};

// Barrier between consecutive compute dispatches that read each other's buffer writes.
void compute_to_compute_barrier(VkCommandBuffer cmd);
// Barrier from transfer commands (fills, copies) to compute dispatches that read or write them.
void transfer_to_compute_barrier(VkCommandBuffer cmd);
// Barrier from compute writes to a transfer that reads them (a copy out of a kernel's output).
void compute_to_transfer_barrier(VkCommandBuffer cmd);

}  // namespace hipr::vk
