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
  m_round_target =
      m_policy->whole_passes() ? m_visit_spp : m_first_visit_spp;  // handed over by planned()
  // Planned while the pixels' owed bits still say which tiles earlier edits left unrendered
  // (HiPR keeps those ranked), then every pixel owes a restart. With no leading step (HiPR when
  // nothing visible changed) the schedule starts at once.
  m_policy->set_reprojection(m_reproject);
  m_leading = std::min(m_policy->plan(m_renderer, changes), m_tile_count);
  m_leading_cursor = 0;
  m_edit_plan = true;
  planned();
  m_renderer.mark_all_owed();
  m_times.plan_seconds = schedule_timer.seconds();
}

std::optional<DisplayRule> Scheduler::step_display_rule() const {
  if (m_policy->whole_passes()) return std::nullopt;  // shown when the pass completes
  return m_edited ? m_display : DisplayRule::Immediate;
}

void Scheduler::step() {
  const Timer step_timer;
  if (m_edit_lead_at && !lead_pass_pending() && !leading_steps_pending() &&
      m_cursor >= *m_edit_lead_at)
    begin_edit_lead();
  const bool first_visit = m_first_round && m_edited && !m_policy->whole_passes();
  const uint32_t spp = first_visit ? m_first_visit_spp : m_visit_spp;
  if (lead_pass_pending()) {
    const uint32_t count = std::min(lead_step_tiles(), m_lead_end - m_lead_cursor);
    m_renderer.render_lead(m_lead_cursor, count, step_display_rule());
    m_times.step_seconds += step_timer.seconds();
    m_times.steps += 1;
    m_lead_cursor += count;
    if (!lead_pass_pending() && !leading_steps_pending() && m_cursor == m_tile_count) end_round();
    return;
  }
  if (leading_steps_pending()) {
    // The policy's own steps, one budget each (HiPR's stage 2: immediate feedback, most changed
    // first). After the last, the policy orders the rest (stage 3's sort, from the weights stage
    // 2 discovered); the leading entries stay first in it, so the schedule resumes after them.
    uint32_t count = std::min(m_tiles_per_step, m_leading - m_leading_cursor);
    if (!m_lead_begun && m_lead_at > m_leading_cursor)
      count = std::min(count, m_lead_at - m_leading_cursor);
    m_policy->render_leading(m_renderer, m_leading_cursor, count, spp, step_display_rule());
    m_times.leading_step_seconds += step_timer.seconds();
    m_times.leading_steps += 1;
    m_leading_cursor += count;
    if (!m_lead_begun && m_leading_cursor >= m_lead_at) begin_lead();
    if (m_leading_cursor == m_leading) {
      const Timer timer;
      m_policy->finish_leading(m_renderer);
      m_times.sort_seconds += timer.seconds();
      m_cursor = m_leading;
      // The edit's lead comes once the tiles stage 2 discovered had their first visit too.
      if (m_edit_plan && m_edit_lead > 0 && m_converged_spp > *m_round_target &&
          m_policy->lead_tiles(m_renderer) > 0)
        m_edit_lead_at = m_leading + m_policy->discovered_entries(m_renderer);
      if (!lead_pass_pending() && m_cursor == m_tile_count)
        end_round();  // every tile was a leading one
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
  m_edit_lead_at.reset();  // a lead the first round did not reach: every pixel gets more now
  if (m_round_target) set_round_target(*m_round_target + m_visit_spp);
  // A whole-pass policy shows a whole pass when it completes, as a full-frame progressive viewer
  // presents each frame. Like every policy's per-step display pass, this counts as rendering.
  if (m_policy->whole_passes()) m_renderer.resolve_display_all(DisplayRule::Immediate);
}

void Scheduler::set_round_target(uint32_t target) {
  m_round_target = target;
  // The focus runs ahead by whole visits, up to the converged count (never past it: the work
  // since the edit would then reach it before every pixel has).
  m_focus_target = 0;
  if (m_focus_ahead && m_follows_focus && !m_focus.empty() && m_focus_lead > 0 &&
      m_converged_spp > target)
    m_focus_target = std::min(target + m_focus_lead * m_visit_spp, m_converged_spp);
  m_renderer.set_sample_target(target, m_focus_target, m_edit_lead_target);
}

void Scheduler::planned() {
  m_focus_ahead = false;  // until the leading steps have visited the focus once
  m_lead_begun = false;
  m_lead_cursor = m_lead_end = 0;
  m_edit_lead_target = 0;
  m_edit_lead_at.reset();
  m_lead_at = std::min(m_policy->seeded_leading(m_renderer), m_leading);
  if (m_round_target) set_round_target(*m_round_target);
}

void Scheduler::begin_lead() {
  // The edit's and the focus's tiles have had their first visit (one visit first wherever the
  // stale image is wrong): the focus's among them now take their lead, before the rest of the
  // leading steps (after a camera edit every tile leads) and the rest of the round.
  m_lead_begun = true;
  m_focus_ahead = true;
  set_round_target(*m_round_target);
  m_lead_cursor = 0;
  m_lead_end = m_focus_target ? m_lead_at : 0;
}

uint32_t Scheduler::lead_step_tiles() const {
  // The edit's lead gives a tile's marked pixels several visits at once: fewer tiles per step
  // keep a step's work near a first visit's (the display is resolved, and a viewer presents,
  // after each step).
  if (m_edit_lead_target == 0 || m_edit_lead == 0) return m_tiles_per_step;
  return std::max(1u, m_tiles_per_step * m_first_visit_spp / (m_edit_lead * m_visit_spp));
}

void Scheduler::begin_edit_lead() {
  // The pixels that lead after the edit are brought to the lead target in a pass over the
  // leading entries that hold them (once per edit: the target stays, and the rounds pass it).
  m_edit_lead_at.reset();
  m_edit_lead_target = std::min(*m_round_target + m_edit_lead * m_visit_spp, m_converged_spp);
  set_round_target(*m_round_target);
  m_lead_cursor = 0;
  m_lead_end = m_lead_at;
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
  m_follows_focus = leading.has_value();
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
  m_edit_plan = false;
  planned();
  m_times.focus_seconds += timer.seconds();
}

double Scheduler::work_since_edit() const {
  return double(m_renderer.samples_since_reset()) / double(m_pixels);
}

}  // namespace hipr
