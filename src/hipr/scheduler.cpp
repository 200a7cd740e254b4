#include "hipr/scheduler.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/error.h"
#include "core/timer.h"
#include "image/error_metrics.h"

namespace hipr {

const std::vector<Policy>& all_policies() {
  static const std::vector<Policy> list = {Policy::Hipr,   Policy::Full,   Policy::Scanline,
                                           Policy::Spiral, Policy::Random, Policy::Oracle};
  return list;
}

Policy parse_policy(const std::string& name) {
  for (Policy p : all_policies())
    if (policy_name(p) == name) return p;
  throw InputError("unknown policy '" + name + "' (hipr, full, scanline, spiral, random, oracle)");
}

std::string policy_name(Policy policy) {
  switch (policy) {
    case Policy::Hipr:
      return "hipr";
    case Policy::Full:
      return "full";
    case Policy::Scanline:
      return "scanline";
    case Policy::Spiral:
      return "spiral";
    case Policy::Random:
      return "random";
    case Policy::Oracle:
      return "oracle";
  }
  return "?";
}

DisplayRule default_display_rule(Policy policy) {
  return policy == Policy::Hipr || policy == Policy::Oracle ? DisplayRule::Blend
                                                            : DisplayRule::Immediate;
}

std::vector<uint32_t> tile_order(Policy policy, uint32_t tiles_x, uint32_t tiles_y, uint32_t seed) {
  std::vector<uint32_t> order(size_t(tiles_x) * tiles_y);
  std::iota(order.begin(), order.end(), 0u);
  if (policy == Policy::Random) {
    std::mt19937 rng(seed);
    std::shuffle(order.begin(), order.end(), rng);
  } else if (policy == Policy::Spiral) {
    // Outward from the centre: by distance, then by angle, as bucket renderers spiral.
    const double cx = (tiles_x - 1) * 0.5, cy = (tiles_y - 1) * 0.5;
    const auto key = [&](uint32_t t) {
      const double dx = double(t % tiles_x) - cx, dy = double(t / tiles_x) - cy;
      return std::make_pair(std::max(std::abs(dx), std::abs(dy)), std::atan2(dy, dx));
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
  }
  return order;
}

namespace {

// Tiles by descending error of what they show against the reference (ties in id order).
std::vector<uint32_t> oracle_order(const ImageRGB& shown, const ImageRGB& reference,
                                   uint32_t tile_size) {
  const std::vector<double> error = relmse_tile_sums(shown, reference, tile_size);
  std::vector<uint32_t> order(error.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return error[a] > error[b]; });
  return order;
}

}  // namespace

Scheduler::Scheduler(Renderer& renderer, Policy policy, uint32_t tiles_per_step, uint32_t visit_spp)
    : m_renderer(renderer),
      m_policy(policy),
      m_display(default_display_rule(policy)),
      m_tiles_per_step(std::max(tiles_per_step, 1u)),
      m_visit_spp(std::max(visit_spp, 1u)),
      m_first_visit_spp(m_visit_spp) {
  const std::vector<uint32_t> order =
      tile_order(Policy::Scanline, renderer.tiles_x(), renderer.tiles_y(), 0);
  renderer.set_schedule(order);
  renderer.resolve_display_all(DisplayRule::Immediate);
  // The G-buffer before any edit. The oracle keeps one too: the display rule uses it (which
  // surface each pixel shows), so the oracle differs from HiPR in its order alone.
  if (policy == Policy::Hipr) renderer.stage1_visibility({});
  if (policy == Policy::Oracle) renderer.refresh_gbuffer();
}

void Scheduler::on_edit(const Scene& scene, const ChangeSet& changes) {
  if (m_policy == Policy::Oracle && !m_reference)
    throw InternalError("the oracle policy needs a reference image");
  // Restarting the counters (a GPU fill) instead of reading them keeps read-backs off the
  // edit path: work is only read when someone asks for it.
  m_renderer.reset_counters();
  m_overhead_seconds = 0.0;
  const Timer timer;
  // What the screen shows at the moment of the edit becomes the stale image. `full` keeps
  // showing its last completed pass (before the first edit: whatever was rendered).
  if (!m_edited)
    m_renderer.resolve_display_all(DisplayRule::Immediate);
  else if (m_policy != Policy::Full)
    m_renderer.resolve_display_all(m_display);
  m_renderer.capture_stale_display();
  m_overhead_seconds += timer.seconds();
  m_renderer.update_scene(scene, changes);
  const Timer schedule_timer;
  m_edited = true;
  m_cursor = 0;
  m_first_round = true;
  m_renderer.mark_all_owed();
  if (m_policy == Policy::Hipr) {
    // Stage 1, then the order it gives (active tiles by change score) for stage 2's steps.
    m_active_tiles = m_renderer.stage1_visibility(changes);
    m_renderer.build_schedule();
    m_stage2_cursor = 0;  // with no active tile (nothing visible changed) stage 3 starts at once
  } else if (m_policy == Policy::Oracle) {
    m_renderer.refresh_gbuffer();
    m_renderer.set_schedule(
        oracle_order(m_renderer.displayed_image(), *m_reference, m_renderer.settings().tile_size));
  } else {
    m_renderer.set_schedule(tile_order(m_policy, m_renderer.tiles_x(), m_renderer.tiles_y(),
                                       m_renderer.settings().seed));
  }
  m_overhead_seconds += schedule_timer.seconds();
}

std::optional<DisplayRule> Scheduler::step_display_rule() const {
  if (m_policy == Policy::Full) return std::nullopt;  // shown when the pass completes
  return m_edited ? m_display : DisplayRule::Immediate;
}

void Scheduler::step() {
  const bool first_visit = m_first_round && m_edited && m_policy != Policy::Full;
  const uint32_t spp = first_visit ? m_first_visit_spp : m_visit_spp;
  if (in_stage2()) {
    // Stage 2, one budget of active tiles per step (immediate feedback, most changed first).
    // When the last active tile is done, stage 3's order is sorted on the GPU from the weights
    // stage 2 discovered; the active tiles stay first in it, so stage 3 starts after them.
    const uint32_t count = std::min(m_tiles_per_step, m_active_tiles - m_stage2_cursor);
    m_renderer.stage2_discover(m_stage2_cursor, count, spp, step_display_rule());
    m_stage2_cursor += count;
    if (m_stage2_cursor == m_active_tiles) {
      const Timer timer;
      m_renderer.build_schedule();
      m_overhead_seconds += timer.seconds();
      m_cursor = m_active_tiles;
      if (m_cursor == m_renderer.tile_count()) end_round();  // every tile was active
    }
    return;
  }
  const uint32_t tiles = m_renderer.tile_count();
  m_renderer.render_schedule(m_cursor, m_tiles_per_step, spp, false, step_display_rule());
  m_cursor += m_tiles_per_step;
  if (m_cursor >= tiles) end_round();
}

void Scheduler::end_round() {
  m_cursor = 0;
  m_first_round = false;
  // `full` shows a whole pass when it completes, as a full-frame progressive viewer presents
  // each frame. Like every policy's per-step display pass, this counts as rendering.
  if (m_policy == Policy::Full) m_renderer.resolve_display_all(DisplayRule::Immediate);
}

double Scheduler::work_since_edit() const {
  const double pixels = double(m_renderer.settings().width) * m_renderer.settings().height;
  return double(m_renderer.counters().samples) / pixels;
}

}  // namespace hipr
