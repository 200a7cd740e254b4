#pragma once
// One scene being edited: the scene model, its renderer and scheduler, the undo history, and
// what the window should show. No window here, so tests drive it headless. Every change to
// the scene (an edit, an undo, a redo) goes through the same path: diff against the scene
// before, Scheduler::on_edit, so HiPR re-renders first what the change touched.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/viewer/edit_history.h"
#include "core/timer.h"
#include "hipr/convergence.h"
#include "hipr/focus.h"
#include "hipr/renderer.h"
#include "hipr/schedule_settings.h"
#include "hipr/scheduler.h"
#include "render/viewer_sources.h"
#include "vk/context.h"

namespace hipr::viewer {

struct SessionSettings {
  RenderSettings render;
  // tiles_per_step 0: 1/64 of the frame, so a frame's time budget is spent finely;
  // first_visit_spp 0: default_first_visit_spp.
  ScheduleSettings schedule;
  uint32_t spp = 64;  // samples per pixel to converge to; rendering pauses there at the latest
  ConvergenceTarget converge;  // what may pause it earlier
};

// How one change reached the screen: the feedback latency of the measurements.
struct EditRecord {
  std::string what;
  double latency_seconds = -1.0;       // edit -> first frame presented after a step; -1: none yet
  double work_at_first_change = 0.0;   // in full-frame 1-spp passes
  uint32_t steps_at_first_change = 0;  // scheduling steps rendered before that frame
};

class Session {
 public:
  // Takes the scene as loaded. A scene without a camera gets its default camera as a node
  // first: otherwise moving an object would move the framing camera and restart everything.
  Session(const vk::Context& ctx, Scene scene, const SessionSettings& settings);

  const Scene& scene() const { return m_scene; }
  // scene().bounds(), kept until the next change: the panels and gestures ask every frame, and
  // Scene::bounds() walks every vertex (a million in the big scenes).
  std::pair<glm::vec3, glm::vec3> bounds() const;
  // Half the bounds' diagonal (at least 1e-6): the scale of drags and key steps.
  float radius() const;
  const SessionSettings& settings() const { return m_settings; }
  const Renderer& renderer() const { return *m_renderer; }
  // Changes whenever the renderer is replaced (a new session's too): its display buffer is another.
  uint64_t renderer_id() const { return m_renderer_id; }
  const Scheduler& scheduler() const { return *m_scheduler; }
  const EditHistory& history() const { return m_history; }

  // Applies and records an edit and starts its re-render. Throws InputError (nothing changed)
  // for an edit the scene refuses. A focus op (a script's) changes the focus, not the scene:
  // it is not recorded for undo.
  void edit(const Edit& edit);

  // Where the user looks (docs/method.md#focus), as the viewer sees it: the selected object,
  // the cursor. The scheduler follows these seeds together with those of a script's focus ops;
  // a new focus re-plans at once and restarts nothing.
  void set_view_focus(const Focus& focus);
  const Focus& focus() const { return m_scheduler->focus(); }
  // Edits between these form one undo step (a drag).
  void begin_group() { m_history.begin_group(); }
  void end_group() { m_history.end_group(); }
  bool undo();
  bool redo();
  void mark_saved() { m_history.mark_saved(); }

  // Runs scheduling steps while another one still fits in `budget_seconds` (judged by the last
  // step's time; at least one step runs) or until the image has converged; returns how many ran.
  uint32_t render(double budget_seconds, uint32_t max_steps = UINT32_MAX);
  // The image is done and rendering pauses: `spp` samples per pixel since the last change, or,
  // once every pixel shows the scene as it is now, the time or noise target (hipr/convergence.h).
  bool converged() const;
  // The last noise estimate of a noise target (none before the first, nor without a target).
  // Estimated where the work since the change is about to meet the target by the last estimate
  // (relMSE falls as 1/samples), so a change costs a few read-backs, not one a frame.
  const std::optional<FilmNoise>& noise() const { return m_noise; }
  // The samples to converge to and the targets that may pause rendering earlier; takes over at
  // once (a paused image resumes when a stricter target is set). spp is raised to the schedule's
  // visit counts where it is below them.
  void set_convergence(uint32_t spp, const ConvergenceTarget& target);
  double work_since_edit() const { return m_scheduler->work_since_edit(); }
  double seconds_since_edit() const { return m_since_edit.seconds(); }
  // Samples per second since the last edit (0 before any sample).
  double samples_per_second() const;

  // What the scheduler says is displayed, read back from the device (only when something ran
  // since the last call): screenshots and tests. The viewer's frames show the renderer's display
  // buffer directly (display_texels, render/viewer_sources.h).
  const ImageRGB& displayed();
  // Whether the window shows the denoised copy: `denoise` is enabled, and the image is not clean
  // yet (the noise target met with an estimate of at most kRawIsCleanerRelmse) or the target
  // keeps it denoised (ConvergenceTarget::keep_denoised).
  bool shows_denoised(const DenoiseSettings& denoise) const;
  // What the window shows: displayed(), or its denoised copy (shows_denoised).
  ImageRGB shown(const DenoiseSettings& denoise);
  // The denoiser's settings for the frame shown now: while the image converges each frame keeps
  // part of the last (DenoiseSettings::history: steady, not shimmering); once rendering has
  // paused, none: the last frame is the filter of the final samples alone, what
  // `hipr render --denoise` writes of them.
  DenoiseSettings frame_denoise(const DenoiseSettings& denoise) const;
  // Increments whenever the display may have changed (steps, edits, a new renderer).
  uint64_t display_version() const { return m_display_version; }
  // The last edit is on the display already and no frame has shown it yet: a light edit relit
  // the converged image at once (docs/method.md#relighting). The viewer presents that frame
  // before rendering steps, which would only delay it.
  bool edit_shown_unpresented() const;
  // The last edit awaits the step that shows it: the frame that renders that step should be
  // presented at once, not filled with more steps that only delay the change on screen.
  bool edit_awaits_first_step() const { return m_awaiting_change && m_steps_since_edit == 0; }
  // Call after a frame was presented: completes the latency of the last change when this frame
  // is the first to show it (the first after a step since the edit, or after a relit edit).
  void on_presented();
  const std::vector<EditRecord>& edit_records() const { return m_records; }

  // Makes an overlay on the device into `output` (Renderer::render_overlay), the G-buffer
  // brought up to date first where ids or an outline need it.
  void render_overlay(DebugOverlay overlay, uint32_t selected_node, const vk::Buffer& output);
  // The exposure in stops for what the display shows, metered on the device
  // (hipr::metered_display_exposure: 4 KB read back) once per display version: an idle viewer
  // meters nothing.
  float metered_exposure();
  // The denoiser's result and its recording into a frame (hipr::denoised_display,
  // hipr::record_denoise), with frame_denoise's settings.
  const vk::Buffer& denoised_display();
  void record_denoise(VkCommandBuffer cmd, const DenoiseSettings& settings);
  // The G-buffer of the scene as it is now: instance per pixel, and one pixel's hit.
  const std::vector<uint32_t>& instance_ids();
  Renderer::PixelHit pick(uint32_t x, uint32_t y);

  // Viewer settings, not edits (no undo). A new policy, step budget or visit count takes over at
  // once with a new scheduler (it starts from the samples there are; the image is not
  // restarted); the others apply to the scheduler there is (the focus lead at once, relight,
  // reprojection and the edit lead from the next edit). Throws InputError for the oracle (it
  // needs a reference). A new tile size rebuilds the renderer (the image restarts); HiPR
  // weights apply from the next stage 2.
  void set_schedule(const ScheduleSettings& schedule);
  void set_tile_size(uint32_t tile_size);
  void set_sampler(Sampler sampler);                   // rebuilds the renderer: the image restarts
  void set_light_selection(LightSelection selection);  // the same
  void set_guiding(bool guiding);                      // the same
  void set_hipr_parameters(const HiprParameters& parameters);

 private:
  void rebuild();
  // Takes `settings` and rebuilds; on failure the session keeps its old settings and renderer.
  void rebuild_with(const SessionSettings& settings);
  // The G-buffer of the scene as it is now (policies without stage 1 leave it behind edits).
  void ensure_gbuffer();
  std::unique_ptr<Scheduler> make_scheduler(Renderer& renderer) const;
  // The schedule settings with the viewer's defaults filled in (first_visit_spp).
  ScheduleSettings resolved_schedule() const;
  // Changes the scene through the edit pipeline and records the change as `what`.
  void changed(const std::function<void(Scene&)>& change, const std::string& what);
  // Hands the scheduler the script's and the view's seeds when they differ from what it follows.
  void update_focus();
  void display_changed() { ++m_display_version; }
  // The time and noise targets pause only between rounds, once a whole round has run since the
  // last change: every pixel shows the scene as it is now, no tile is left a visit behind.
  bool may_pause_early() const;
  // The noise target's estimates start over (a change, a new scheduler, a new target).
  void restart_noise_checks();
  // Estimates the noise when a noise target is set and the work has reached the next check.
  void check_noise();

  const vk::Context& m_ctx;
  SessionSettings m_settings;
  Scene m_scene;
  EditHistory m_history;
  std::unique_ptr<Renderer> m_renderer;
  uint64_t m_renderer_id = 0;
  std::unique_ptr<Scheduler> m_scheduler;
  Timer m_since_edit;
  std::optional<FilmNoise> m_noise;
  bool m_noise_met = false;
  double m_next_noise_check = 2.0;  // in work since the last change
  uint64_t m_display_version = 0;
  uint64_t m_displayed_version = UINT64_MAX;  // the version m_displayed was read at
  struct Metering {
    uint64_t renderer = 0, version = UINT64_MAX;  // what the exposure was metered at
    float ev = 0.0f;
  } m_metering;
  ImageRGB m_displayed;
  bool m_awaiting_change = false;  // the last change has not been presented yet
  uint32_t m_steps_since_edit = 0;
  std::vector<EditRecord> m_records;
  bool m_ids_stale = true;
  bool m_gbuffer_stale = false;  // edits since stage 1 last ran (policies without stage 1)
  std::vector<uint32_t> m_ids;
  mutable std::optional<std::pair<glm::vec3, glm::vec3>> m_bounds;  // cache of bounds()
  Focus m_script_focus, m_view_focus;
};

// The viewer's tiles per step unless set: 1/64 of the frame, at least one tile (smaller steps
// than hipr replay's and bench's: several fit in one frame's time budget).
uint32_t viewer_tiles_per_step(uint32_t tile_count);

// Samples of a tile's first visit after an edit unless set: 2 (as hipr bench), at least
// visit_spp, at most spp. The blend and switch display rules need two samples per pixel to
// judge a fresh estimate, so one sample would keep an edit off the screen for a whole pass.
uint32_t default_first_visit_spp(const SessionSettings& settings);

}  // namespace hipr::viewer
