// `hipr view SCENE [--script EDITS.json] [--screenshot FILE] [--exit-after-frames N] [--size WxH]`:
// the interactive viewer. Every flag, the scene and the script are checked before a window
// opens, so bad input is one line and exit code 2 even without a display.
#include <regex>

#include "app/commands.h"
#include "app/denoise_flags.h"
#include "app/display_flags.h"
#include "app/schedule_flags.h"
#include "app/viewer/screenshot.h"
#include "app/viewer/viewer.h"
#include "core/error.h"
#include "core/log.h"
#include "hipr/scene_loader.h"

namespace hipr::app {
namespace {
namespace fs = std::filesystem;

struct ViewCommandOptions {
  viewer::ViewerOptions viewer;
  std::string size;
  fs::path script;
  std::string overlay = "none";
  std::string select;
  bool no_ui = false;
};

void apply_size(const std::string& size, RenderSettings& render) {
  if (size.empty()) return;
  std::smatch match;
  static const std::regex pattern("([0-9]{1,5})x([0-9]{1,5})");
  if (!std::regex_match(size, match, pattern))
    throw InputError("--size must be WxH, e.g. 512x512 (got '" + size + "')");
  render.width = uint32_t(std::stoul(match[1]));
  render.height = uint32_t(std::stoul(match[2]));
}

// The viewer's convergence: a GPU renders 64 samples per pixel of most scenes in well under a
// second, so --spp is only the limit (kViewerSpp) and a noise target pauses rendering when the
// image is clean (kViewerRelmse: about 3 % RMS relative error per channel; the samples it takes
// per scene are in BENCHMARKS.md, "Viewer convergence"; whether it is where noise stops being
// visible to artists is not measured). It is the level below which the raw image is closer to
// the truth than the denoised one, so by default the window ends on the raw image.
constexpr uint32_t kViewerSpp = 4096;
constexpr double kViewerRelmse = kRawIsCleanerRelmse;

void add_convergence_flags(CLI::App& cmd, ConvergenceTarget& target) {
  target.relmse = kViewerRelmse;
  struct FlagBinder {
    CLI::App& cmd;
    void operator()(const ConvergenceSettingInfo& info, double& value) const {
      cmd.add_option(info.flag, value, info.help)
          ->capture_default_str()
          ->check(CLI::Range(info.min, info.max));
    }
    void operator()(const ConvergenceSettingInfo& info, bool& value) const {
      cmd.add_flag(info.flag, value, info.help);
    }
  };
  for_each_convergence_setting(target, FlagBinder{cmd});
}

int run_view(ViewCommandOptions& o) {
  viewer::ViewerOptions& v = o.viewer;
  apply_size(o.size, v.common.render);
  validate_common_options(v.common);
  log::set_quiet(v.common.quiet);
  v.overlay = viewer::parse_overlay(o.overlay);
  const ScheduleSettings& schedule = v.schedule;
  if (schedule.policy == Policy::Oracle)
    throw InputError("the oracle policy needs a reference image: use hipr bench");
  if (schedule.first_visit_spp != 0 &&
      (schedule.first_visit_spp < schedule.visit_spp || schedule.first_visit_spp > v.common.spp))
    throw InputError("--first-visit-spp must be between --visit-spp and --spp");
  v.show_ui = !o.no_ui;
  if (v.script_every < 1) throw InputError("--script-every must be at least 1");
  if (v.headless && v.exit_after_frames == 0)
    throw InputError("--headless needs --exit-after-frames (there is no window to close)");
  if (schedule.visit_spp < 1 || schedule.visit_spp > v.common.spp)
    throw InputError("--visit-spp must be between 1 and --spp");
  if (!(v.frame_budget_ms >= 0.0) || v.frame_budget_ms > 10000.0)
    throw InputError("--frame-budget-ms must be between 0 (adapt) and 10000");
  if (!v.screenshot.empty()) viewer::check_screenshot_path(v.screenshot);
  if (!v.save.empty()) {
    const std::string ext = v.save.extension().string();
    if (ext != ".gltf" && ext != ".glb")
      throw InputError("--save must name a .gltf or .glb file: " + v.save.string());
    const fs::path dir = v.save.has_parent_path() ? v.save.parent_path() : fs::path(".");
    if (!fs::is_directory(dir)) throw InputError("--save folder does not exist: " + dir.string());
  }
  if (!v.frames_dir.empty() && !fs::is_directory(v.frames_dir))
    throw InputError("--frames-dir is not a folder: " + v.frames_dir.string());
  if (!v.stats_json.empty()) {
    const fs::path dir =
        v.stats_json.has_parent_path() ? v.stats_json.parent_path() : fs::path(".");
    if (!fs::is_directory(dir))
      throw InputError("--stats-json folder does not exist: " + dir.string());
  }
  Scene scene = load_scene(v.common.scene, v.common.load);
  if (!o.select.empty()) {
    try {
      v.select = int(find_node(scene, o.select));
    } catch (const InputError& e) {
      throw InputError(std::string("--select: ") + e.what());
    }
  }
  if (!o.script.empty()) {
    v.script = load_edit_script(o.script);
    // Every name in the script must resolve before the window opens.
    Scene probe = scene;
    for (const Edit& edit : v.script) apply_edit(probe, edit);
  }
  return viewer::run_viewer(v, std::move(scene));
}

}  // namespace

Command add_view_command(CLI::App& app) {
  auto options = std::make_shared<ViewCommandOptions>();
  viewer::ViewerOptions& v = options->viewer;
  CLI::App* cmd =
      app.add_subcommand("view", "Open a scene in the interactive viewer (edit, pick, undo, save)");
  cmd->add_option("scene", v.common.scene, "Scene file (.gltf or .glb)")->required();
  cmd->add_option("--script", options->script,
                  "Edit script (.json) applied as if typed, one edit every --script-every frames");
  cmd->add_option(
         "--script-every", v.script_every,
         "Frames between script edits (edit k at frame (k+1) x N, or --script-start + k x N)")
      ->capture_default_str();
  cmd->add_option(
      "--script-start", v.script_start,
      "Frame of the first script edit (default: --script-every), e.g. after the scene converged");
  cmd->add_option("--screenshot", v.screenshot,
                  "At exit, write what the window shows (.png) or the displayed radiance (.exr)");
  cmd->add_option("--exit-after-frames", v.exit_after_frames,
                  "Close after N frames (0: when the window closes)");
  cmd->add_option("--size", options->size, "Rendered image size WxH (overrides --width/--height)");
  cmd->add_option("--overlay", options->overlay, "Initial overlay: none, ids, weights, owed")
      ->capture_default_str();
  add_schedule_flags(*cmd, v.schedule);
  cmd->add_option(
         "--frame-budget-ms", v.frame_budget_ms,
         "Time spent on scheduling steps per frame; 0 adapts it to the device, aiming at 60 fps "
         "(at least one step a frame)")
      ->capture_default_str();
  cmd->add_option("--steps-per-frame", v.steps_per_frame,
                  "Exactly N scheduling steps per frame instead of a time budget");
  add_display_flags(*cmd, v.display, "the window (auto: metered as it converges, until set)");
  add_denoise_flags(*cmd, v.denoise);
  add_convergence_flags(*cmd, v.converge);
  cmd->add_flag("--no-ui", options->no_ui,
                "No panels or status line: the window shows the render alone");
  cmd->add_flag(
      "--headless", v.headless,
      "No window: frames are drawn off screen as fast as the device allows (GPU servers, CI); "
      "needs --exit-after-frames");
  cmd->add_option("--stats-json", v.stats_json,
                  "At exit, write fps and per-edit feedback latency (JSON)");
  cmd->add_option(
      "--frames-dir", v.frames_dir,
      "Write every frame's displayed image to this folder (frame_NNNNN.exr, and frames.json: "
      "the script edits each shows and its time without the read-back)");
  cmd->add_option("--save", v.save, "At exit, save the edited scene as glTF (.gltf or .glb)");
  cmd->add_option("--select", options->select, "Node selected at start (glTF name or #index)");
  cmd->add_flag_function(
      "--no-focus", [&v](int64_t) { v.focus_selection = false; },
      "hipr does not start from the selected object (the HiPR panel's \"focus: selection\")");
  v.common.spp = kViewerSpp;
  add_common_options(*cmd, v.common);
  return {cmd, [options] { return run_view(*options); }};
}

}  // namespace hipr::app
