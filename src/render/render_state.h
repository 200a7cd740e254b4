#pragma once
// One render's state on the device: the GPU scene, the tile state, the film, the G-buffers and
// the display, with the passes every render runs over them (trace, G-buffer, display resolve,
// relight of the stale display). The engine (Renderer) owns it; a rendering method (HiPR:
// src/hipr/hipr_stages.h) attaches its own passes to it as an extension and drives them itself.
// The engine never knows which method is attached.
#include <cstdint>
#include <memory>

#include "hipr/renderer.h"
#include "render/denoise_pass.h"
#include "render/exposure_meter.h"
#include "render/film.h"
#include "render/gbuffer_pass.h"
#include "render/gpu_scene.h"
#include "render/guide_pass.h"
#include "render/overlay_pass.h"
#include "render/relight_pass.h"
#include "render/resolve_pass.h"
#include "render/tile_state.h"
#include "render/trace_pass.h"
#include "vk/context.h"

namespace hipr {

// The scheduler's round targets (ProgressiveRenderer::set_sample_target): 0 for none.
struct SampleTarget {
  uint32_t round = 0;
  uint32_t focus = 0;
  uint32_t lead = 0;
};

// Passes a method attaches to one render. They live as long as the render, so that schedulers
// coming and going (a policy switched in the viewer, one run per policy in a benchmark) reuse
// their kernels instead of compiling them again.
class RenderExtension {
 public:
  virtual ~RenderExtension() = default;
  // An edit brought in a kernel feature: the trace kernels were recompiled with `features`.
  virtual void kernel_features_changed(uint32_t features) = 0;
  // An edit replaced scene buffers bound outside the scene's set (GpuScene::layout_generation).
  virtual void scene_buffers_replaced() = 0;
};

class RenderState {
 public:
  RenderState(const vk::Context& c, const Scene& scene, const RenderSettings& s);
  RenderState(const RenderState&) = delete;
  RenderState& operator=(const RenderState&) = delete;
  virtual ~RenderState();

  // Dispatches the trace kernel over no tile (it compiles, nothing changes) when kernels are
  // compiled early (RenderSettings::compile_kernels_early).
  void warm_up_trace();

  // Traces schedule entries [offset, offset + count) of the tiles whose flags pass
  // require/skip, with `pass` (the engine's trace, or a method's own trace pass), toward the
  // scheduler's round targets; resolves them when asked, in the same submission.
  void trace_entries(const TracePass& pass, uint32_t offset, uint32_t count,
                     uint32_t samples_per_pixel, uint32_t require, uint32_t skip,
                     std::optional<DisplayRule> then_resolve) const;

  // The G-buffer exists from the start but is rendered on first need: a render that never asks
  // which surface a pixel shows never compiles the visibility kernel.
  const GBufferPass& rendered_gbuffers();

  const vk::Context& ctx;
  RenderSettings settings;
  GpuScene gpu;
  TileState tiles;
  uint32_t features;  // kernel features the trace kernels are compiled with
  Film film;
  GBufferPass gbuffers;
  ResolvePass resolve;
  RelightPass relight;
  TracePass trace;
  // Path guiding's training (RenderSettings::guiding; null without it). The guide of a new
  // scene state is learnt just before its first samples (ensure_guide, from trace_entries and
  // every other way samples are added), so its cost counts where a render's time is measured.
  std::unique_ptr<GuidePass> guide;
  mutable bool guide_stale = true;
  mutable GuideCost guide_cost;  // trainings and their time (bytes: Renderer::guide_cost)
  void ensure_guide() const;
  SampleTarget sample_target;
  // The viewer's overlays (viewer_sources.h), made on first use, and the GpuScene::
  // records_generation they show.
  std::unique_ptr<OverlayPass> overlays;
  uint64_t overlay_records_seen = 0;
  // The display denoiser (denoise_pass.h), made on first use: renders that never show a
  // denoised image never compile its kernels.
  std::unique_ptr<DenoisePass> denoiser;
  DenoisePass& denoise_pass();
  // The viewer's exposure meter over the display (exposure_meter.h), made on first use.
  std::unique_ptr<ExposureMeter> exposure;
  ExposureMeter& exposure_meter();
  // The method's passes (made by the method on first use; declared last: they refer to the
  // members above and go first).
  std::unique_ptr<RenderExtension> extension;
};

// A trace push that lets every workgroup leave at once (bit 31 is no kTile* flag): a dispatch
// that compiles the kernel and renders nothing.
abi::TracePush no_tile_push(const TracePass& pass, uint32_t tile_count);

}  // namespace hipr
