#pragma once
// Relighting by linearity (relight.comp, docs/method.md#relighting): at an edit that only scaled
// emitters' intensity or colour, every pixel's estimate is rescaled group by group and shown at
// once as the stale estimate. Owns the stale estimate's light-group shares.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/film.h"
#include "render/resolve_pass.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class RelightPass {
 public:
  RelightPass(const vk::Context& ctx, const Film& film, const ResolvePass& resolve,
              uint32_t light_groups, uint32_t width, uint32_t height);

  // Records the relight: group g's share of each pixel's estimate scaled by factors[g] (one per
  // group). Run after the stale capture, before the pixels are marked owed.
  void record(VkCommandBuffer cmd, const std::vector<glm::vec3>& factors) const;
  // No group of any stale estimate is known (with the display cleared).
  void clear();

  vk::Buffer stale_groups;  // vec3 per pixel and group: the stale estimate's shares

 private:
  uint32_t m_groups, m_pixels;
  vk::ComputePipeline m_relight;
};

}  // namespace hipr
