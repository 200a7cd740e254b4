#include "render/trace_pass.h"

#include <algorithm>
#include <numeric>

#include "core/error.h"
#include "render/kernel_features.h"
#include "shaders/shared/bindings/trace.h"

namespace hipr {

uint32_t scatter_stride(uint32_t count) {
  if (count <= 2) return 1;
  uint32_t stride = std::max<uint32_t>(1, uint32_t(double(count) * 0.6180339887));
  while (std::gcd(stride, count) != 1) ++stride;
  return stride;
}

TracePass::TracePass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles,
                     const Film& film, const vk::Buffer& display, const RenderSettings& settings,
                     uint32_t features, std::vector<vk::BufferBinding> discovery,
                     bool guide_training)
    : m_ctx(ctx),
      m_scene(scene),
      m_settings(settings),
      m_features(features),
      m_bindings{{abi::kTraceTileList, &tiles.schedule},
                 {abi::kTraceAccumulation, &film.accumulation},
                 {abi::kTraceStats, &film.stats},
                 {abi::kTraceTileFlags, &tiles.flags},
                 {abi::kTraceTileBackground, &tiles.background},
                 {abi::kTraceGroupSums, &film.group_sums},
                 {abi::kTraceMaterialGroups, &scene.material_groups},
                 {abi::kTraceDifference, &film.difference},
                 {abi::kTraceDisplay, &display},
                 {abi::kTracePixelLead, &tiles.pixel_lead}},
      m_difference(film.keeps_difference()),
      m_discovery(!discovery.empty()),
      m_guide_training(guide_training) {
  m_bindings.insert(m_bindings.end(), discovery.begin(), discovery.end());
  compile();
}

void TracePass::compile() {
  vk::ShaderDefines defines = kernel_feature_defines(m_features);
  defines.emplace_back("HIPR_LIGHT_SAMPLING", std::to_string(int(m_settings.light_sampling)));
  defines.emplace_back("HIPR_DISCOVERY", m_discovery ? "1" : "0");
  defines.emplace_back("HIPR_LIGHT_GROUPS",
                       std::to_string(m_guide_training ? 0 : m_scene.light_groups().count));
  defines.emplace_back("HIPR_DIFFERENCE", m_difference && !m_guide_training ? "1" : "0");
  defines.emplace_back("HIPR_GUIDING", m_settings.guiding && !m_guide_training ? "1" : "0");
  defines.emplace_back("HIPR_GUIDE_TRAINING", m_guide_training ? "1" : "0");
  m_pipeline =
      std::make_unique<vk::ComputePipeline>(m_ctx, "trace_tiles.comp", defines, m_bindings,
                                            sizeof(abi::TracePush), &m_scene.descriptor_set());
}

void TracePass::set_features(uint32_t features) {
  if (features == m_features) return;
  m_features = features;
  compile();
}

void TracePass::rebind() {
  for (const vk::BufferBinding& b : m_bindings)
    if (b.buffer) m_pipeline->bind_buffer(b.binding, *b.buffer);
}

abi::TracePush TracePass::push(uint32_t offset, uint32_t count, uint32_t samples_per_pixel) const {
  abi::TracePush push{};
  push.listOffset = offset;
  push.tileCount = count;
  push.groupsPerTile =
      (m_settings.tile_size * m_settings.tile_size + abi::kWorkgroupSize - 1) / abi::kWorkgroupSize;
  const uint64_t groups = uint64_t(count) * push.groupsPerTile;
  if (groups > UINT32_MAX) throw InputError("too many tiles in one dispatch");
  push.tileStride = scatter_stride(uint32_t(groups));
  push.samplesPerPixel = samples_per_pixel;
  return push;
}

void TracePass::record(VkCommandBuffer cmd, const abi::TracePush& push) const {
  m_pipeline->dispatch(cmd, &push, push.tileCount * push.groupsPerTile);
}

void TracePass::record_training(VkCommandBuffer cmd, uint32_t samples_per_pixel) const {
  if (!m_guide_training) throw InternalError("record_training: not the training variant");
  abi::TracePush push{};
  push.samplesPerPixel = samples_per_pixel;
  const uint64_t pixels = uint64_t(m_settings.width) * m_settings.height;
  m_pipeline->dispatch(cmd, &push,
                       uint32_t((pixels + abi::kWorkgroupSize - 1) / abi::kWorkgroupSize));
}

}  // namespace hipr
