#pragma once
// Re-render scheduling after edits: the HiPR policy and the orders it is compared with.
// A step renders a budget of tiles. What the screen shows is the renderer's display buffer:
// tiles keep showing their previous radiance until the display rule lets their fresh estimate
// take over (`full` shows nothing new until a whole pass is done).
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hipr/renderer.h"
#include "hipr/scene_diff.h"

namespace hipr {

enum class Policy {
  Hipr,      // the paper: active tiles, then discovered by weight, then outward by distance
  Full,      // restart the whole frame; the display changes when a full pass completes
  Scanline,  // production bucket order, row by row
  Spiral,    // production bucket order, outward from the image centre
  Random,    // tiles in a seeded random order
  Oracle,    // tiles by their true error against a reference image: the best any order could do
};

Policy parse_policy(const std::string& name);  // throws InputError
std::string policy_name(Policy policy);
const std::vector<Policy>& all_policies();

// The tile order of the fixed-order policies (every tile once).
std::vector<uint32_t> tile_order(Policy policy, uint32_t tiles_x, uint32_t tiles_y, uint32_t seed);

// The display rule a policy uses unless told otherwise: HiPR and the oracle blend stale and fresh
// estimates by their expected errors (Blend); the bucket orders show each tile as soon as it is
// rendered, as production IPR renderers do.
DisplayRule default_display_rule(Policy policy);

class Scheduler {
 public:
  // `tiles_per_step`: the budget of one step; `visit_spp`: samples a tile gets per visit.
  // The display starts as the renderer's current accumulation.
  Scheduler(Renderer& renderer, Policy policy, uint32_t tiles_per_step, uint32_t visit_spp = 1);

  void set_display_rule(DisplayRule rule) { m_display = rule; }
  // Samples a tile gets on its first visit after an edit (HiPR's stage 2 included); later visits
  // get `visit_spp`. More samples up front make a re-rendered tile worth showing sooner (its
  // fresh estimate must beat the converged stale one). `full` ignores it: its passes stay whole.
  void set_first_visit_spp(uint32_t spp) { m_first_visit_spp = std::max(spp, 1u); }
  DisplayRule display_rule() const { return m_display; }
  // The oracle ranks tiles by the error of what they show against this image (the converged
  // render of the edited scene); it must be set before each on_edit.
  void set_reference(ImageRGB reference) { m_reference = std::move(reference); }

  // The scene changed (already edited in `scene`): update the GPU and start a new schedule.
  // Tiles still owed to earlier edits stay owed: every pixel restarts at its next visit.
  void on_edit(const Scene& scene, const ChangeSet& changes);
  // Renders one step. Before any edit, steps are ordinary full-frame progressive passes.
  void step();

  ImageRGB displayed_image() const { return m_renderer.displayed_image(); }
  // Samples rendered since the last edit, in full-frame 1-spp passes (DESIGN.md's work unit).
  // The renderer's counters restart at each edit.
  double work_since_edit() const;
  // Seconds spent since the last edit in scheduling rather than path tracing: stage 1, sorting,
  // the oracle's ranking and capturing the stale display. (The display pass that follows each
  // step's rendering in the same submission counts as rendering, as any viewer's tone mapping.)
  double overhead_seconds() const { return m_overhead_seconds; }
  Policy policy() const { return m_policy; }
  // HiPR: stage 2 of the last edit still has active tiles to render (its weights are partial).
  bool in_stage2() const {
    return m_policy == Policy::Hipr && m_edited && m_stage2_cursor < m_active_tiles;
  }

 private:
  // How the tiles a step renders are shown (resolved in the step's own submission); none for
  // `full`, whose display waits for the whole pass.
  std::optional<DisplayRule> step_display_rule() const;
  // The last schedule entry was rendered: the next step starts a new round at the first.
  void end_round();

  Renderer& m_renderer;
  Policy m_policy;
  DisplayRule m_display;
  uint32_t m_tiles_per_step;
  uint32_t m_visit_spp;
  uint32_t m_first_visit_spp;
  uint32_t m_cursor = 0;       // next schedule entry
  bool m_edited = false;       // an edit happened: the display rule applies
  bool m_first_round = false;  // still in the first pass over the schedule since the edit
  // HiPR: |A| of the last edit (schedule entries [0, |A|) are stage 2's) and the next of them.
  uint32_t m_active_tiles = 0;
  uint32_t m_stage2_cursor = 0;
  double m_overhead_seconds = 0.0;
  std::optional<ImageRGB> m_reference;
};

}  // namespace hipr
