#pragma once
// `hipr view`: the interactive viewer's main loop. Each frame: events and panels (edits go
// to the session), the scheduler's steps for a time budget (or a fixed count in scripts), the
// display pass + UI into the frame image, then the swapchain.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/display_flags.h"
#include "app/viewer/overlays.h"
#include "hipr/convergence.h"
#include "hipr/denoise.h"
#include "hipr/edits.h"
#include "hipr/schedule_settings.h"

namespace hipr::viewer {

struct ViewerOptions {
  app::CommonOptions common;  // validated; render size from --size or --width/--height
  std::vector<Edit> script;  // applied as if typed: edit k at frame script_start + k * script_every
  uint32_t script_every = 10;
  uint32_t script_start = 0;         // 0: script_every
  std::filesystem::path screenshot;  // written at exit
  uint32_t exit_after_frames = 0;    // 0: run until the window closes
  Overlay overlay = Overlay::None;
  ScheduleSettings
      schedule;  // tiles_per_step 0: 1/64 of the frame; first_visit_spp 0: default_first_visit_spp
  uint32_t steps_per_frame = 0;  // > 0: exactly this many steps per frame (reproducible scripts)
  double frame_budget_ms = 0.0;  // 0: adapt (ViewerState::frame_budget_ms)
  // What an artist expects of a viewer: metered exposure (until they set one) and Khronos PBR
  // Neutral, which shows glTF base colours as authored and rolls highlights off to white.
  app::DisplayFlags display{std::nullopt, ToneMapper::PbrNeutral};
  bool show_ui = true;
  DenoiseSettings denoise{.enabled = true};  // the window shows the display denoised (N)
  // What may pause rendering before --spp (hipr/convergence.h); the view command sets its own
  // defaults.
  ConvergenceTarget converge;
  // No window (machines without a display): frames are drawn off screen, as fast as the device
  // renders them, until exit_after_frames (which headless runs need).
  bool headless = false;
  std::filesystem::path stats_json;  // fps and per-edit latency, written at exit
  // Every presented frame's displayed image (linear EXR) and, at exit, frames.json (per frame:
  // how many script edits it shows, and its time without the read-back), for measuring what the
  // screen showed frame by frame.
  std::filesystem::path frames_dir;
  std::filesystem::path save;   // the edited scene, saved as glTF at exit
  int select = -1;              // node selected at start (-1: none)
  bool focus_selection = true;  // hipr starts from the selected object (docs/method.md#focus)
};

// Runs the viewer on a loaded scene until the window closes or the frame count is reached.
int run_viewer(const ViewerOptions& options, Scene scene);

}  // namespace hipr::viewer
