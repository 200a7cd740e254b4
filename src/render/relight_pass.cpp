#include "render/relight_pass.h"

#include <algorithm>

#include "core/error.h"
#include "shaders/shared/bindings/relight.h"

namespace hipr {

RelightPass::RelightPass(const vk::Context& ctx, const Film& film, const ResolvePass& resolve,
                         uint32_t light_groups, uint32_t width, uint32_t height)
    : stale_groups(ctx,
                   std::max<size_t>(size_t(width) * height * light_groups, 1) * sizeof(glm::vec3),
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      m_groups(light_groups),
      m_pixels(width * height),
      m_relight(ctx, "relight.comp", {},
                {{abi::kRelightAccumulation, &film.accumulation},
                 {abi::kRelightGroupSums, &film.group_sums},
                 {abi::kRelightDisplay, &resolve.display},
                 {abi::kRelightStaleGroups, &stale_groups}},
                sizeof(abi::RelightPush)) {
  clear();
}

void RelightPass::record(VkCommandBuffer cmd, const std::vector<glm::vec3>& factors) const {
  if (factors.size() != m_groups)
    throw InternalError("relight: one factor per light group expected");
  abi::RelightPush push{};
  for (size_t g = 0; g < factors.size(); ++g) push.factors[g] = factors[g];
  push.pixelCount = m_pixels;
  push.groupCount = m_groups;
  vk::compute_to_compute_barrier(cmd);
  m_relight.dispatch(cmd, &push, groups_for(m_pixels));
}

void RelightPass::clear() { stale_groups.clear(); }

}  // namespace hipr
