#pragma once
// What the viewer's UI shows and changes besides the scene (which lives in the Session):
// overlay, exposure, selection, the paths of the file panel, messages, and requests the panels
// hand to the main loop (opening, saving, screenshots, renderer settings).
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/viewer/gizmo.h"
#include "app/viewer/overlays.h"
#include "hipr/convergence.h"
#include "hipr/denoise.h"
#include "hipr/focus.h"
#include "hipr/renderer.h"
#include "hipr/schedule_settings.h"
#include "hipr/scheduler.h"
#include "image/tonemap.h"

namespace hipr::viewer {

struct Message {
  std::string text;
  bool error = false;
};

struct ViewerState {
  Overlay overlay = Overlay::None;
  float exposure_ev = 0.0f;
  // Metered while on (follow_metering); setting an exposure by hand turns it off (locks it).
  bool auto_exposure = false;
  ToneMapper tone_mapper = ToneMapper::Clamp;
  // The display denoised (N): on by default, at convergence too, where the filter leaves precise
  // pixels as they are (docs/method.md, "The denoised display").
  DenoiseSettings denoise{.enabled = true};
  bool show_ui = true;      // panels and status line (Tab)
  bool show_status = true;  // the status line alone
  int selected_node = -1;
  // The gizmo over the selection (W move, E rotate, R scale; Q world/local axes).
  GizmoMode gizmo_mode = GizmoMode::Translate;
  GizmoSpace gizmo_space = GizmoSpace::World;
  bool pick_focus = false;  // the next click on the image sets the camera's focus distance
  // Attention-guided rendering (docs/method.md#focus): HiPR starts from the selected object
  // (on by default) and, when asked, from a disc around the cursor.
  bool focus_selection = true;
  bool focus_cursor = false;
  float focus_radius = 32.0f;  // rendered pixels
  // Time spent on scheduling steps per frame; 0 adapts it: what a 60 fps frame leaves after the
  // frame's other work (UI, presentation), measured; on a device too slow for 60 fps, as long as
  // that other work, up to 30 ms (at least one step a frame, whatever it costs).
  double frame_budget_ms = 0.0;
  double adaptive_budget_ms =
      0.0;  // the budget the last frame used when adapting (shown in the panel)
  uint32_t steps_per_frame = 0;  // > 0: a fixed number of steps instead (scripts, tests)

  std::string open_path, save_path, screenshot_path;
  std::string import_path;  // the File panel's Import field
  std::string
      environment_file;  // the last environment file shown, offered in the Environment panel
  std::string environment_input;  // the Environment panel's file field
  bool request_open = false;
  bool request_save = false;
  bool request_screenshot = false;
  bool open_confirmed = false;                       // discard unsaved edits when opening
  std::optional<ScheduleSettings> request_schedule;  // the HiPR panel's scheduling settings
  std::optional<uint32_t> request_tile_size;
  std::optional<Sampler> request_sampler;
  std::optional<LightSelection> request_light_selection;
  std::optional<bool> request_guiding;
  // The Convergence panel's samples per pixel and targets (Session::set_convergence).
  std::optional<std::pair<uint32_t, ConvergenceTarget>> request_convergence;
  int tile_size_input = 16;
  std::string preset = "default";
  HiprParameters hipr_sliders;  // as the sliders hold them; normalised when applied

  // Materials listed under "Lights" as emitters: emissive once, listed for good (so setting
  // one's emission to 0 does not make it vanish from the panel).
  std::set<uint32_t> emitters;

  bool ui_group_open = false;  // a widget is being dragged: its edits form one undo step

  // Frame statistics for the status line.
  double fps = 0.0;
  uint32_t steps_last_frame = 0;
  double mean_spp = 0.0;

  std::vector<Message> messages;  // newest last; the panel shows the last few
  uint64_t message_count = 0;     // messages ever posted
  uint64_t messages_shown = 0;  // message_count when the panel last drew (it scrolls to a new one)
  void info(const std::string& text);
  void error(const std::string& text);  // also printed on stderr as a warning

  // The environment map last seen (file or built-in name, and size; not the sun) and the mean
  // radiance of the last one that was not black, for follow_environment.
  std::string environment_key;
  float environment_radiance = 0.0f;
};

// The view's focus this frame: the selected object's subtree and the disc around `cursor` (the
// rendered pixel under the mouse, none when it is off the image or over a panel), as the
// state's toggles ask.
Focus view_focus(const Scene& scene, const ViewerState& state, std::optional<glm::vec2> cursor);

// Called every frame: when another environment map lights the scene (a switch, its undo or
// redo, a script), the exposure moves by the change in the maps' mean radiance, so a switch
// between the studio (about 1 nit) and the daylight sky (thousands) stays viewable. Intensity
// and the sun are left to show as they are. With auto exposure on, the metering does that.
void follow_environment(const Scene& scene, ViewerState& state);

// With auto exposure on, takes the exposure metered from the displayed image
// (image/auto_exposure.h) when it differs by more than kMeteringDeadbandEv: the noise of a
// converging image does not make the picture pulse.
constexpr float kMeteringDeadbandEv = 0.1f;
void follow_metering(ViewerState& state, float metered_ev);

}  // namespace hipr::viewer
