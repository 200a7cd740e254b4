#include "render/render_readback.h"

#include "render/render_state.h"

namespace hipr {

std::vector<uint32_t> read_tile_flags(const Renderer& renderer) {
  return renderer.state().tiles.flags.download_all<uint32_t>();
}

std::vector<double> read_tile_weights(const Renderer& renderer) {
  const auto fixed = renderer.state().tiles.weights.download_all<uint64_t>();
  std::vector<double> out(fixed.size());
  for (size_t i = 0; i < fixed.size(); ++i) out[i] = double(fixed[i]) / abi::kWeightScale;
  return out;
}

std::vector<uint32_t> read_schedule(const Renderer& renderer) {
  return renderer.state().tiles.schedule.download_all<uint32_t>();
}

std::vector<uint32_t> read_owed_tiles(const Renderer& renderer) {
  const RenderState& state = renderer.state();
  const std::vector<bool> owed = state.film.owed_pixels();
  const uint32_t width = state.settings.width;
  std::vector<uint32_t> per_tile(state.tiles.count(), 0);
  for (size_t i = 0; i < owed.size(); ++i)
    if (owed[i]) ++per_tile[state.tiles.tile_of(uint32_t(i % width), uint32_t(i / width))];
  return per_tile;
}

std::vector<abi::GBufferTexel> read_gbuffer(Renderer& renderer) {
  return renderer.render_state()->rendered_gbuffers().current.download_all<abi::GBufferTexel>();
}

std::vector<abi::DisplayTexel> read_display(const Renderer& renderer) {
  return renderer.state().resolve.display.download_all<abi::DisplayTexel>();
}

DifferenceEstimates read_difference_estimates(const Renderer& renderer) {
  const RenderState& state = renderer.state();
  if (!state.film.keeps_difference()) return {};
  return difference_estimates(state.settings.width, state.settings.height,
                              state.film.accumulation.download_all<abi::PixelAccum>(),
                              state.film.difference.download_all<abi::DifferenceRecord>(),
                              state.resolve.display.download_all<abi::DisplayTexel>());
}

}  // namespace hipr
