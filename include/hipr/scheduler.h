#pragma once
// Re-render scheduling after edits: the HiPR policy and the orders it is compared with.
// A step renders a budget of tiles; tiles not yet re-rendered since the last edit keep showing
// their previous radiance (except `full`, which shows nothing new until a whole pass is done).
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
};

Policy parse_policy(const std::string& name);  // throws InputError
std::string policy_name(Policy policy);

// The tile order of the non-HiPR policies (every tile once).
std::vector<uint32_t> tile_order(Policy policy, uint32_t tiles_x, uint32_t tiles_y, uint32_t seed);

class Scheduler {
 public:
  // `tiles_per_step`: the budget of one step; `visit_spp`: samples a tile gets per visit.
  Scheduler(Renderer& renderer, Policy policy, uint32_t tiles_per_step, uint32_t visit_spp = 1);

  // The scene changed (already edited in `scene`): update the GPU and start a new schedule.
  // Tiles still owed to earlier edits stay owed: every pixel restarts at its next visit.
  void on_edit(const Scene& scene, const ChangeSet& changes);
  // Renders one step. Before any edit, steps are ordinary full-frame progressive passes.
  void step();

  ImageRGB displayed_image() const;
  // Samples rendered since the last edit, in full-frame 1-spp passes (DESIGN.md's work unit).
  // The renderer's counters restart at each edit.
  double work_since_edit() const;
  // Seconds spent in stage 1 and sorting since the last edit (scheduler overhead).
  double overhead_seconds() const { return m_overhead_seconds; }
  Policy policy() const { return m_policy; }

 private:
  Renderer& m_renderer;
  Policy m_policy;
  uint32_t m_tiles_per_step;
  uint32_t m_visit_spp;
  uint32_t m_cursor = 0;       // next schedule entry
  bool m_first_round = false;  // still in the first pass over the schedule since the edit
  bool m_stage2_pending = false;
  double m_overhead_seconds = 0.0;
  std::optional<ImageRGB> m_full_display;  // `full`: what the screen shows until a pass ends
};

}  // namespace hipr
