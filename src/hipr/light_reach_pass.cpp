#include "hipr/light_reach_pass.h"

#include <algorithm>
#include <vector>

#include "render/film.h"
#include "render/kernel_features.h"
#include "render/light_tables.h"
#include "shaders/shared/bindings/visibility.h"

namespace hipr {

LightReachPass::LightReachPass(const vk::Context& ctx, const GpuScene& scene,
                               const TileState& tiles, const GBufferPass& gbuffers,
                               const vk::Buffer& display, const vk::Buffer& tile_change,
                               uint32_t pixels, uint32_t kernel_features)
    : m_ctx(ctx),
      m_scene(scene),
      m_tiles(tiles),
      m_gbuffers(gbuffers),
      m_display(display),
      m_tile_change(tile_change),
      m_lights(ctx, sizeof(abi::Light) * 2 * abi::kMaxReachLights,
               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Shared),
      m_pixels(pixels),
      m_features(kernel_features) {}

bool LightReachPass::can_follow(const ChangeSet& changes) {
  return changes.lights.size() <= abi::kMaxReachLights;
}

void LightReachPass::set_changed(const ChangeSet& changes) {
  m_light_count = uint32_t(std::min<size_t>(changes.lights.size(), abi::kMaxReachLights));
  if (m_light_count == 0) return;
  std::vector<abi::Light> lights(2 * m_light_count);
  for (uint32_t i = 0; i < m_light_count; ++i) {
    const LightChange& change = changes.lights[i];
    lights[i] = punctual_light(change.before.light, change.before.world);
    lights[m_light_count + i] = punctual_light(change.after.light, change.after.world);
  }
  m_lights.upload(lights.data(), lights.size() * sizeof(abi::Light));
  make_pipeline();
}

void LightReachPass::make_pipeline() {
  if (m_reach) return;
  m_reach = std::make_unique<vk::ComputePipeline>(
      m_ctx, "light_reach.comp", kernel_feature_defines(m_features),
      std::vector<vk::BufferBinding>{{abi::kReachGBuffer, &m_gbuffers.current},
                                     {abi::kReachLights, &m_lights},
                                     {abi::kReachDisplay, &m_display},
                                     {abi::kReachTileFlags, &m_tiles.flags},
                                     {abi::kReachTileChange, &m_tile_change}},
      uint32_t(sizeof(uint32_t)), &m_scene.descriptor_set());
}

void LightReachPass::record_warm_up(VkCommandBuffer cmd) {
  // Only a scene with punctual lights has light edits to follow (edits add no light).
  if ((m_features & kernel_feature_bit("HIPR_FEATURE_PUNCTUAL_LIGHTS")) == 0) return;
  make_pipeline();
  const uint32_t none = 0;
  m_reach->dispatch(cmd, &none, groups_for(m_pixels));
}

void LightReachPass::record(VkCommandBuffer cmd) const {
  if (m_light_count == 0 || !m_reach) return;
  m_reach->dispatch(cmd, &m_light_count, groups_for(m_pixels));
}

void LightReachPass::set_kernel_features(uint32_t features) {
  if (features == m_features) return;
  m_features = features;
  m_reach.reset();  // compiled anew, with the new features, at the next light edit
}

}  // namespace hipr
