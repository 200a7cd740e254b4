#include "hipr/hipr_policy.h"

#include <algorithm>

#include "hipr/hipr_stages.h"

namespace hipr {

HiprStageRunner& HiprPolicy::stages_of(ProgressiveRenderer& renderer) {
  return m_given ? *m_given : static_cast<HiprStageRunner&>(hipr_stages(renderer));
}

void HiprPolicy::start(ProgressiveRenderer& renderer) {
  HiprStageRunner& stages = stages_of(renderer);
  stages.set_focus({});  // the stages outlive schedulers: no focus of an earlier one stays
  stages.stage1_visibility({});
}

uint32_t HiprPolicy::plan(ProgressiveRenderer& renderer, const ChangeSet& changes) {
  HiprStageRunner& stages = stages_of(renderer);
  stages.set_reprojection(m_reprojection);
  const uint32_t active = stages.stage1_visibility(changes);
  stages.build_schedule();  // active tiles first, by change score: the order of stage 2
  return active;
}

uint32_t HiprPolicy::render_leading(ProgressiveRenderer& renderer, uint32_t offset, uint32_t budget,
                                    uint32_t samples_per_pixel,
                                    std::optional<DisplayRule> then_resolve,
                                    const RoundState& round) {
  // A step stops where the scored tiles end, so the focus's lead starts right after them.
  uint32_t count = budget;
  if (!m_lead_begun && m_lead_at > offset) count = std::min(count, m_lead_at - offset);
  stages_of(renderer).stage2_discover(offset, count, samples_per_pixel, then_resolve);
  if (!m_lead_begun && offset + count >= m_lead_at) begin_lead(renderer, round);
  return count;
}

void HiprPolicy::finish_leading(ProgressiveRenderer& renderer, const RoundState& round) {
  HiprStageRunner& stages = stages_of(renderer);
  stages.build_schedule();
  // The edit's lead comes once the tiles stage 2 discovered had their first visit too.
  if (m_edit_plan && round.edit_lead > 0 && round.converged_spp > round.target &&
      stages.lead_tiles() > 0)
    m_edit_lead_at = round.cursor + stages.discovered_tiles();
}

// The focus is a changed set for ordering only: stage 1 marks where it is seen (after what an
// edit left unrendered), stage 2 discovers from there, stage 3 orders the rest outward.
std::optional<uint32_t> HiprPolicy::refocus(ProgressiveRenderer& renderer, const Focus& focus) {
  HiprStageRunner& stages = stages_of(renderer);
  stages.set_focus(focus);
  const uint32_t active = stages.stage1_focus();
  stages.build_schedule();
  m_follows_focus = true;
  return active;
}

void HiprPolicy::planned(ProgressiveRenderer& renderer, uint32_t leading, bool edit) {
  m_focus_ahead = false;  // until the leading steps have visited the focus once
  m_lead_begun = false;
  m_lead_cursor = m_lead_end = 0;
  m_edit_lead_target = 0;
  m_edit_lead_at.reset();
  m_edit_plan = edit;
  m_lead_at = std::min(stages_of(renderer).seeded_tiles(), leading);
}

void HiprPolicy::set_round_target(ProgressiveRenderer& renderer, const RoundState& round) {
  // The focus runs ahead by whole visits, up to the converged count (never past it: the work
  // since the edit would then reach it before every pixel has).
  m_focus_target = 0;
  if (m_focus_ahead && m_follows_focus && round.focus_set && round.focus_lead > 0 &&
      round.converged_spp > round.target)
    m_focus_target =
        std::min(round.target + round.focus_lead * round.visit_spp, round.converged_spp);
  renderer.set_sample_target(round.target, m_focus_target, m_edit_lead_target);
}

bool HiprPolicy::lead_step(ProgressiveRenderer& renderer, const RoundState& round) {
  if (m_edit_lead_at && !lead_pending() && !round.leading_pending &&
      round.cursor >= *m_edit_lead_at)
    begin_edit_lead(renderer, round);
  if (!lead_pending()) return false;
  const uint32_t count = std::min(lead_step_tiles(round), m_lead_end - m_lead_cursor);
  renderer.render_lead(m_lead_cursor, count, round.display);
  m_lead_cursor += count;
  return true;
}

void HiprPolicy::begin_lead(ProgressiveRenderer& renderer, const RoundState& round) {
  // The edit's and the focus's tiles have had their first visit (one visit first wherever the
  // stale image is wrong): the focus's among them now take their lead, before the rest of the
  // leading steps (after a camera edit every tile leads) and the rest of the round.
  m_lead_begun = true;
  m_focus_ahead = true;
  set_round_target(renderer, round);
  m_lead_cursor = 0;
  m_lead_end = m_focus_target ? m_lead_at : 0;
}

uint32_t HiprPolicy::lead_step_tiles(const RoundState& round) const {
  // The edit's lead gives a tile's marked pixels several visits at once: fewer tiles per step
  // keep a step's work near a first visit's (the display is resolved, and a viewer presents,
  // after each step).
  if (m_edit_lead_target == 0 || round.edit_lead == 0) return round.tiles_per_step;
  return std::max(
      1u, round.tiles_per_step * round.first_visit_spp / (round.edit_lead * round.visit_spp));
}

void HiprPolicy::begin_edit_lead(ProgressiveRenderer& renderer, const RoundState& round) {
  // The pixels that lead after the edit are brought to the lead target in a pass over the
  // leading entries that hold them (once per edit: the target stays, and the rounds pass it).
  m_edit_lead_at.reset();
  m_edit_lead_target =
      std::min(round.target + round.edit_lead * round.visit_spp, round.converged_spp);
  set_round_target(renderer, round);
  m_lead_cursor = 0;
  m_lead_end = m_lead_at;
}

std::unique_ptr<SchedulingPolicy> make_hipr_policy(HiprStageRunner& stages) {
  return std::make_unique<HiprPolicy>(&stages);
}

}  // namespace hipr
