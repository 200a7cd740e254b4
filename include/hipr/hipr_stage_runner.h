#pragma once
// HiPR's three stages as an interface (docs/method.md, "The method"): what the HiPR policy
// drives. hipr's own run on the renderer's device state (src/hipr/hipr_stages.h); another
// progressive renderer gives the policy its own (make_hipr_policy).
#include <cstdint>
#include <optional>

#include "hipr/display_rule.h"
#include "hipr/focus.h"
#include "hipr/scene_diff.h"

namespace hipr {

// HiPR's stages (docs/method.md, "The method"). Each records GPU work and waits.
class HiprStageRunner {
 public:
  virtual ~HiprStageRunner() = default;
  // Stage 1: the G-buffer of the scene as it is now (the previous one is kept) and the active
  // tiles, where an element of `changes` is visible now or was before, each with a change
  // score. A changed punctual light activates the tiles it reaches; a camera or environment
  // change makes every tile active (no G-buffer shows their reach), and a camera change alone
  // reprojects the display before it (set_reprojection). Returns |A| (stage 2 is split into
  // steps over it).
  virtual uint32_t stage1_visibility(const ChangeSet& changes) = 0;
  // Whether stage 1 reprojects the display at an edit that changes nothing but the camera (on
  // by default; off, such an edit restarts what the screen shows, for comparison).
  virtual void set_reprojection(bool reproject) = 0;
  // Stage 2: path-traces the active tiles among schedule entries [offset, offset + count)
  // (restarting them) with discovery on; `then_resolve` resolves their display in the same
  // submission.
  virtual void stage2_discover(uint32_t offset, uint32_t count, uint32_t samples_per_pixel,
                               std::optional<DisplayRule> then_resolve = std::nullopt) = 0;
  // Stage 3: the schedule, sorted on the GPU: active tiles by change score (those of the focus
  // after the edit's, by focus score), then discovered tiles by weight, then the rest by
  // distance to the seeds.
  virtual void build_schedule() = 0;
  // The focus every later stage 1 marks besides the edit's changes (docs/method.md#focus).
  virtual void set_focus(const Focus& focus) = 0;
  // Stage 1 without an edit (the focus changed): the same tile state as stage1_visibility
  // (tiles an edit left unrendered keep their rank, the focus's tiles are active), from the
  // G-buffer as it is; nothing is rendered. Returns |A|.
  virtual uint32_t stage1_focus() = 0;
  // Of the last stage 1's active tiles, how many have a change or focus score: they lead its
  // order, the rest of the active set (an edit that activates every tile) follows them.
  virtual uint32_t seeded_tiles() const = 0;
  // Of them, how many hold a pixel that leads after the edit (a moved object, a surface the pixel
  // no longer sees: docs/method.md#the-edits-lead).
  virtual uint32_t lead_tiles() const = 0;
  // After the last build_schedule: how many tiles stage 2 discovered strongly besides the active
  // ones (weight at least a sixteenth of the strongest: they follow the active tiles in the
  // schedule).
  virtual uint32_t discovered_tiles() const = 0;
};

}  // namespace hipr
