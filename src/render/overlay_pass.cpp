#include "render/overlay_pass.h"

#include <algorithm>
#include <cmath>

#include "image/tonemap.h"
#include "shaders/shared/bindings/overlay.h"

namespace hipr {
namespace {

std::vector<abi::OverlayRecord> overlay_records(const GpuScene& scene) {
  std::vector<abi::OverlayRecord> records;
  for (size_t r = 0; r < scene.record_instance().size(); ++r)
    records.push_back({scene.record_instance()[r], scene.record_node()[r]});
  if (records.empty()) records.push_back({abi::kInvalidIndex, abi::kInvalidIndex});
  return records;
}

// The sRGB byte of an id colour channel whose hash byte is k, computed as debug_images.cpp's
// id_colour and the overlays' srgb_encode do, so the kernel's ids are the CPU's exactly.
std::vector<uint32_t> id_channel_bytes() {
  std::vector<uint32_t> bytes(256);
  for (uint32_t k = 0; k < 256; ++k) {
    const float linear = 0.15f + 0.85f * float(k) / 255.0f;
    bytes[k] = uint32_t(std::lround(std::clamp(srgb_encode(linear), 0.0f, 1.0f) * 255.0f));
  }
  return bytes;
}

}  // namespace

OverlayPass::OverlayPass(const vk::Context& ctx, const GpuScene& scene,
                         const OverlaySources& sources, uint32_t width, uint32_t height,
                         uint32_t tile_size, uint32_t tiles_x, uint32_t tile_count)
    : m_ctx(ctx),
      m_width(width),
      m_height(height),
      m_tile_size(tile_size),
      m_tiles_x(tiles_x),
      m_tile_count(tile_count),
      m_records(vk::make_storage_buffer(ctx, overlay_records(scene))),
      m_id_bytes(vk::make_storage_buffer(ctx, id_channel_bytes())),
      m_max_weight(vk::make_storage_buffer(ctx, std::vector<uint64_t>(1, 0))),
      m_pipeline(ctx, "overlay.comp", {},
                 {{abi::kOverlayGBuffer, &sources.gbuffer},
                  {abi::kOverlayRecords, &m_records},
                  {abi::kOverlayTileWeights, &sources.tile_weights},
                  {abi::kOverlayTileFlags, &sources.tile_flags},
                  {abi::kOverlayAccumulation, &sources.accumulation},
                  {abi::kOverlayIdBytes, &m_id_bytes},
                  {abi::kOverlayMaxWeight, &m_max_weight},
                  {abi::kOverlayOutput, nullptr}},
                 sizeof(abi::OverlayPush)) {}

void OverlayPass::update_records(const GpuScene& scene) {
  const std::vector<abi::OverlayRecord> records = overlay_records(scene);
  if (m_records.size() >= records.size() * sizeof(abi::OverlayRecord)) {
    m_records.upload(records.data(), records.size() * sizeof(abi::OverlayRecord));
  } else {
    m_records = vk::make_storage_buffer(m_ctx, records);
    m_pipeline.bind_buffer(abi::kOverlayRecords, m_records);
  }
}

void OverlayPass::render(uint32_t mode, uint32_t selected_node, const vk::Buffer& output) {
  m_pipeline.bind_buffer(abi::kOverlayOutput, output);
  abi::OverlayPush push{mode,     selected_node, 0u,        m_width,
                        m_height, m_tile_size,   m_tiles_x, m_tile_count};
  m_ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    vk::compute_to_compute_barrier(cmd);  // the weights, flags and G-buffer of earlier work
    if (mode == abi::kOverlayWeights) {   // the largest weight first: the heat map's scale
      vkCmdFillBuffer(cmd, m_max_weight.handle(), 0, VK_WHOLE_SIZE, 0);
      vk::transfer_to_compute_barrier(cmd);
      m_pipeline.dispatch(cmd, &push,
                          (m_tile_count + abi::kWorkgroupSize - 1) / abi::kWorkgroupSize);
      vk::compute_to_compute_barrier(cmd);
    }
    push.pass = 1u;
    m_pipeline.dispatch(cmd, &push,
                        (m_width * m_height + abi::kWorkgroupSize - 1) / abi::kWorkgroupSize);
  });
}

}  // namespace hipr
