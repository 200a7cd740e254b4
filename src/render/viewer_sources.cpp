#include "render/viewer_sources.h"

#include "render/render_state.h"

namespace hipr {

const vk::Buffer& display_texels(const Renderer& renderer) {
  return renderer.state().resolve.display;
}

const vk::Buffer& denoised_display(Renderer& renderer) {
  return renderer.render_state()->denoise_pass().result;
}

bool has_denoiser(const Renderer& renderer) { return renderer.state().denoiser != nullptr; }

bool has_exposure_meter(const Renderer& renderer) { return renderer.state().exposure != nullptr; }

float metered_display_exposure(Renderer& renderer) {
  return renderer.render_state()->exposure_meter().metered_ev();
}

void record_denoise(Renderer& renderer, VkCommandBuffer cmd, const DenoiseSettings& settings) {
  renderer.render_state()->denoise_pass().record(cmd, settings);
}

void render_overlay(Renderer& renderer, DebugOverlay overlay, uint32_t selected_node,
                    const vk::Buffer& output) {
  RenderState& m = *renderer.render_state();
  if (!m.overlays) {
    const OverlaySources sources{m.gbuffers.current, m.tiles.weights, m.tiles.flags,
                                 m.film.accumulation};
    m.overlays =
        std::make_unique<OverlayPass>(m.ctx, m.gpu, sources, m.settings.width, m.settings.height,
                                      m.settings.tile_size, m.tiles.tiles_x(), m.tiles.count());
    m.overlay_records_seen = m.gpu.records_generation();
  }
  static constexpr uint32_t kModes[] = {abi::kOverlayNone, abi::kOverlayIds, abi::kOverlayWeights,
                                        abi::kOverlayOwed};
  m.overlays->render(kModes[size_t(overlay)],
                     selected_node == UINT32_MAX ? abi::kInvalidIndex : selected_node, output);
}

}  // namespace hipr
