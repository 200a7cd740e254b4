#pragma once
// Re-render scheduling after edits. A step renders a budget of tiles in the order a policy
// (scheduling_policy.h) plans. What the screen shows is the renderer's display: tiles keep
// their previous radiance until the display rule lets their fresh estimate take over (`full`
// shows nothing new until a whole pass is done).
#include <cstdint>
#include <memory>
#include <optional>

#include "hipr/display_rule.h"
#include "hipr/image.h"
#include "hipr/progressive_renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/schedule_settings.h"
#include "hipr/scheduling_policy.h"

namespace hipr {

class Scheduler {
 public:
  // `tiles_per_step`: the budget of one step; `visit_spp`: samples a tile gets per visit.
  // The display starts as the renderer's current accumulation.
  Scheduler(ProgressiveRenderer& renderer, std::unique_ptr<SchedulingPolicy> policy,
            uint32_t tiles_per_step, uint32_t visit_spp = 1);
  Scheduler(ProgressiveRenderer& renderer, Policy policy, uint32_t tiles_per_step,
            uint32_t visit_spp = 1)
      : Scheduler(renderer, make_policy(policy), tiles_per_step, visit_spp) {}

  // Every setting but the policy, the step budget and the visit's samples (the constructor's)
  // at once; `converged_spp` as set_converged_spp. What every command, the viewer and the bench
  // call, so none of them leaves a setting out.
  void configure(const ScheduleSettings& settings, uint32_t converged_spp);
  void set_display_rule(DisplayRule rule) { m_display = rule; }
  // Samples a tile gets on its first visit after an edit (HiPR's stage 2 included); later visits
  // get `visit_spp`. More samples up front make a re-rendered tile worth showing sooner (its
  // fresh estimate must beat the converged stale one). Whole-pass policies ignore it.
  void set_first_visit_spp(uint32_t spp) { m_first_visit_spp = spp < 1 ? 1 : spp; }
  DisplayRule display_rule() const { return m_display; }
  // Relighting by linearity at edits that only scale emitters (policies that relight: hipr).
  // On by default; off for comparison (the estimator's ablation).
  void set_relight(bool relight) { m_relight = relight; }
  // Reprojecting the display at camera edits (HiPR's stage 1, docs/method.md#camera-moves). On
  // by default; off for comparison.
  void set_reproject(bool reproject) { m_reproject = reproject; }
  // Whether the last edit was relit (its stale estimate is the relit converged image).
  bool relit() const { return m_relit; }

  // The scene changed (already edited in `scene`): update the renderer and plan a new
  // schedule. Tiles still owed to earlier edits stay owed: every pixel restarts at its next visit.
  void on_edit(const Scene& scene, const ChangeSet& changes);
  // Renders one step. Before any edit, steps are ordinary full-frame progressive passes.
  void step();

  // What the user looks at (docs/method.md#focus): from now on, and at every later edit after
  // the edit's own changes, HiPR starts from where the focus is seen and spreads outward. A new
  // focus re-plans at once without restarting any pixel: the round under way is completed in
  // the new order (tiles it already visited get nothing more in it), then rounds follow that
  // order; with a converged count, the focus's tiles also run ahead (set_converged_spp). An
  // empty focus clears it. Policies other than hipr keep their order.
  void set_focus(const Focus& focus);
  // The same focus renumbered by an edit that added or removed instances (follow_instances),
  // for the plan the next on_edit makes: stored, nothing planned now.
  void renumber_focus(const Focus& focus) { m_focus = focus; }
  const Focus& focus() const { return m_focus; }
  // The samples per pixel the render converges to (where its user stops stepping: the work
  // since the edit reaches it exactly when every pixel has it); 0, the default: unknown. Known,
  // the focus's tiles run `focus_lead` visits ahead of the round, never past it: the focus
  // converges first, and no pixel ever ends with more samples than the others.
  void set_converged_spp(uint32_t spp);
  void set_focus_lead(uint32_t visits);
  uint32_t focus_lead() const { return m_focus_lead; }
  // After an edit, the pixels stage 1 saw change most (those that show a moved, shown, hidden or
  // deformed object, or a surface they no longer see: their fresh estimate is on screen from its
  // first samples, with nothing to steady it) get `visits` more visits once the edit's tiles had
  // their first, before the rest of the round (docs/method.md#the-edits-lead). Needs the converged
  // count (set_converged_spp), which they never pass; 0: off. Policies other than hipr ignore it.
  void set_edit_lead(uint32_t visits) { m_edit_lead = visits; }
  // Where the rounds stand (what the policy's own steps are planned from).
  RoundState round_state() const;
  uint32_t edit_lead() const { return m_edit_lead; }

  ImageRGB displayed_image() const { return m_renderer.displayed_image(); }
  // Samples rendered since the last edit, in full-frame 1-spp passes (the work unit of
  // docs/method.md, "Measuring run time against error"). The counters restart at each edit.
  double work_since_edit() const;
  // Rounds over the whole schedule completed since the last edit (since this scheduler started,
  // before any): from one on, every tile has been visited, so every pixel shows the scene as it
  // is now (the noise and time targets of the viewer wait for that).
  uint32_t rounds_since_edit() const { return m_rounds_since_edit; }
  // The last step ended a round: every tile has had the round's visit, so a render paused here
  // leaves no tile a visit behind the others.
  bool at_round_end() const { return m_at_round_end; }
  // Seconds spent since the last edit in scheduling rather than path tracing: the policy's
  // planning (stage 1, sorting, the oracle's ranking) and capturing the stale display. (The
  // display pass that follows each step's rendering in the same submission counts as
  // rendering, as any viewer's tone mapping.)
  double overhead_seconds() const {
    return m_times.capture_seconds + m_times.plan_seconds + m_times.sort_seconds +
           m_times.focus_seconds;
  }
  // Where the time since the last edit went, part by part (wall time of each part's submissions,
  // which wait for the device: on a GPU, its time plus a submission's overhead).
  struct EditTimes {
    double capture_seconds = 0.0;    // the stale display captured (and relit) at the edit
    double scene_seconds = 0.0;      // the scene's device copy updated (materials, transforms, BVH)
    uint32_t scene_allocations = 0;  // device memory allocations the scene update made
    uint32_t scene_submissions = 0;  // and the queue submissions it waited for
    double plan_seconds =
        0.0;  // the policy's plan: HiPR's stage 1 (G-buffer, marking, reach, reprojection)
    double sort_seconds = 0.0;   // after the leading steps: HiPR's stage 3 (keys, radix sort)
    double focus_seconds = 0.0;  // re-planning for a new focus (set_focus)
    double leading_step_seconds =
        0.0;  // the policy's own steps (HiPR's stage 2: discovery + display)
    uint32_t leading_steps = 0;
    double step_seconds = 0.0;  // scheduled steps (path tracing + display)
    uint32_t steps = 0;
  };
  const EditTimes& edit_times() const { return m_times; }
  Policy policy() const { return m_policy->id(); }
  // The policy still renders leading steps of its own since the last edit (HiPR: stage 2, whose
  // weights are partial until it ends).
  bool leading_steps_pending() const { return m_leading_cursor < m_leading; }
  // The policy takes steps of its own before the rest of the round (HiPR: once the leading steps
  // have visited the edit's and the focus's tiles, their leads); some are still to come.
  bool lead_pass_pending() const { return m_policy->lead_pending(); }

 private:
  // How the tiles a step renders are shown (resolved in the step's own submission); none for
  // whole-pass policies, whose display waits for the whole pass.
  std::optional<DisplayRule> step_display_rule() const;
  // The last schedule entry was rendered: the next step starts a new round at the first.
  void end_round();
  // The round's target: a visit brings each pixel to it (the policy's own targets follow).
  void set_round_target(uint32_t target);
  // A plan was made (an edit, `edit`, or a focus): the policy's own steps start over.
  void planned(bool edit);

  ProgressiveRenderer& m_renderer;
  std::unique_ptr<SchedulingPolicy> m_policy;
  uint32_t m_tile_count;
  uint32_t m_pixels;
  DisplayRule m_display;
  uint32_t m_tiles_per_step;
  uint32_t m_visit_spp;
  uint32_t m_first_visit_spp;
  uint32_t m_cursor = 0;  // next schedule entry
  bool m_edited = false;  // an edit happened: the display rule applies
  bool m_relight = true;
  bool m_reproject = true;
  bool m_relit = false;
  bool m_first_round = false;  // still in the first pass over the schedule since the edit
  uint32_t m_rounds_since_edit = 0;
  bool m_at_round_end = false;
  uint32_t m_leading = 0;         // schedule entries [0, m_leading) are the policy's own steps
  uint32_t m_leading_cursor = 0;  // the next of them
  EditTimes m_times;              // since the last edit
  // The samples every pixel has when the round under way ends; unknown before the first edit
  // or focus (the renderer may have been given samples outside the scheduler).
  std::optional<uint32_t> m_round_target;
  Focus m_focus;
  // Settings the policy's own steps follow (RoundState).
  uint32_t m_converged_spp = 0;
  uint32_t m_focus_lead = kDefaultFocusLead;
  uint32_t m_edit_lead = kDefaultEditLead;
};

// Tiles per step when none is given: a sixteenth of the frame, as `hipr replay` and `hipr
// bench` use (the viewer takes smaller steps to fit its frame budget).
uint32_t default_tiles_per_step(uint32_t tile_count);

}  // namespace hipr
