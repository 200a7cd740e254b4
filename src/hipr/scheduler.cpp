#include "hipr/scheduler.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/error.h"
#include "core/timer.h"

namespace hipr {

Policy parse_policy(const std::string& name) {
  for (Policy p : {Policy::Hipr, Policy::Full, Policy::Scanline, Policy::Spiral, Policy::Random})
    if (policy_name(p) == name) return p;
  throw InputError("unknown policy '" + name + "' (hipr, full, scanline, spiral, random)");
}

std::string policy_name(Policy policy) {
  switch (policy) {
    case Policy::Hipr: return "hipr";
    case Policy::Full: return "full";
    case Policy::Scanline: return "scanline";
    case Policy::Spiral: return "spiral";
    case Policy::Random: return "random";
  }
  return "?";
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
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
  }
  return order;
}

Scheduler::Scheduler(Renderer& renderer, Policy policy, uint32_t tiles_per_step, uint32_t visit_spp)
    : m_renderer(renderer), m_policy(policy), m_tiles_per_step(std::max(tiles_per_step, 1u)), m_visit_spp(std::max(visit_spp, 1u)) {
  const std::vector<uint32_t> order = tile_order(Policy::Scanline, renderer.tiles_x(), renderer.tiles_y(), 0);
  renderer.set_schedule(order);
  if (policy == Policy::Hipr) renderer.stage1_visibility({});  // the G-buffer before any edit
}

void Scheduler::on_edit(const Scene& scene, const ChangeSet& changes) {
  // Restarting the counters (a GPU fill) instead of reading them keeps read-backs off the
  // edit path: work is only read when someone asks for it.
  m_renderer.reset_counters();
  m_overhead_seconds = 0.0;
  m_renderer.update_scene(scene, changes);
  m_cursor = 0;
  m_first_round = true;
  const Timer timer;
  m_renderer.mark_all_owed();
  if (m_policy == Policy::Hipr) {
    m_renderer.stage1_visibility(changes);
    m_stage2_pending = true;
  } else {
    m_renderer.set_schedule(tile_order(m_policy, m_renderer.tiles_x(), m_renderer.tiles_y(), m_renderer.settings().seed));
    if (m_policy == Policy::Full && !m_full_display) m_full_display = m_renderer.image();
  }
  m_overhead_seconds += timer.seconds();
}

void Scheduler::step() {
  if (m_stage2_pending) {
    // Stage 2 renders the active set at once (immediate feedback), then stage 3's order is
    // sorted on the GPU from the weights it discovered.
    m_stage2_pending = false;
    m_renderer.stage2_discover(m_visit_spp);
    const Timer timer;
    m_renderer.build_schedule();
    m_overhead_seconds += timer.seconds();
    return;
  }
  const uint32_t tiles = m_renderer.tile_count();
  // The first round after a HiPR edit skips the active tiles: stage 2 rendered them.
  m_renderer.render_schedule(m_cursor, m_tiles_per_step, m_visit_spp, m_first_round && m_policy == Policy::Hipr);
  m_cursor += m_tiles_per_step;
  if (m_cursor >= tiles) {
    m_cursor = 0;
    m_first_round = false;
    if (m_policy == Policy::Full) m_full_display.reset();  // a whole pass is done: show it
  }
}

ImageRGB Scheduler::displayed_image() const { return m_full_display ? *m_full_display : m_renderer.image(); }

double Scheduler::work_since_edit() const {
  const double pixels = double(m_renderer.settings().width) * m_renderer.settings().height;
  return double(m_renderer.counters().samples) / pixels;
}

}  // namespace hipr
