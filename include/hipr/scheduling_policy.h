#pragma once
// Scheduling policies: in which order tiles are re-rendered after an edit. HiPR is one; the
// orders it is compared with (full, scanline, spiral, random) are others, and `hipr bench`
// adds the oracle. Each is a class behind one interface, made by name (make_policy).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hipr/display_rule.h"
#include "hipr/focus.h"
#include "hipr/hipr_stage_runner.h"
#include "hipr/progressive_renderer.h"
#include "hipr/scene_diff.h"

namespace hipr {

enum class Policy {
  Hipr,      // the paper: active tiles, then discovered by weight, then outward by distance
  Full,      // restart the whole frame; the display changes when a full pass completes
  Scanline,  // production bucket order, row by row
  Spiral,    // production bucket order, outward from the image centre
  Random,    // tiles in a seeded random order
  Oracle,    // tiles by their true error against a reference image (hipr bench only)
};

Policy parse_policy(const std::string& name);  // throws InputError
std::string policy_name(Policy policy);
const std::vector<Policy>& all_policies();

// The display rule a policy uses unless told otherwise: HiPR and the oracle blend stale and fresh
// estimates by their expected errors (Blend); the bucket orders show each tile as soon as it is
// rendered, as production IPR renderers do.
DisplayRule default_display_rule(Policy policy);

// The tile order of the fixed-order policies (every tile once; identity for the others).
std::vector<uint32_t> tile_order(Policy policy, uint32_t tiles_x, uint32_t tiles_y, uint32_t seed);

// Where the scheduler's rounds stand, for a policy's steps of its own.
struct RoundState {
  uint32_t target = 0;           // the samples every pixel has when the round ends (0: unknown)
  uint32_t cursor = 0;           // the next schedule entry the round renders
  bool leading_pending = false;  // the policy's leading steps are not all taken
  uint32_t tiles_per_step = 1;   // the step budget
  uint32_t visit_spp = 1;        // samples a visit adds
  uint32_t first_visit_spp = 1;  // samples of a tile's first visit after an edit
  uint32_t converged_spp = 0;    // where the render stops (0: unknown); no pixel passes it
  bool focus_set = false;        // the user's focus is not empty
  uint32_t focus_lead = 0;       // visits the focus's tiles may run ahead (ScheduleSettings)
  uint32_t edit_lead = 0;        // visits the pixels an edit moved may get ahead (ScheduleSettings)
  std::optional<DisplayRule> display;  // how a step's tiles are shown (none: at the pass's end)
};

class SchedulingPolicy {
 public:
  virtual ~SchedulingPolicy() = default;
  virtual Policy id() const = 0;
  // Every tile restarts at the edit and the display changes only when a pass over all tiles
  // completes (what full-frame progressive viewers show); tiles get no extra first-visit samples.
  virtual bool whole_passes() const { return false; }
  // At an edit that only scales emitters, the stale image is relit by linearity
  // (ProgressiveRenderer::relight) before fresh samples come.
  virtual bool relights() const { return false; }

  // Whether a camera edit alone reprojects the display (HiPR's stage 1,
  // docs/method.md#camera-moves; on by default); off, it restarts what the screen shows.
  virtual void set_reprojection(bool reproject) { (void)reproject; }
  // Before any edit, on the scene as loaded (HiPR: the first G-buffer).
  virtual void start(ProgressiveRenderer& renderer) { (void)renderer; }
  // After an edit (the renderer already holds the edited scene; pixels not re-rendered since
  // the previous edit still owe its restart, the new one is marked after this): puts the order
  // in the renderer's schedule. Returns how many leading schedule entries the policy renders
  // itself (render_leading), 0 when the schedule is rendered as it is.
  virtual uint32_t plan(ProgressiveRenderer& renderer, const ChangeSet& changes) = 0;
  // Renders one leading step: entries from `offset`, at most `budget` of them (HiPR: stage 2,
  // with discovery; it may stop early where its own lead begins). Returns how many it rendered
  // (at least 1).
  virtual uint32_t render_leading(ProgressiveRenderer& renderer, uint32_t offset, uint32_t budget,
                                  uint32_t samples_per_pixel,
                                  std::optional<DisplayRule> then_resolve,
                                  const RoundState& round) {
    (void)renderer, (void)offset, (void)samples_per_pixel, (void)then_resolve, (void)round;
    return budget;
  }
  // After the last leading entry: orders the rest (HiPR: stage 3, from stage 2's weights).
  virtual void finish_leading(ProgressiveRenderer& renderer, const RoundState& round) {
    (void)renderer, (void)round;
  }

  // ---- Rounds. A visit brings each pixel to the round's target (set_round_target); a policy
  // may bring some pixels ahead of it in steps of its own (HiPR: the focus's and the edit's
  // leads, docs/method.md#the-edits-lead). The scheduler keeps the rounds, the policy its leads.

  // After a plan (an edit's, or a new focus's: `edit` false) with `leading` leading entries.
  virtual void planned(ProgressiveRenderer& renderer, uint32_t leading, bool edit) {
    (void)renderer, (void)leading, (void)edit;
  }
  // The round's target is known or changed: the renderer's sample targets follow (the round's,
  // and the policy's own for the pixels it brings ahead).
  virtual void set_round_target(ProgressiveRenderer& renderer, const RoundState& round) {
    renderer.set_sample_target(round.target);
  }
  // Before each step: takes a step of the policy's own instead (HiPR: a lead step) and returns
  // true, or false to leave the step to the scheduler.
  virtual bool lead_step(ProgressiveRenderer& renderer, const RoundState& round) {
    (void)renderer, (void)round;
    return false;
  }
  // The policy's own steps are not done (a round cannot end before them).
  virtual bool lead_pending() const { return false; }
  // The last schedule entry was rendered: a new round starts.
  virtual void round_ended() {}

  // The user's focus changed (docs/method.md#focus; no edit: nothing restarts). A policy that
  // follows it keeps it for every later plan, re-plans now and returns its leading entries as
  // plan() does; the others return nothing and keep their order.
  virtual std::optional<uint32_t> refocus(ProgressiveRenderer& renderer, const Focus& focus) {
    (void)renderer, (void)focus;
    return std::nullopt;
  }
};

// hipr, full, scanline, spiral or random; the oracle needs a reference image and throws
// InputError here (hipr bench makes it). hipr's stages run on hipr's renderer.
std::unique_ptr<SchedulingPolicy> make_policy(Policy policy);
// HiPR driving `stages` (another progressive renderer's, or a test's), which outlive it.
std::unique_ptr<SchedulingPolicy> make_hipr_policy(HiprStageRunner& stages);

}  // namespace hipr
