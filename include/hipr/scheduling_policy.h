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
  // Renders leading entries [offset, offset + count) (HiPR: stage 2, with discovery).
  virtual void render_leading(ProgressiveRenderer& renderer, uint32_t offset, uint32_t count,
                              uint32_t samples_per_pixel, std::optional<DisplayRule> then_resolve) {
    (void)renderer, (void)offset, (void)count, (void)samples_per_pixel, (void)then_resolve;
  }
  // After the last leading entry: orders the rest (HiPR: stage 3, from stage 2's weights).
  virtual void finish_leading(ProgressiveRenderer& renderer) { (void)renderer; }
  // Of the last plan's leading entries, the first this many hold the tiles the edit or the
  // focus scored (HiPR: the rest of the active set follows them, by distance); 0: none.
  virtual uint32_t seeded_leading(ProgressiveRenderer& renderer) {
    (void)renderer;
    return 0;
  }
  // Of the last plan's seeded leading entries, how many hold pixels that lead after the edit
  // (HiPR: stage 1's pixel-lead bits); 0: none, no edit lead.
  virtual uint32_t lead_tiles(ProgressiveRenderer& renderer) {
    (void)renderer;
    return 0;
  }
  // After finish_leading: how many schedule entries after the leading ones hold tiles the
  // leading steps found changed too (HiPR: discovered); the edit's lead waits for them.
  virtual uint32_t discovered_entries(ProgressiveRenderer& renderer) {
    (void)renderer;
    return 0;
  }
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
