#include "hipr/scheduler.h"

#include <algorithm>

#include "core/timer.h"
#include "vk/buffer.h"

namespace hipr {

uint32_t default_tiles_per_step(uint32_t tile_count) {
  return std::max(1u, (tile_count + 15) / 16);
}

Scheduler::Scheduler(ProgressiveRenderer& renderer, std::unique_ptr<SchedulingPolicy> policy,
                     uint32_t tiles_per_step, uint32_t visit_spp)
    : m_renderer(renderer),
      m_policy(std::move(policy)),
      m_tile_count(renderer.tile_grid().tile_count()),
      m_pixels(renderer.tile_grid().width * renderer.tile_grid().height),
      m_display(default_display_rule(m_policy->id())),
      m_tiles_per_step(std::max(tiles_per_step, 1u)),
      m_visit_spp(std::max(visit_spp, 1u)),
      m_first_visit_spp(m_visit_spp) {
  const TileGrid grid = renderer.tile_grid();
  renderer.set_sample_target(0);  // an earlier scheduler's rounds are not this one's
  renderer.set_schedule(tile_order(Policy::Scanline, grid.tiles_x, grid.tiles_y, 0));
  renderer.resolve_display_all(DisplayRule::Immediate);
  m_policy->start(renderer);
}

void Scheduler::configure(const ScheduleSettings& settings, uint32_t converged_spp) {
  set_display_rule(settings.display.value_or(default_display_rule(policy())));
  set_first_visit_spp(settings.first_visit_spp ? settings.first_visit_spp : m_visit_spp);
  set_relight(settings.relight);
  set_reproject(settings.reproject);
  set_converged_spp(converged_spp);
  set_focus_lead(settings.focus_lead);
  set_edit_lead(settings.edit_lead);
}

void Scheduler::on_edit(const Scene& scene, const ChangeSet& changes) {
  // Restarting the counters (a GPU fill) instead of reading them keeps read-backs off the
  // edit path: work is only read when someone asks for it.
  m_renderer.reset_counters();
  m_times = {};
  const Timer timer;
  // What the screen shows at the moment of the edit becomes the stale image. A whole-pass
  // policy keeps showing its last completed pass (before the first edit: whatever was rendered).
  if (!m_edited)
    m_renderer.resolve_display_all(DisplayRule::Immediate);
  else if (!m_policy->whole_passes())
    m_renderer.resolve_display_all(m_display);
  m_renderer.capture_stale_display();
  // Before the pixels owe this edit's restart: the relight reads which estimates are current.
  m_relit = m_relight && m_policy->relights() && m_renderer.relight(changes.emitter_scales);
  m_times.capture_seconds = timer.seconds();
  const Timer scene_timer;
  const vk::DeviceCounts before_update = vk::DeviceCounts::now();
  m_renderer.update_scene(scene, changes);
  m_times.scene_seconds = scene_timer.seconds();
  const vk::DeviceCounts update = vk::DeviceCounts::now() - before_update;
  m_times.scene_allocations = uint32_t(update.allocations);
  m_times.scene_submissions = uint32_t(update.submissions);
  const Timer schedule_timer;
  m_edited = true;
  m_cursor = 0;
  m_first_round = true;
  m_rounds_since_edit = 0;
  m_at_round_end = false;
  m_round_target =
      m_policy->whole_passes() ? m_visit_spp : m_first_visit_spp;  // handed over by planned()
  // Planned while the pixels' owed bits still say which tiles earlier edits left unrendered
  // (HiPR keeps those ranked), then every pixel owes a restart. With no leading step (HiPR when
  // nothing visible changed) the schedule starts at once.
  m_policy->set_reprojection(m_reproject);
  m_leading = std::min(m_policy->plan(m_renderer, changes), m_tile_count);
  m_leading_cursor = 0;
  planned(true);
  m_renderer.mark_all_owed();
  m_times.plan_seconds = schedule_timer.seconds();
}

std::optional<DisplayRule> Scheduler::step_display_rule() const {
  if (m_policy->whole_passes()) return std::nullopt;  // shown when the pass completes
  return m_edited ? m_display : DisplayRule::Immediate;
}

RoundState Scheduler::round_state() const {
  RoundState round;
  round.target = m_round_target.value_or(0);
  round.cursor = m_cursor;
  round.leading_pending = leading_steps_pending();
  round.tiles_per_step = m_tiles_per_step;
  round.visit_spp = m_visit_spp;
  round.first_visit_spp = m_first_visit_spp;
  round.converged_spp = m_converged_spp;
  round.focus_set = !m_focus.empty();
  round.focus_lead = m_focus_lead;
  round.edit_lead = m_edit_lead;
  round.display = step_display_rule();
  return round;
}

void Scheduler::step() {
  const Timer step_timer;
  m_at_round_end = false;
  // A step of the policy's own first (HiPR: the focus's or the edit's lead), when it has one.
  if (m_policy->lead_step(m_renderer, round_state())) {
    m_times.step_seconds += step_timer.seconds();
    m_times.steps += 1;
    if (!lead_pass_pending() && !leading_steps_pending() && m_cursor == m_tile_count) end_round();
    return;
  }
  const bool first_visit = m_first_round && m_edited && !m_policy->whole_passes();
  const uint32_t spp = first_visit ? m_first_visit_spp : m_visit_spp;
  if (leading_steps_pending()) {
    // The policy's own steps, one budget each (HiPR's stage 2: immediate feedback, most changed
    // first). After the last, the policy orders the rest (stage 3's sort, from the weights stage
    // 2 discovered); the leading entries stay first in it, so the schedule resumes after them.
    const uint32_t budget = std::min(m_tiles_per_step, m_leading - m_leading_cursor);
    const uint32_t count =
        std::min(m_policy->render_leading(m_renderer, m_leading_cursor, budget, spp,
                                          step_display_rule(), round_state()),
                 budget);
    m_times.leading_step_seconds += step_timer.seconds();
    m_times.leading_steps += 1;
    m_leading_cursor += std::max(count, 1u);
    if (m_leading_cursor >= m_leading) {
      m_leading_cursor = m_leading;
      m_cursor = m_leading;
      const Timer timer;
      m_policy->finish_leading(m_renderer, round_state());
      m_times.sort_seconds += timer.seconds();
      if (!lead_pass_pending() && m_cursor == m_tile_count) end_round();  // every tile led
    }
    return;
  }
  m_renderer.render_schedule(m_cursor, m_tiles_per_step, spp, false, step_display_rule());
  m_times.step_seconds += step_timer.seconds();
  m_times.steps += 1;
  m_cursor += m_tiles_per_step;
  if (m_cursor >= m_tile_count) end_round();
}

void Scheduler::end_round() {
  m_cursor = 0;
  m_first_round = false;
  ++m_rounds_since_edit;
  m_at_round_end = true;
  m_policy->round_ended();
  if (m_round_target) set_round_target(*m_round_target + m_visit_spp);
  // A whole-pass policy shows a whole pass when it completes, as a full-frame progressive viewer
  // presents each frame. Like every policy's per-step display pass, this counts as rendering.
  if (m_policy->whole_passes()) m_renderer.resolve_display_all(DisplayRule::Immediate);
}

void Scheduler::set_round_target(uint32_t target) {
  m_round_target = target;
  m_policy->set_round_target(m_renderer, round_state());
}

void Scheduler::planned(bool edit) {
  m_policy->planned(m_renderer, m_leading, edit);
  if (m_round_target) set_round_target(*m_round_target);
}

void Scheduler::set_converged_spp(uint32_t spp) {
  m_converged_spp = spp;
  if (m_round_target) set_round_target(*m_round_target);
}

void Scheduler::set_focus_lead(uint32_t visits) {
  m_focus_lead = visits;
  if (m_round_target) set_round_target(*m_round_target);
}

void Scheduler::set_focus(const Focus& focus) {
  m_focus = focus;
  const Timer timer;
  const std::optional<uint32_t> leading = m_policy->refocus(m_renderer, m_focus);
  if (!leading) return;  // the policy keeps its order
  // The round under way goes on in the new order: a visit brings a pixel to the round's target,
  // so tiles it already visited get nothing more and every pixel ends it with the same count
  // (but the focus's lead: the work since the edit tells when a render has converged, so no
  // pixel may run ahead unchecked). Before the first edit the scheduler knows no round: the
  // counts are read back, and the round is the one they are in (uniform counts: the next).
  if (!m_round_target) {
    const auto [fewest, most] = m_renderer.sample_count_range();
    set_round_target(fewest == most ? most + m_visit_spp : most);
  }
  m_cursor = 0;
  m_leading = std::min(*leading, m_tile_count);
  m_leading_cursor = 0;
  planned(false);
  m_times.focus_seconds += timer.seconds();
}

double Scheduler::work_since_edit() const {
  return double(m_renderer.samples_since_reset()) / double(m_pixels);
}

}  // namespace hipr
