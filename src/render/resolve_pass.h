#pragma once
// What the screen shows (resolve_display.comp): a display buffer apart from the accumulation.
// At an edit the shown image is captured as the stale estimate; resolves then judge per tile, by
// the display rule, when its fresh estimate may replace the stale one, and weigh each pixel's mix
// over the pixels around it (show_display.comp; docs/method.md, "The display after an edit").
#include <cstdint>
#include <vector>

#include "hipr/display_rule.h"
#include "hipr/renderer.h"
#include "render/film.h"
#include "render/gbuffer_pass.h"
#include "render/tile_state.h"
#include "shaders/shared/abi.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class ResolvePass {
 public:
  ResolvePass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles,
              const Film& film, const GBufferPass& gbuffers, uint32_t width, uint32_t height);

  // Which tiles a resolve covers: schedule entries [offset, offset + count) with all of
  // `require_flags` and none of `skip_flags`; offset abi::kInvalidIndex: tile ids 0 .. count - 1.
  struct Tiles {
    uint32_t offset;
    uint32_t count;
    uint32_t require_flags = 0;
    uint32_t skip_flags = 0;
  };
  // Records a resolve by `rule` after whatever the command buffer wrote before: the tiles are
  // judged, then their pixels and their neighbours' are shown.
  void record(VkCommandBuffer cmd, const Tiles& tiles, DisplayRule rule) const;
  // Records the capture of what every pixel shows as its stale estimate (at an edit).
  void record_capture_stale(VkCommandBuffer cmd, uint32_t tile_count) const;

  ImageRGB displayed_image() const;
  // Black everywhere, depicting no known surface; no tile judged.
  void clear();

  vk::Buffer display;  // DisplayTexel per pixel
  vk::Buffer
      judgements;  // TileJudgement per tile: its gate and regression sums, for showing its pixels

 private:
  void record_pass(VkCommandBuffer cmd, const Tiles& tiles, uint32_t rule) const;
  // A number for the next recorded resolve (ResolvePush::epoch), never 0.
  uint32_t next_epoch() const;
  // Both kernels' set 0 (shaders/shared/bindings/resolve.h).
  std::vector<vk::BufferBinding> bindings(const TileState& tiles, const Film& film,
                                          const GBufferPass& gbuffers) const;

  const GBufferPass& m_gbuffers;
  uint32_t m_width, m_height;
  bool m_difference;  // the film keeps difference records
  uint32_t m_tile_count;
  uint32_t m_tile_size;
  mutable uint32_t m_epoch = 0;  // the last resolve's number
  vk::ComputePipeline m_judge;   // resolve_display.comp
  vk::ComputePipeline m_show;    // show_display.comp
};

}  // namespace hipr
