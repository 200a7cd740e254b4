#pragma once
// The tile grid of a render and the per-tile buffers its passes share: the schedule (tile ids
// in the order to render them), the flags (abi::kTile*) and the background mask.
#include <cstdint>
#include <span>
#include <vector>

#include "hipr/renderer.h"
#include "shaders/shared/abi.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace hipr {

class TileState {
 public:
  TileState(const vk::Context& ctx, const RenderSettings& settings);

  uint32_t tiles_x() const { return m_tiles_x; }
  uint32_t tiles_y() const { return m_tiles_y; }
  uint32_t count() const { return m_tiles_x * m_tiles_y; }
  uint32_t tile_size() const { return m_tile_size; }
  // Every tile id in id order.
  const std::vector<uint32_t>& all() const { return m_all; }
  // The tile a pixel belongs to.
  uint32_t tile_of(uint32_t x, uint32_t y) const {
    return (y / m_tile_size) * m_tiles_x + x / m_tile_size;
  }

  // Replaces the schedule; `order` lists every tile once.
  void set_schedule(std::span<const uint32_t> order);
  // Per tile: 1 = its camera rays cannot hit anything (BackgroundTiles).
  void set_background(const std::vector<uint32_t>& mask);

  vk::Buffer schedule, flags, background;
  // One bit per pixel (row-major, 32 per uint): the pixel leads after the edit (HiPR's stage 1
  // sets it; the trace kernel brings such pixels to the edit's lead target).
  vk::Buffer pixel_lead;
  // Per tile: how strongly a method's discovery found it changed (HiPR's stage 2 writes W(T) x
  // abi::kWeightScale as uint64, stage 3 sorts by it, the viewer's overlay shows it).
  vk::Buffer weights;

 private:
  uint32_t m_tile_size, m_tiles_x, m_tiles_y;
  std::vector<uint32_t> m_all;
};

}  // namespace hipr
