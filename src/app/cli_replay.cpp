// `hipr replay SCENE EDITS.json -o OUTDIR --policy P [--dump-steps 1,2,4] [--steps K]`:
// converges the scene, then applies each edit and runs the policy's scheduling steps,
// writing the displayed image after chosen steps, the final image and debug images. Focus ops
// set the focus (docs/method.md#focus) the edits after them are planned with.
#include <nlohmann/json.hpp>

#include <set>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/denoise_flags.h"
#include "app/display_flags.h"
#include "app/schedule_flags.h"
#include "core/error.h"
#include "core/file_util.h"
#include "core/log.h"
#include "core/memory_usage.h"
#include "core/timer.h"
#include "hipr/edit_pipeline.h"
#include "hipr/scene_writer.h"
#include "hipr/scheduler.h"
#include "image/debug_images.h"
#include "image/image_io.h"
#include "render/render_readback.h"
#include "vk/buffer.h"

namespace hipr::app {
namespace {

double mean_seconds(double seconds, uint32_t count) { return count ? seconds / count : 0.0; }

// A step of either kind, without the image writing between steps.
double mean_step_seconds(const Scheduler::EditTimes& t) {
  return mean_seconds(t.leading_step_seconds + t.step_seconds, t.leading_steps + t.steps);
}

nlohmann::json edit_times_json(const Scheduler::EditTimes& t) {
  return {{"capture_seconds", t.capture_seconds},
          {"scene_update_seconds", t.scene_seconds},
          {"scene_update_allocations", t.scene_allocations},
          {"scene_update_submissions", t.scene_submissions},
          {"plan_seconds", t.plan_seconds},
          {"sort_seconds", t.sort_seconds},
          {"leading_steps", t.leading_steps},
          {"mean_leading_step_seconds", mean_seconds(t.leading_step_seconds, t.leading_steps)},
          {"steps", t.steps},
          {"mean_step_seconds", mean_seconds(t.step_seconds, t.steps)},
          {"focus_seconds", t.focus_seconds}};
}

namespace fs = std::filesystem;

struct ReplayOptions {
  CommonOptions common;
  fs::path edits;
  fs::path output;
  std::vector<uint32_t> dump_steps;
  uint32_t steps = 0;         // per edit; 0 = until every pixel has --spp samples again
  ScheduleSettings schedule;  // tiles_per_step 0: default_tiles_per_step
  fs::path save;              // empty: the edited scene is not saved
  DisplayFlags display;       // the PNGs' (auto: metered once, on the scene as loaded)
  DenoiseSettings denoise;    // enabled: every image written is written denoised too (_denoised)
};

std::string step_name(size_t edit, uint32_t step) {
  return "edit" + std::to_string(edit + 1) + "_step" + std::to_string(step);
}

void write_pair(const fs::path& dir, const std::string& stem, const ImageRGB& image,
                const DisplayTransform& display) {
  write_image(dir / (stem + ".exr"), image);
  write_image(dir / (stem + ".png"), image, {}, display);
}

// The display as `stem`, and with --denoise its denoised copy as `stem`_denoised: a still of
// each (the steps written are not a view's frames: no history of them is kept).
void write_shown(const ReplayOptions& o, const std::string& stem, Renderer& renderer,
                 const DisplayTransform& display) {
  write_pair(o.output, stem, renderer.displayed_image(), display);
  if (o.denoise.enabled)
    write_pair(o.output, stem + "_denoised", renderer.denoised_image(without_history(o.denoise)),
               display);
}

void write_debug_images(const fs::path& dir, size_t edit, const Renderer& renderer) {
  const RenderSettings& s = renderer.settings();
  const std::string stem = "edit" + std::to_string(edit + 1);
  write_image(dir / (stem + "_objects.png"),
              object_id_image(renderer.gbuffer_instances(), s.width, s.height));
  const auto flags = read_tile_flags(renderer);
  write_image(dir / (stem + "_weights.png"),
              tile_weight_image(read_tile_weights(renderer), flags, renderer.tiles_x(), s.tile_size,
                                s.width, s.height));
  write_image(dir / (stem + "_tiles.png"),
              tile_mask_image(flags, renderer.tiles_x(), s.tile_size, s.width, s.height));
}

int run_replay(ReplayOptions& o) {
  validate_common_options(o.common);
  log::set_quiet(o.common.quiet);
  const ScheduleSettings& schedule = o.schedule;
  const Policy policy = schedule.policy;
  if (policy == Policy::Oracle)
    throw InputError("the oracle policy needs a reference image: use hipr bench");
  if (schedule.visit_spp < 1 || schedule.visit_spp > o.common.spp)
    throw InputError("--visit-spp must be between 1 and --spp");
  if (schedule.first_visit_spp > o.common.spp)
    throw InputError("--first-visit-spp must be between 1 and --spp");
  Scene scene = load_scene(o.common.scene, o.common.load);
  const std::vector<Edit> edits = load_edit_script(o.edits);
  // Check every name before rendering or writing anything: a typo in edit 5 must not cost
  // four renders and leave a half-filled folder.
  Scene probe = scene;
  for (const Edit& edit : edits) apply_edit(probe, edit);
  std::error_code ec;
  const bool had_output = fs::exists(o.output, ec);
  fs::create_directories(o.output, ec);
  if (!fs::is_directory(o.output))
    throw InputError("cannot create output folder " + o.output.string());
  // The edited scene is the same before the renders as after them: saved first (the output
  // folder may hold it), a problem with it (an unwritable path, what the writer cannot hold)
  // costs no render and leaves no folder behind.
  if (!o.save.empty()) {
    try {
      save_scene(probe, o.save);
    } catch (const InputError&) {
      if (!had_output) fs::remove(o.output, ec);
      throw;
    }
  }
  probe = Scene();

  const vk::Context ctx(context_options(o.common));
  Renderer renderer(ctx, scene, o.common.render);
  const uint32_t tiles = renderer.tile_count();
  const uint32_t per_step =
      schedule.tiles_per_step ? schedule.tiles_per_step : default_tiles_per_step(tiles);
  Scheduler scheduler(renderer, policy, per_step, schedule.visit_spp);
  scheduler.configure(schedule, o.common.spp);
  // Converge the scene as loaded; the last 1-spp pass is timed: the unit of the overhead share.
  for (uint32_t done = 0; done + 1 < o.common.spp; done += 16)
    renderer.add_samples_full_frame(std::min(16u, o.common.spp - 1 - done));
  const Timer pass_timer;
  renderer.add_samples_full_frame(1);
  const double pass_seconds = pass_timer.seconds();
  // One exposure for every picture of the run: a sequence that does not flicker.
  const DisplayTransform display =
      o.display.exposure_ev ? DisplayTransform{*o.display.exposure_ev, o.display.tone_mapper}
                            : display_transform(o.display, renderer.image());

  // Without --steps: until every pixel has --spp samples again (work counts samples since the
  // edit). The bound only guards against a schedule that would never get there.
  const uint32_t rounds = (o.common.spp + schedule.visit_spp - 1) / schedule.visit_spp;
  const uint32_t max_steps =
      o.steps ? o.steps : 2 * (rounds + 1) * ((tiles + per_step - 1) / per_step) + 2;
  const std::set<uint32_t> dumps(o.dump_steps.begin(), o.dump_steps.end());
  nlohmann::json summary = {{"scene", o.common.scene.string()},
                            {"policy", policy_name(policy)},
                            {"display", display_rule_name(scheduler.display_rule())},
                            {"full_frame_pass_seconds", pass_seconds},
                            {"edits", nlohmann::json::array()}};
  uint64_t non_finite = 0;  // the counters restart at every edit
  EditPipeline pipeline(scene, scheduler);
  for (size_t e = 0; e < edits.size(); ++e) {
    non_finite += renderer.counters().non_finite_samples;
    if (is_focus(edits[e])) {  // no change of the scene: the focus later edits start from
      pipeline.apply(edits[e]);
      const std::string focus = describe(scene, pipeline.focus());
      summary["edits"].push_back({{"edit", describe(edits[e])}, {"focus", focus}, {"steps", 0}});
      log::info("edit " + std::to_string(e + 1) + " (" + describe(edits[e]) + "): the focus is " +
                focus);
      continue;
    }
    const Timer timer;
    // An edit that changes nothing (a move by zero) re-renders nothing.
    const bool changed = !pipeline.apply(edits[e]).empty();
    double work_after_first_step = 0.0;
    double first_step_seconds = 0.0;  // the edit until its first step is on the display
    bool debug_written = policy != Policy::Hipr || !changed;
    uint32_t steps = 0;
    for (uint32_t s = 1;
         s <= max_steps && (o.steps || scheduler.work_since_edit() < double(o.common.spp)); ++s) {
      steps = s;
      scheduler.step();
      if (s == 1) {
        work_after_first_step = scheduler.work_since_edit();
        first_step_seconds = timer.seconds();
      }
      if (!debug_written && !scheduler.leading_steps_pending()) {  // stage 2's weights are all in
        write_debug_images(o.output, e, renderer);
        debug_written = true;
      }
      if (dumps.count(s)) write_shown(o, step_name(e, s), renderer, display);
    }
    summary["edits"].push_back(
        {{"edit", describe(edits[e])},
         {"steps", steps},
         {"work", scheduler.work_since_edit()},
         {"seconds", timer.seconds()},
         {"first_step_seconds", first_step_seconds},
         {"mean_step_seconds", mean_step_seconds(scheduler.edit_times())},
         {"work_after_first_step", work_after_first_step},
         {"overhead_seconds", scheduler.overhead_seconds()},
         {"parts", edit_times_json(scheduler.edit_times())},
         {"overhead_share_of_full_pass", scheduler.overhead_seconds() / pass_seconds},
         {"blas_builds", renderer.scene_stats().blas_builds},
         {"blas_build_seconds", renderer.scene_stats().blas_build_seconds},
         {"device_bytes", vk::device_bytes_in_use()},
         {"resident_bytes", resident_bytes()}});
    log::info("edit " + std::to_string(e + 1) + " (" + describe(edits[e]) +
              "): " + std::to_string(steps) + " steps, " + std::to_string(timer.seconds()) + " s");
  }
  check_validation(ctx);
  write_shown(o, "final", renderer, display);
  write_text_atomically(o.output / "summary.json", summary.dump(2) + "\n");
  non_finite += renderer.counters().non_finite_samples;
  if (non_finite) log::warn(std::to_string(non_finite) + " non-finite samples were dropped");
  return kExitOk;
}

}  // namespace

Command add_replay_command(CLI::App& app) {
  auto options = std::make_shared<ReplayOptions>();
  CLI::App* cmd =
      app.add_subcommand("replay", "Apply an edit script and re-render with a scheduling policy");
  cmd->add_option("scene", options->common.scene, "Scene file (.gltf or .glb)")->required();
  cmd->add_option("edits", options->edits, "Edit script (.json)")->required();
  cmd->add_option("-o,--output", options->output, "Output folder")->required();
  cmd->add_option("--dump-steps", options->dump_steps,
                  "Steps after which to write the displayed image")
      ->delimiter(',');
  cmd->add_option("--steps", options->steps,
                  "Scheduling steps per edit (default: until converged)");
  add_schedule_flags(*cmd, options->schedule);
  add_display_flags(*cmd, options->display, "the PNGs (auto: metered on the scene as loaded)");
  add_denoise_flags(*cmd, options->denoise);
  cmd->add_option("--save", options->save,
                  "Also write the edited scene (after every edit) as glTF (.gltf or .glb); written "
                  "before rendering");
  add_common_options(*cmd, options->common);
  return {cmd, [options] { return run_replay(*options); }};
}

}  // namespace hipr::app
