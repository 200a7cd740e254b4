#pragma once
// What the scheduler needs of a progressive renderer: a tile grid, a schedule to render from,
// a display to resolve. hipr's Renderer is one; another progressive renderer drives the same
// policies by implementing this (the HiPR policy then needs HiPR's stages given to it:
// make_hipr_policy, hipr/hipr_stage_runner.h).
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "hipr/display_rule.h"
#include "hipr/image.h"
#include "hipr/scene.h"
#include "hipr/scene_diff.h"

namespace hipr {

class RenderState;  // the engine's device state: only the library's own methods use it

// Image and tile geometry.
struct TileGrid {
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t tile_size = 0;
  uint32_t tiles_x = 0;
  uint32_t tiles_y = 0;
  uint32_t seed = 0;  // of the render's random numbers (the random order uses it too)
  uint32_t tile_count() const { return tiles_x * tiles_y; }
};

class ProgressiveRenderer {
 public:
  virtual ~ProgressiveRenderer() = default;

  virtual TileGrid tile_grid() const = 0;
  // Brings the renderer up to date with `scene` after edits, touching only what `changes`
  // names. Accumulated samples are kept: the scheduler decides which tiles restart.
  virtual void update_scene(const Scene& scene, const ChangeSet& changes) = 0;

  // The schedule: tile ids in the order to render them, every tile once.
  virtual void set_schedule(std::span<const uint32_t> order) = 0;
  // Adds samples to the tiles of schedule entries [offset, offset + count) (skip_active: not
  // those stage 2 rendered) and, with `then_resolve`, resolves their display.
  virtual void render_schedule(uint32_t offset, uint32_t count, uint32_t samples_per_pixel,
                               bool skip_active,
                               std::optional<DisplayRule> then_resolve = std::nullopt) = 0;
  // Brings the focus's tiles and the pixels that lead after the edit among schedule entries
  // [offset, offset + count) to their targets (set_sample_target; the rest is left alone) and,
  // with `then_resolve`, resolves them.
  virtual void render_lead(uint32_t offset, uint32_t count,
                           std::optional<DisplayRule> then_resolve = std::nullopt) = 0;
  // Every pixel owes a restart: its next visit drops its old samples.
  virtual void mark_all_owed() = 0;
  // The scheduler's round target: from now on a visit brings each pixel to `target` samples
  // since its last restart, adding none where it has them (0: a visit adds samples_per_pixel,
  // whatever the pixel has). A round re-planned midway then still ends uniform. The tiles where
  // stage 1 saw the focus are brought to `focus_target` instead (0: `target`): they run ahead.
  // The pixels stage 1 marked to lead after the edit are brought to at least `lead_target`.
  virtual void set_sample_target(uint32_t target, uint32_t focus_target = 0,
                                 uint32_t lead_target = 0) = 0;
  // The fewest and the most samples a pixel has since its last restart (owed pixels count as
  // 0).
  virtual std::pair<uint32_t, uint32_t> sample_count_range() const = 0;

  // The display: what every pixel shows. At an edit it becomes the stale estimate fresh samples
  // are weighed against; resolves let fresh estimates take over by the display rule.
  virtual void resolve_display_all(DisplayRule rule) = 0;
  virtual void capture_stale_display() = 0;
  virtual ImageRGB displayed_image() const = 0;
  // At an edit that only scaled emitters (ChangeSet::emitter_scales), after the capture: the
  // stale estimate becomes the converged image relit by linearity, shown at once. Returns false
  // (nothing done) where the renderer cannot (an emitter it does not keep apart).
  virtual bool relight(const std::vector<EmitterScale>& /*scales*/) { return false; }
  // Renders the G-buffer of the scene as it is now (the display rules read which surface each
  // pixel shows), leaving the previous one and the tile flags alone.
  virtual void refresh_gbuffer() = 0;

  // Samples added since the last reset_counters (work, in samples).
  virtual uint64_t samples_since_reset() const = 0;
  virtual void reset_counters() = 0;

  // hipr's Renderer: its device state (src/render/render_state.h), to which HiPR attaches its
  // stage passes; nullptr for other renderers.
  virtual RenderState* render_state() { return nullptr; }
};

}  // namespace hipr
