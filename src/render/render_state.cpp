#include "render/render_state.h"

#include <algorithm>

#include "core/timer.h"
#include "render/kernel_features.h"

namespace hipr {

abi::TracePush no_tile_push(const TracePass& pass, uint32_t tile_count) {
  abi::TracePush push = pass.push(0, tile_count, 1);
  push.requireFlags = 1u << 31;
  return push;
}

RenderState::RenderState(const vk::Context& c, const Scene& scene, const RenderSettings& s)
    : ctx(c),
      settings(s),
      gpu(c, scene, s.light_groups),
      tiles(c, s),
      features(s.specialize_kernel ? hipr::kernel_features(scene) : all_kernel_features()),
      film(c, s.width, s.height, gpu.light_groups().count, s.difference_estimate,
           gpu.descriptor_set(), tiles.flags),
      // The display pass reads the G-buffer from the start (which surface a pixel shows), so
      // the G-buffers exist even in renders that never run HiPR's stages.
      gbuffers(c, gpu, s.width, s.height),
      resolve(c, gpu, tiles, film, gbuffers, s.width, s.height),
      relight(c, film, resolve, gpu.light_groups().count, s.width, s.height),
      trace(c, gpu, tiles, film, resolve.display, s, features) {
  if (s.guiding) {
    guide = std::make_unique<GuidePass>(c, gpu, tiles, film, resolve.display, s, features);
    guide->warm_up();
  }
}

void RenderState::ensure_guide() const {
  if (!guide || !guide_stale) return;
  const Timer timer;
  guide->train();
  guide_stale = false;
  guide_cost.trainings += 1;
  guide_cost.training_seconds += timer.seconds();
}

RenderState::~RenderState() = default;

void RenderState::warm_up_trace() {
  if (!settings.compile_kernels_early) return;
  ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) { trace.record(cmd, no_tile_push(trace, tiles.count())); });
}

void RenderState::trace_entries(const TracePass& pass, uint32_t offset, uint32_t count,
                                uint32_t samples_per_pixel, uint32_t require, uint32_t skip,
                                std::optional<DisplayRule> then_resolve) const {
  if (offset >= tiles.count() || count == 0) return;
  count = std::min(count, tiles.count() - offset);
  abi::TracePush push = pass.push(offset, count, samples_per_pixel);
  push.requireFlags = require;
  push.skipFlags = skip;
  push.sampleTarget = sample_target.round;
  push.focusTarget = sample_target.focus;
  push.leadTarget = sample_target.lead;
  ensure_guide();
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    pass.record(cmd, push);
    if (then_resolve) resolve.record(cmd, {offset, count, require, skip}, *then_resolve);
  });
}

const GBufferPass& RenderState::rendered_gbuffers() {
  if (!gbuffers.ever_rendered()) gbuffers.render();
  return gbuffers;
}

DenoisePass& RenderState::denoise_pass() {
  if (!denoiser) {
    denoiser = std::make_unique<DenoisePass>(ctx, gpu, film, resolve.display, settings.width,
                                             settings.height);
    if (settings.compile_kernels_early) denoiser->run(DenoiseSettings{.enabled = true});
  }
  return *denoiser;
}

ExposureMeter& RenderState::exposure_meter() {
  if (!exposure)
    exposure =
        std::make_unique<ExposureMeter>(ctx, resolve.display, settings.width, settings.height);
  return *exposure;
}

}  // namespace hipr
