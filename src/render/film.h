#pragma once
// The film: per-pixel accumulation (radiance sum, sum of squares, sample count and the owed
// bit), each light group's share of the sum (render/light_groups.h), and the ray/sample counters
// the trace kernels add to, and the difference records (the first samples kept for the
// difference estimate, abi::DifferenceRecord). Owed pixels (mark_owed.comp) keep their old samples
// until their next visit restarts them.
#include <cstdint>
#include <vector>

#include "hipr/renderer.h"
#include "shaders/shared/abi.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"

namespace hipr {

class Film {
 public:
  // `scene`: the scene's descriptor set (the kernel reads the frame parameters from it).
  Film(const vk::Context& ctx, uint32_t width, uint32_t height, uint32_t light_groups,
       bool keep_difference, const vk::DescriptorSet& scene, const vk::Buffer& tile_flags);

  bool keeps_difference() const { return m_difference; }

  // Every pixel owes a restart; also forgets which tiles have shown their fresh estimate.
  void record_mark_all_owed(VkCommandBuffer cmd) const;

  ImageRGB image() const;  // per-pixel mean radiance
  // Light group `group`'s share of image() (black where the pixel has no sample).
  ImageRGB group_image(uint32_t group) const;
  std::vector<uint32_t> sample_counts() const;
  // The sum of sample_counts(), added up on the GPU (8 bytes read back).
  uint64_t total_samples() const;
  // film_noise.comp's estimate, its workgroups' partial sums added up here in a fixed order.
  FilmNoise noise() const;
  // Per pixel: whether it still holds samples from before the last edit.
  std::vector<bool> owed_pixels() const;
  RenderCounters counters() const;
  void reset_counters() { stats.clear(); }  // on the GPU, no read-back
  void clear();                             // samples and counters

  vk::Buffer accumulation, stats;
  vk::Buffer group_sums;  // vec3 per pixel and group (pixel-major); one vec3 without groups
  vk::Buffer difference;  // abi::DifferenceRecord per pixel; one record without

 private:
  const vk::Context& m_ctx;
  uint32_t m_width, m_height, m_light_groups;
  bool m_difference;
  vk::ComputePipeline m_mark_owed;
  vk::Buffer m_total;  // sum_samples.comp's output
  vk::ComputePipeline m_sum_samples;
  vk::Buffer m_noise_partials;  // film_noise.comp's output: abi::NoisePartial per workgroup
  vk::ComputePipeline m_film_noise;
};

// Workgroups of `group_size` invocations (or pixels) covering `items`.
uint32_t groups_for(uint32_t items, uint32_t group_size = abi::kWorkgroupSize);

// The image whose pixel i is radiance_of(texels[i]) (a read-back of per-pixel GPU state).
template <typename Texel, typename RadianceOf>
ImageRGB image_of(uint32_t width, uint32_t height, const std::vector<Texel>& texels,
                  RadianceOf radiance_of) {
  ImageRGB image{width, height, std::vector<float>(texels.size() * 3)};
  for (size_t i = 0; i < texels.size(); ++i) {
    const glm::vec3 radiance = radiance_of(texels[i]);
    for (int c = 0; c < 3; ++c) image.rgb[i * 3 + size_t(c)] = radiance[c];
  }
  return image;
}

}  // namespace hipr
