#pragma once
// The viewer's overlays on the GPU (shaders/overlay.comp): object ids, stage 2's tile weights,
// the tiles still owed a restart and a selected node's outline, written straight into the
// display pass's overlay buffer from what the renderer holds on the device (no read-back). The
// colours are image/debug_images.cpp's; the ids match the CPU's byte for byte.
#include <cstdint>

#include "render/gpu_scene.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"

namespace hipr {

struct OverlaySources {
  const vk::Buffer& gbuffer;       // GBufferTexel per pixel, of the scene as it is now
  const vk::Buffer& tile_weights;  // uint64 per tile
  const vk::Buffer& tile_flags;
  const vk::Buffer& accumulation;  // PixelAccum per pixel
};

class OverlayPass {
 public:
  OverlayPass(const vk::Context& ctx, const GpuScene& scene, const OverlaySources& sources,
              uint32_t width, uint32_t height, uint32_t tile_size, uint32_t tiles_x,
              uint32_t tile_count);

  // Writes the overlay (`mode`: abi::kOverlay*; `selected_node` outlined on top, kInvalidIndex:
  // none) into `output` (uint RGBA8 per pixel), submits and waits.
  // The records' instances and nodes again (after an edit added or removed instances).
  void update_records(const GpuScene& scene);
  void render(uint32_t mode, uint32_t selected_node, const vk::Buffer& output);

 private:
  const vk::Context& m_ctx;
  uint32_t m_width, m_height, m_tile_size, m_tiles_x, m_tile_count;
  vk::Buffer m_records, m_id_bytes, m_max_weight;
  vk::ComputePipeline m_pipeline;
};

}  // namespace hipr
