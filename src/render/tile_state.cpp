#include "render/tile_state.h"

#include <numeric>

#include "core/error.h"

namespace hipr {
namespace {

vk::Buffer tile_buffer(const vk::Context& ctx, uint32_t tiles,
                       vk::MemoryUse use = vk::MemoryUse::Device) {
  return vk::Buffer(ctx, size_t(tiles) * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, use);
}

}  // namespace

TileState::TileState(const vk::Context& ctx, const RenderSettings& s)
    : m_tile_size(s.tile_size),
      m_tiles_x((s.width + s.tile_size - 1) / s.tile_size),
      m_tiles_y((s.height + s.tile_size - 1) / s.tile_size) {
  schedule = tile_buffer(ctx, count(), vk::MemoryUse::Shared);  // written at every step
  flags = tile_buffer(ctx, count());
  background =
      tile_buffer(ctx, count(), vk::MemoryUse::Shared);  // written at edits that move things
  pixel_lead = vk::Buffer(ctx, (size_t(s.width) * s.height + 31) / 32 * sizeof(uint32_t),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  weights = vk::Buffer(ctx, size_t(count()) * sizeof(uint64_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  flags.clear();
  pixel_lead.clear();
  weights.clear();
  m_all.resize(count());
  std::iota(m_all.begin(), m_all.end(), 0u);
}

void TileState::set_schedule(std::span<const uint32_t> order) {
  if (order.size() != count()) throw InternalError("a schedule lists every tile once");
  schedule.upload(order.data(), order.size_bytes());
}

void TileState::set_background(const std::vector<uint32_t>& mask) {
  if (mask.size() != count()) throw InternalError("a background mask has one entry per tile");
  background.upload(mask.data(), mask.size() * sizeof(uint32_t));
}

}  // namespace hipr
