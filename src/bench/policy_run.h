#pragma once
// One policy's re-render after one edit, measured step by step against a reference: the core
// of `hipr bench`.
#include <cstdint>
#include <optional>
#include <vector>

#include "bench/error_curve.h"
#include "hipr/denoise.h"
#include "hipr/renderer.h"
#include "hipr/schedule_settings.h"
#include "hipr/scheduler.h"
#include "image/error_metrics.h"
#include "render/render_snapshot.h"

namespace hipr::bench {

struct PolicyRunOptions {
  // The scheduler's settings (a tiles_per_step of 0 counts as 1; first_visit_spp 0: visit_spp).
  ScheduleSettings schedule = {.tiles_per_step = 1, .first_visit_spp = 1};
  uint32_t target_spp = 1;    // converged: every pixel has this many samples since the edit
  uint32_t max_steps = 0;     // 0: until converged
  double dense_until = 16.0;  // evaluate after every step until this much work, then sparser
  uint32_t sparse_every = 8;  // steps between evaluations after that (0 counts as 1)
  FlipOptions flip;
  // Keep the displayed image at these amounts of work (0: what the edit itself shows).
  std::vector<double> capture_work = {0.0, 0.25, 1.0};
  Focus focus;  // handed to the scheduler before the edit (docs/method.md#focus); empty: none
  // One entry per pixel, non-zero in the region whose error is also measured (focus_relmse);
  // empty: none.
  std::vector<uint8_t> focus_region;
  // Each measured image is the display denoised by these settings when enabled (a peer's
  // viewer shows its denoised image); the feedback times and the final image stay the display's.
  DenoiseSettings denoise;
};

struct PolicyRun {
  ErrorCurve curve;
  // Work and time when the display first changed anywhere (0 work: at the edit itself, relit),
  // and when every changed tile
  // (stage 1's active set) had shown its fresh estimate (at weight 1/2 or more: kTileShown);
  // -1 when it never happened.
  double first_feedback_work = -1.0, first_feedback_ms = -1.0;
  double changed_tiles_shown_work = -1.0, changed_tiles_shown_ms = -1.0;
  double overhead_seconds = 0.0;  // scheduling (stage 1, sort, display resolves) since the edit
  double wall_seconds = 0.0;      // scheduling + rendering until converged (or the last step)
  bool converged = false;
  uint32_t non_finite_samples = 0;
  ImageRGB final_image;
  // Per capture_work entry: (that work, the first image shown with at least that much work).
  std::vector<std::pair<double, ImageRGB>> captures;
  // A drag (run_drag): the work at the last of its edits; -1 for a single edit.
  double drag_work = -1.0;
};

// `renderer` holds the scene `before` the edit; `start` is the state every policy starts from.
// Applies the edit (`after`) and runs the policy, leaving the renderer on `after`.
PolicyRun run_policy(Renderer& renderer, const Scene& after, const ChangeSet& changes,
                     const RenderSnapshot& start, const ImageRGB& reference,
                     const std::vector<uint32_t>& changed_tiles, const PolicyRunOptions& options);

// From nothing: the renderer's film and display cleared, the scene it holds (whose converged
// render is `reference`) rendered by the policy's scheduler with no edit, the focus set first
// when there is one. Work counts from the empty film.
PolicyRun run_cold_start(Renderer& renderer, const ImageRGB& reference,
                         const PolicyRunOptions& options);

// A drag: the edits one after another, `work_per_edit` apart (steps run until the current
// edit has that much work: a viewer applies one per frame, and a frame has a budget), then
// steps until converged. `states[0]` is the scene the renderer holds, and
// `states[i + 1]` the scene after edit i (`changes[i]`), with its converged render
// `references[i]`: every step is measured against the scene as it is at that step. Work counts
// from the first edit. No feedback or changed-tile times (they belong to one edit).
PolicyRun run_drag(Renderer& renderer, const std::vector<Scene>& states,
                   const std::vector<ChangeSet>& changes, const RenderSnapshot& start,
                   const std::vector<ImageRGB>& references, double work_per_edit,
                   const PolicyRunOptions& options);

}  // namespace hipr::bench
