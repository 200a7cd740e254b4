// `hipr bench SCENE EDITS.json -o DIR [--policies ...] [--ref-spp N] [--steps K]`: for each edit,
// a converged reference of the edited scene (cached), then every policy from the same converged
// pre-edit state at equal work per step, with the error of the displayed image after each step.
// Writes DIR/curves.csv, DIR/summary.json, DIR/plot.png
// (docs/method.md#measuring-run-time-against-error) and, per edit, the reference and what each
// policy shows after 0.25 and 1 work units. Focus ops set the focus for the edits after them (hipr
// runs again with it, every run measures the focus region); --cold-start first measures the scene
// rendered from nothing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app/bench_report.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/denoise_flags.h"
#include "app/schedule_flags.h"
#include "bench/policy_run.h"
#include "bench/reference_cache.h"
#include "core/error.h"
#include "core/log.h"
#include "core/timer.h"
#include "hipr/edits.h"
#include "hipr/focus.h"
#include "hipr/scene_diff.h"
#include "render/render_readback.h"
#include "render/render_snapshot.h"
#include "shaders/shared/abi.h"

namespace hipr::app {
namespace {
namespace fs = std::filesystem;

struct BenchOptions {
  BenchOptions() {
    // Small enough that the shipped Cornell edits run in minutes on 2 CPU cores.
    common.render.width = 128;
    common.render.height = 128;
    common.render.tile_size = 8;
    common.spp = 64;
  }
  CommonOptions common;
  fs::path edits;
  fs::path output;
  std::vector<std::string> policies = {"hipr", "full", "scanline", "spiral", "random", "oracle"};
  uint32_t ref_spp = 1024;
  uint32_t steps = 0;  // per edit and policy; 0 = until converged
  // Its policy is --policies'; tiles_per_step 0: a sixteenth of the frame; first_visit_spp 0: 2
  // (measured best with blend on the Cornell edits), at most --spp; display: hipr's and the
  // oracle's (difference by default), the others show tiles at once.
  ScheduleSettings schedule;
  fs::path ref_cache;
  bool no_ref_cache = false;
  double drag = 0.0;        // > 0: the edits are one drag, this much work apart (full-frame passes)
  bool cold_start = false;  // measure the render of the scene as loaded, from nothing, first
  DisplayFlags display;     // the PNGs' (the metrics measure linear radiance, FLIP as clamp)
  DenoiseSettings denoise;  // enabled: every policy's displayed image is measured denoised
};

// The edits' own JSON text, one per edit: with the scene's hash it names a scene state.
std::vector<std::string> edit_texts(const fs::path& path) {
  std::ifstream in(path);
  const nlohmann::json doc = nlohmann::json::parse(in);
  std::vector<std::string> texts;
  for (const auto& edit : doc.at("edits")) texts.push_back(edit.dump());
  return texts;
}

struct PlannedRun {
  std::string name;
  Policy policy;
  Focus focus;
};

// The listed policies (none follows the focus), then hipr with the focus when there is one
// and hipr is listed.
std::vector<PlannedRun> planned_runs(const std::vector<Policy>& policies, const Focus& focus) {
  std::vector<PlannedRun> runs;
  for (Policy policy : policies) runs.push_back({policy_name(policy), policy, {}});
  if (!focus.empty() && std::find(policies.begin(), policies.end(), Policy::Hipr) != policies.end())
    runs.push_back({kFocusedHipr, Policy::Hipr, focus});
  return runs;
}

void log_run(const std::string& name, const bench::PolicyRun& run) {
  const auto auc = [&](bench::Metric metric) {
    return std::to_string(error_auc(run.curve, metric, 1.0));
  };
  std::string line = "  " + name + ": relMSE AUC(1) " + auc(bench::Metric::RelMse) +
                     ", FLIP AUC(1) " + auc(bench::Metric::Flip);
  if (!run.curve.empty() && run.curve.front().focus_relmse >= 0.0)
    line += ", focus region relMSE AUC(1) " + auc(bench::Metric::FocusRelMse) + ", FLIP AUC(1) " +
            auc(bench::Metric::FocusFlip);
  log::info(line + ", " + std::to_string(run.wall_seconds) + " s");
}

// "the focus F: N pixels".
std::string focus_line(const Scene& scene, const Focus& focus, const std::vector<uint8_t>& region) {
  const auto pixels = std::count(region.begin(), region.end(), uint8_t(1));
  return "the focus " + describe(scene, focus) + ": " + std::to_string(pixels) + " pixels";
}

// The scene as loaded, rendered from nothing by every policy (and hipr with the focus the
// script's first ops set): what a user sees after opening it, the focus region measured.
void run_cold_start_bench(const BenchOptions& o, const vk::Context& ctx, Renderer& renderer,
                          const Scene& scene, const Focus& focus, const fs::path& cache,
                          const std::vector<Policy>& policies, bench::PolicyRunOptions run_options,
                          BenchReport& report) {
  const RenderSettings& settings = o.common.render;
  const bench::Reference reference = bench::converged_reference(
      ctx, scene, bench::reference_key(ctx, scene, "", settings, o.ref_spp), settings, o.ref_spp,
      cache);
  renderer.refresh_gbuffer();
  run_options.focus_region = focus.empty() ? std::vector<uint8_t>()
                                           : focus_pixels(focus, renderer.gbuffer_instances(),
                                                          settings.width, settings.height);
  const std::string focus_text =
      focus.empty() ? "" : ", " + focus_line(scene, focus, run_options.focus_region);
  log::info("cold start" + focus_text);
  BenchEdit& edit_report = report.add_edit("cold start", reference.image, 0, renderer.tile_count());
  for (const PlannedRun& planned : planned_runs(policies, focus)) {
    if (planned.policy == Policy::Oracle) continue;  // its order needs an edit to rank
    run_options.schedule.policy = planned.policy;
    run_options.focus = planned.focus;
    const bench::PolicyRun run = bench::run_cold_start(renderer, reference.image, run_options);
    log_run(planned.name, run);
    edit_report.add_run(planned.name, run);
  }
}

// Stage 1's active set for this edit (the tiles where a changed element is visible now or
// before). Its on_edit also makes every kernel the edited scene's runs use (an edit can add a
// kernel feature), compiled early, so no timed run pays for JIT compilation.
std::vector<uint32_t> changed_tiles_and_warm_up(Renderer& renderer, const RenderSnapshot& start,
                                                const Scene& after, const ChangeSet& changes) {
  restore_render(renderer, start);
  Scheduler probe(renderer, Policy::Hipr, 1);
  probe.on_edit(after, changes);
  const std::vector<uint32_t> flags = read_tile_flags(renderer);
  std::vector<uint32_t> tiles;
  for (uint32_t t = 0; t < flags.size(); ++t)
    if (flags[t] & abi::kTileActive) tiles.push_back(t);
  return tiles;
}

// The edits as one drag: every scene state and its reference first, then each policy from
// the converged scene before the drag.
void run_drag_bench(const BenchOptions& o, const vk::Context& ctx, Renderer& renderer,
                    const Scene& scene, const std::vector<Edit>& edits,
                    const std::vector<std::string>& texts, const fs::path& cache,
                    const std::vector<Policy>& policies, bench::PolicyRunOptions run_options,
                    const std::function<DisplayRule(Policy)>& display_of, BenchReport& report) {
  std::vector<Scene> states = {scene};
  std::vector<ChangeSet> changes;
  std::vector<ImageRGB> references;
  std::string state;
  for (size_t e = 0; e < edits.size(); ++e) {
    states.push_back(states.back());
    apply_edit(states.back(), edits[e]);
    changes.push_back(diff_scenes(states[e], states.back()));
    state += texts[e];
    const bench::Reference reference = bench::converged_reference(
        ctx, states.back(),
        bench::reference_key(ctx, states.back(), state, o.common.render, o.ref_spp),
        o.common.render, o.ref_spp, cache);
    references.push_back(reference.image);
  }
  log::info("drag of " + std::to_string(edits.size()) + " edits: references ready");
  bench::converge(renderer, o.common.spp);  // the renderer holds the scene before the drag
  renderer.resolve_display_all(DisplayRule::Immediate);
  const RenderSnapshot start = snapshot_render(renderer);
  const ChangeSet whole = diff_scenes(states.front(), states.back()),
                  undo = diff_scenes(states.back(), states.front());
  changed_tiles_and_warm_up(renderer, start, states.back(), whole);  // compiles what the drag needs
  char spacing[32];
  std::snprintf(spacing, sizeof spacing, "%g", o.drag);
  BenchEdit& edit_report =
      report.add_edit("drag: " + std::to_string(edits.size()) + " edits " + spacing +
                          " passes apart, first " + describe(edits.front()),
                      references.back(), 0, renderer.tile_count());
  for (Policy policy : policies) {
    renderer.update_scene(states.front(), undo);
    run_options.schedule.policy = policy;
    run_options.schedule.display = display_of(policy);
    const bench::PolicyRun run =
        bench::run_drag(renderer, states, changes, start, references, o.drag, run_options);
    edit_report.add_run(policy_name(policy), run);
    log::info(
        "  " + policy_name(policy) + ": relMSE during the drag " +
        std::to_string(bench::error_mean(run.curve, bench::Metric::RelMse, 0.0, run.drag_work)) +
        ", over the work unit after it " +
        std::to_string(bench::error_mean(run.curve, bench::Metric::RelMse, run.drag_work,
                                         run.drag_work + 1.0)));
  }
}

int run_bench(BenchOptions& o) {
  validate_common_options(o.common);
  log::set_quiet(o.common.quiet);
  std::vector<Policy> policies;
  for (const std::string& name : o.policies) {
    const Policy policy = parse_policy(name);
    if (std::find(policies.begin(), policies.end(), policy) != policies.end())
      throw InputError("--policies names " + name + " twice");
    policies.push_back(policy);
  }
  if (policies.empty()) throw InputError("--policies names no policy");
  if (o.ref_spp < 1 || o.ref_spp > (1u << 20))
    throw InputError("--ref-spp must be between 1 and 1048576");
  ScheduleSettings& schedule = o.schedule;
  if (schedule.visit_spp < 1 || schedule.visit_spp > o.common.spp)
    throw InputError("--visit-spp must be between 1 and --spp");
  if (schedule.first_visit_spp > o.common.spp)
    throw InputError("--first-visit-spp must be between 1 and --spp");
  if (schedule.first_visit_spp == 0) schedule.first_visit_spp = std::min(2u, o.common.spp);
  if (!std::isfinite(o.drag) || o.drag < 0.0 || o.drag > 1024.0)
    throw InputError("--drag must be a work between edits from 0 to 1024 full-frame passes");
  // hipr and the oracle share a display rule: the comparison is of orders, not of displays.
  const DisplayRule ordered_display = schedule.display.value_or(default_display_rule(Policy::Hipr));

  Scene scene = load_scene(o.common.scene, o.common.load);
  const std::vector<Edit> edits = load_edit_script(o.edits);
  if (edits.empty()) throw InputError(o.edits.string() + ": the edit script has no edits");
  {
    Scene probe = scene;  // every name checked before anything renders or is written
    Focus focus;          // and every focus op (a 17th disc is refused here too)
    for (const Edit& edit : edits) {
      apply_edit(probe, edit);
      if (const auto* focus_edit = std::get_if<FocusEdit>(&edit))
        focus = with_focus_edit(probe, focus, *focus_edit);
    }
    if (std::all_of(edits.begin(), edits.end(), is_focus) && !o.cold_start)
      throw InputError(
          o.edits.string() +
          ": the edit script has only focus ops: nothing to measure without --cold-start");
    if (o.drag && std::any_of(edits.begin(), edits.end(), is_focus))
      throw InputError(o.edits.string() +
                       ": --drag takes no focus ops (a drag measures edits only)");
    if (o.drag && o.cold_start)
      throw InputError("--cold-start and --drag measure different things: use one");
  }
  const std::vector<std::string> texts = edit_texts(o.edits);
  std::error_code ec;
  fs::create_directories(o.output, ec);
  if (!fs::is_directory(o.output))
    throw InputError("cannot create output folder " + o.output.string());
  const fs::path cache = o.no_ref_cache        ? fs::path()
                         : o.ref_cache.empty() ? bench::default_reference_cache()
                                               : o.ref_cache;

  const vk::Context ctx(context_options(o.common));
  const RenderSettings& settings = o.common.render;
  RenderSettings early = settings;  // compiled before any timed step
  early.compile_kernels_early = true;
  Renderer renderer(ctx, scene, early);
  bench::PolicyRunOptions run_options;
  run_options.schedule = schedule;
  if (schedule.tiles_per_step == 0)
    run_options.schedule.tiles_per_step = default_tiles_per_step(renderer.tile_count());
  run_options.target_spp = o.common.spp;
  run_options.max_steps = o.steps;
  run_options.denoise = o.denoise;

  const nlohmann::json recorded = {
      {"width", settings.width},
      {"height", settings.height},
      {"tile", settings.tile_size},
      {"spp", o.common.spp},
      {"ref_spp", o.ref_spp},
      {"tiles_per_step", run_options.schedule.tiles_per_step},
      {"visit_spp", schedule.visit_spp},
      {"first_visit_spp", schedule.first_visit_spp},
      {"display_hipr_oracle", display_rule_name(ordered_display)},
      {"relight", schedule.relight},
      {"reproject", schedule.reproject},
      {"light_groups", settings.light_groups},
      {"steps", o.steps},
      {"drag_work_per_edit", o.drag},
      {"focus_lead", schedule.focus_lead},
      {"edit_lead", schedule.edit_lead},
      {"denoise", o.denoise.enabled},
      {"denoise_strength", o.denoise.strength},
      {"denoise_passes", o.denoise.passes},
      {"denoise_display_state", o.denoise.display_state},
      {"max_depth", settings.max_depth},
      {"seed", settings.seed},
      {"sampler", sampler_name(settings.sampler)},
      {"light_selection", light_selection_name(settings.light_selection)},
      {"guiding", settings.guiding},
      {"guide_training_spp", settings.guide_training_spp},
      {"device", ctx.device_name()},
      {"traversal", ctx.traversal_name()}};
  BenchReport report(o.common.scene.filename().string(), recorded, o.output, o.display);
  const auto display_of = [&](Policy policy) {
    return policy == Policy::Hipr || policy == Policy::Oracle ? ordered_display
                                                              : default_display_rule(policy);
  };
  if (o.drag) {
    run_drag_bench(o, ctx, renderer, scene, edits, texts, cache, policies, run_options, display_of,
                   report);
    check_validation(ctx);
    report.write();
    return kExitOk;
  }
  // The focus (docs/method.md#focus) the script's focus ops have made so far: an edit measured
  // while there is one also runs hipr with it, and every run measures the focus region's error.
  Focus focus;
  if (o.cold_start) {
    for (size_t e = 0; e < edits.size() && is_focus(edits[e]); ++e)  // the focus before any edit
      focus = with_focus_edit(scene, focus, std::get<FocusEdit>(edits[e]));
    run_cold_start_bench(o, ctx, renderer, scene, focus, cache, policies, run_options, report);
  }
  focus = {};
  std::string state;                           // the edits applied so far
  std::optional<ImageRGB> previous_reference;  // of the scene before the next edit
  for (size_t e = 0; e < edits.size(); ++e) {
    if (const auto* focus_edit = std::get_if<FocusEdit>(&edits[e])) {
      focus = with_focus_edit(scene, focus, *focus_edit);
      log::info("edit " + std::to_string(e + 1) + ": the focus is " + describe(scene, focus));
      continue;
    }
    const Scene before = scene;
    // What the edit really changed is judged between the references before and after it.
    if (!previous_reference)
      previous_reference =
          bench::converged_reference(ctx, before,
                                     bench::reference_key(ctx, before, state, settings, o.ref_spp),
                                     settings, o.ref_spp, cache)
              .image;
    apply_edit(scene, edits[e]);
    state += texts[e];
    const ChangeSet changes = diff_scenes(before, scene);
    const ChangeSet undo = diff_scenes(scene, before);
    const std::string name = describe(edits[e]);
    log::info("edit " + std::to_string(e + 1) + " (" + name + "): reference at " +
              std::to_string(o.ref_spp) + " spp");
    const bench::Reference reference = bench::converged_reference(
        ctx, scene, bench::reference_key(ctx, scene, state, settings, o.ref_spp), settings,
        o.ref_spp, cache);
    log::info(reference.from_cache
                  ? "  reference read from the cache"
                  : "  reference rendered in " + std::to_string(reference.render_seconds) + " s");

    bench::converge(renderer, o.common.spp);  // the renderer holds `before`
    renderer.resolve_display_all(DisplayRule::Immediate);
    const RenderSnapshot start = snapshot_render(renderer);
    const std::vector<uint32_t> changed =
        changed_tiles_and_warm_up(renderer, start, scene, changes);
    // The focus region: where the focus is seen in the edited scene (the probe's G-buffer).
    run_options.focus_region = focus.empty() ? std::vector<uint8_t>()
                                             : focus_pixels(focus, renderer.gbuffer_instances(),
                                                            settings.width, settings.height);
    if (!focus.empty()) log::info("  " + focus_line(scene, focus, run_options.focus_region));
    BenchEdit& edit_report =
        report.add_edit(name, reference.image, changed.size(), renderer.tile_count());
    const std::vector<uint32_t> really_changed = bench::reference_changed_tiles(
        *previous_reference, reference.image, renderer.tile_grid().tile_size);
    edit_report.reference_changed_tiles = really_changed.size();
    edit_report.active_and_changed_tiles =
        size_t(std::count_if(really_changed.begin(), really_changed.end(), [&](uint32_t t) {
          return std::binary_search(changed.begin(), changed.end(), t);
        }));
    log::info("  active tiles " + std::to_string(changed.size()) + ", changed (references) " +
              std::to_string(really_changed.size()) + ", both " +
              std::to_string(edit_report.active_and_changed_tiles));
    previous_reference = reference.image;
    for (const PlannedRun& planned : planned_runs(policies, focus)) {
      renderer.update_scene(before, undo);
      run_options.schedule.policy = planned.policy;
      run_options.schedule.display = display_of(planned.policy);
      run_options.focus = planned.focus;
      const bench::PolicyRun run =
          bench::run_policy(renderer, scene, changes, start, reference.image, changed, run_options);
      log_run(planned.name, run);
      edit_report.add_run(planned.name, run);
    }
    run_options.focus = {};
  }
  check_validation(ctx);
  report.write();
  return kExitOk;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Measure error against time and work after edits, for each re-render policy");
  cmd->add_option("scene", options->common.scene, "Scene file (.gltf or .glb)")->required();
  cmd->add_option("edits", options->edits, "Edit script (.json)")->required();
  cmd->add_option("-o,--output", options->output, "Output folder")->required();
  cmd->add_option("--policies", options->policies,
                  "Policies to compare: hipr, full, scanline, spiral, random, oracle")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--ref-spp", options->ref_spp, "Samples per pixel of the converged references")
      ->capture_default_str();
  cmd->add_option("--steps", options->steps,
                  "Scheduling steps per edit and policy (default: until converged)");
  add_schedule_flags(*cmd, options->schedule, {"policy"});
  add_denoise_flags(*cmd, options->denoise);
  add_display_flags(*cmd, options->display, "the PNGs (auto: metered on each edit's reference)");
  cmd->add_option("--ref-cache", options->ref_cache,
                  "Folder of cached references (default: beside the shader cache)");
  cmd->add_flag("--no-ref-cache", options->no_ref_cache,
                "Render references without reading or writing the cache");
  cmd->add_option(
      "--drag", options->drag,
      "Apply the edits as one drag, this much work apart in full-frame passes (as a viewer applies "
      "one per frame), measuring against the scene as it is at each step");
  cmd->add_flag("--cold-start", options->cold_start,
                "First measure the scene as loaded rendered from nothing (with the focus of the "
                "script's first "
                "focus ops, if any)");
  add_common_options(*cmd, options->common);
  return {cmd, [options] { return run_bench(*options); }};
}

}  // namespace hipr::app
