#pragma once
// The film: per-pixel accumulation (radiance sum, sum of squares, sample count and the owed
// bit) and the ray/sample counters the trace kernels add to. Owed pixels (mark_owed.comp) keep
// their old samples until their next visit restarts them.
#include <cstdint>
#include <vector>

#include "hipr/renderer.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"
#include "shaders/shared/abi.h"

namespace hipr {

class Film {
 public:
  // `scene`: the scene's descriptor set (the kernel reads the frame parameters from it).
  Film(const vk::Context& ctx, uint32_t width, uint32_t height, const vk::DescriptorSet& scene,
       const vk::Buffer& tile_flags);

  // Every pixel owes a restart; also forgets which tiles have shown their fresh estimate.
  void record_mark_all_owed(VkCommandBuffer cmd) const;

  ImageRGB image() const;  // per-pixel mean radiance
  std::vector<uint32_t> sample_counts() const;
  // Per pixel: whether it still holds samples from before the last edit.
  std::vector<bool> owed_pixels() const;
  RenderCounters counters() const;
  void reset_counters() { stats.clear(); }  // on the GPU, no read-back
  void clear();                             // samples and counters

  vk::Buffer accumulation, stats;

 private:
  uint32_t m_width, m_height;
  vk::ComputePipeline m_mark_owed;
};

// Workgroups of abi::kWorkgroupSize invocations covering `items`.
uint32_t groups_for(uint32_t items);

}  // namespace hipr
