#include "bench/policy_run.h"

#include <algorithm>

#include "bench/oracle_policy.h"
#include "core/error.h"
#include "core/timer.h"
#include "render/render_readback.h"
#include "render/render_snapshot.h"
#include "shaders/shared/abi.h"

namespace hipr::bench {
namespace {

bool all_shown(const std::vector<uint32_t>& flags, const std::vector<uint32_t>& tiles) {
  for (uint32_t t : tiles)
    if ((flags[t] & abi::kTileShown) == 0) return false;
  return true;
}

CurvePoint measured(uint32_t step, double work, double wall_seconds, const ImageRGB& shown,
                    const ImageRGB& reference, const PolicyRunOptions& options) {
  if (options.focus_region.empty())
    return {step, work, wall_seconds * 1e3, relmse(shown, reference),
            flip_mean(shown, reference, options.flip)};
  // One FLIP map for the frame's mean (summed as flip_mean sums) and the region's.
  const std::vector<float> flip = flip_error_map(shown, reference, options.flip);
  double sum = 0.0, region_sum = 0.0;
  size_t region_pixels = 0;
  for (size_t p = 0; p < flip.size(); ++p) {
    sum += flip[p];
    if (options.focus_region[p]) {
      region_sum += flip[p];
      ++region_pixels;
    }
  }
  CurvePoint point{step, work, wall_seconds * 1e3, relmse(shown, reference),
                   flip.empty() ? 0.0 : sum / double(flip.size())};
  point.focus_relmse = relmse_masked(shown, reference, options.focus_region);
  point.focus_flip = region_pixels ? region_sum / double(region_pixels) : 0.0;
  return point;
}

// What the screen shows: the display, or a denoised copy of it when the run asks (the display
// the scheduler judges stays as it is): a frame of the denoiser's history while the image
// converges, the final samples' filter alone once it has, as the viewer shows them.
ImageRGB shown_image(Renderer& renderer, const PolicyRunOptions& options, bool converged) {
  if (!options.denoise.enabled) return renderer.displayed_image();
  return renderer.denoised_image(converged ? without_history(options.denoise) : options.denoise);
}

// Adds the point measured at `step` to the curve, and `shown` as each capture its work reaches.
void record(PolicyRun& run, uint32_t step, double work, double wall_seconds, const ImageRGB& shown,
            const ImageRGB& reference, const PolicyRunOptions& options) {
  run.curve.push_back(measured(step, work, wall_seconds, shown, reference, options));
  while (run.captures.size() < options.capture_work.size() &&
         work >= options.capture_work[run.captures.size()])
    run.captures.emplace_back(options.capture_work[run.captures.size()], shown);
}

// One scheduling step, its time added to `wall`; returns the work since the edit.
double timed_step(Scheduler& scheduler, double& wall) {
  const Timer timer;
  scheduler.step();
  wall += timer.seconds();
  return scheduler.work_since_edit();
}

// Every step while the work is small, then every sparse_every-th, and the last.
bool evaluated_at(uint32_t step, double work, bool last, const PolicyRunOptions& options) {
  return work <= options.dense_until || last || step % std::max(options.sparse_every, 1u) == 0;
}

// A scheduler with every setting of the run (the oracle ranks against `reference`, which it
// reads at every plan: a drag updates it in place).
Scheduler make_scheduler(Renderer& renderer, const ImageRGB& reference,
                         const PolicyRunOptions& options) {
  const ScheduleSettings& s = options.schedule;
  Scheduler scheduler(renderer, make_bench_policy(s.policy, reference),
                      std::max(s.tiles_per_step, 1u), std::max(s.visit_spp, 1u));
  scheduler.configure(s, options.target_spp);
  return scheduler;
}

// The run's totals and the image it ends on; captures not reached take that image.
void finish(PolicyRun& run, const Scheduler& scheduler, double overhead_seconds,
            double wall_seconds, uint32_t non_finite_samples, const PolicyRunOptions& options) {
  run.overhead_seconds = overhead_seconds;
  run.wall_seconds = wall_seconds;
  run.non_finite_samples = non_finite_samples;
  run.final_image = scheduler.displayed_image();
  while (run.captures.size() < options.capture_work.size())
    run.captures.emplace_back(options.capture_work[run.captures.size()], run.final_image);
}

}  // namespace

PolicyRun run_policy(Renderer& renderer, const Scene& after, const ChangeSet& changes,
                     const RenderSnapshot& start, const ImageRGB& reference,
                     const std::vector<uint32_t>& changed_tiles, const PolicyRunOptions& options) {
  restore_render(renderer, start);
  Scheduler scheduler = make_scheduler(renderer, reference, options);
  if (!options.focus.empty())
    scheduler.set_focus(options.focus);  // what the user looked at before the edit

  PolicyRun run;
  const ImageRGB stale = scheduler.displayed_image();
  // Measures what the screen shows; returns the display (what feedback is judged by).
  const auto evaluate = [&](uint32_t step, double wall_seconds) {
    record(run, step, step == 0 ? 0.0 : scheduler.work_since_edit(), wall_seconds,
           shown_image(renderer, options, run.converged), reference, options);
    return scheduler.displayed_image();
  };
  double wall = 0.0;  // only scheduling and rendering: evaluation and read-backs are left out
  {
    const Timer timer;
    scheduler.on_edit(after, changes);
    wall += timer.seconds();
  }
  // What the screen shows at the edit, before any sample: the stale image, or the relit one.
  if (evaluate(0, wall).rgb != stale.rgb) {
    run.first_feedback_work = 0.0;
    run.first_feedback_ms = wall * 1e3;
  }
  for (uint32_t step = 1; options.max_steps == 0 || step <= options.max_steps; ++step) {
    const double work = timed_step(scheduler, wall);
    run.converged = work >= double(options.target_spp);
    const bool tracking = run.first_feedback_work < 0.0 || run.changed_tiles_shown_work < 0.0;
    const bool evaluated =
        evaluated_at(step, work, run.converged || step == options.max_steps, options);
    if (!evaluated && !tracking) continue;
    const ImageRGB shown = evaluated ? evaluate(step, wall) : scheduler.displayed_image();
    if (run.first_feedback_work < 0.0 && shown.rgb != stale.rgb) {
      run.first_feedback_work = work;
      run.first_feedback_ms = wall * 1e3;
    }
    if (run.changed_tiles_shown_work < 0.0 && all_shown(read_tile_flags(renderer), changed_tiles)) {
      run.changed_tiles_shown_work = work;
      run.changed_tiles_shown_ms = wall * 1e3;
    }
    if (run.converged) break;
  }
  finish(run, scheduler, scheduler.overhead_seconds(), wall, renderer.counters().non_finite_samples,
         options);
  return run;
}

PolicyRun run_cold_start(Renderer& renderer, const ImageRGB& reference,
                         const PolicyRunOptions& options) {
  renderer.reset();
  renderer.reset_counters();
  Scheduler scheduler = make_scheduler(renderer, reference, options);
  PolicyRun run;
  double wall = 0.0;
  const auto evaluate = [&](uint32_t step) {
    record(run, step, scheduler.work_since_edit(), wall,
           shown_image(renderer, options, run.converged), reference, options);
  };
  if (!options.focus.empty()) {
    const Timer timer;
    scheduler.set_focus(options.focus);
    wall += timer.seconds();
  }
  evaluate(0);
  for (uint32_t step = 1; options.max_steps == 0 || step <= options.max_steps; ++step) {
    const double work = timed_step(scheduler, wall);
    run.converged = work >= double(options.target_spp);
    if (evaluated_at(step, work, run.converged || step == options.max_steps, options))
      evaluate(step);
    if (run.converged) break;
  }
  finish(run, scheduler, scheduler.overhead_seconds(), wall, renderer.counters().non_finite_samples,
         options);
  return run;
}

PolicyRun run_drag(Renderer& renderer, const std::vector<Scene>& states,
                   const std::vector<ChangeSet>& changes, const RenderSnapshot& start,
                   const std::vector<ImageRGB>& references, double work_per_edit,
                   const PolicyRunOptions& options) {
  if (changes.empty() || states.size() != changes.size() + 1 || references.size() != changes.size())
    throw InternalError("a drag needs a scene state and a reference after every edit");
  restore_render(renderer, start);
  ImageRGB reference = references.front();  // the oracle reads the current one at each edit
  // Every setting, the converged count included: the edit's and the focus's leads run in drags
  // as after single edits.
  Scheduler scheduler = make_scheduler(renderer, reference, options);

  PolicyRun run;
  double wall = 0.0, overhead = 0.0,
         work_before = 0.0;  // work_before: of the edits before the current one
  uint32_t non_finite = 0;   // the counters restart at every edit
  uint32_t step = 0;
  const auto evaluate = [&](double work) {
    record(run, step, work, wall, shown_image(renderer, options, run.converged), reference,
           options);
  };
  for (size_t e = 0; e < changes.size(); ++e) {
    if (e > 0) {
      work_before += scheduler.work_since_edit();
      overhead += scheduler.overhead_seconds();
      non_finite += renderer.counters().non_finite_samples;
    }
    reference = references[e];
    {
      const Timer timer;
      scheduler.on_edit(states[e + 1], changes[e]);
      wall += timer.seconds();
    }
    if (e == 0) evaluate(0.0);  // what the first edit shows before any sample (stale or relit)
    const bool last = e + 1 == changes.size();
    if (last) run.drag_work = work_before;
    for (;;) {
      const double work = scheduler.work_since_edit();
      if (last ? work >= double(options.target_spp) ||
                     (options.max_steps && step >= options.max_steps)
               : work >= work_per_edit)
        break;
      const Timer timer;
      scheduler.step();
      wall += timer.seconds();
      ++step;
      // Every step during the drag; after it, as run_policy thins its evaluations.
      const double since_drag = last ? scheduler.work_since_edit() : 0.0;
      const bool done = last && scheduler.work_since_edit() >= double(options.target_spp);
      if (since_drag <= options.dense_until || done ||
          step % std::max(options.sparse_every, 1u) == 0)
        evaluate(work_before + scheduler.work_since_edit());
    }
  }
  run.converged = scheduler.work_since_edit() >= double(options.target_spp);
  finish(run, scheduler, overhead + scheduler.overhead_seconds(), wall,
         non_finite + renderer.counters().non_finite_samples, options);
  return run;
}

}  // namespace hipr::bench
