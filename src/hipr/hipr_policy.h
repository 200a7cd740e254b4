#pragma once
// The HiPR policy (docs/method.md, "The method"): stage 1 marks the active tiles and orders them
// by change score; stage 2 renders them (the leading steps) and discovers where their light
// goes; stage 3 sorts the rest. It owns what the method adds to the scheduler's rounds: the
// focus's lead and the edit's lead (docs/method.md#focus, #the-edits-lead), steps of its own
// that bring those pixels ahead of the round, never past the converged count.
#include <cstdint>
#include <optional>

#include "hipr/hipr_stage_runner.h"
#include "hipr/scheduling_policy.h"

namespace hipr {

class HiprPolicy final : public SchedulingPolicy {
 public:
  // `given`: stages of another progressive renderer; none: hipr's, on the renderer's device
  // state (hipr_stages).
  explicit HiprPolicy(HiprStageRunner* given = nullptr) : m_given(given) {}

  Policy id() const override { return Policy::Hipr; }
  bool relights() const override { return true; }
  void set_reprojection(bool reproject) override { m_reprojection = reproject; }
  void start(ProgressiveRenderer& renderer) override;
  uint32_t plan(ProgressiveRenderer& renderer, const ChangeSet& changes) override;
  uint32_t render_leading(ProgressiveRenderer& renderer, uint32_t offset, uint32_t budget,
                          uint32_t samples_per_pixel, std::optional<DisplayRule> then_resolve,
                          const RoundState& round) override;
  void finish_leading(ProgressiveRenderer& renderer, const RoundState& round) override;
  std::optional<uint32_t> refocus(ProgressiveRenderer& renderer, const Focus& focus) override;

  void planned(ProgressiveRenderer& renderer, uint32_t leading, bool edit) override;
  void set_round_target(ProgressiveRenderer& renderer, const RoundState& round) override;
  bool lead_step(ProgressiveRenderer& renderer, const RoundState& round) override;
  bool lead_pending() const override { return m_lead_cursor < m_lead_end; }
  void round_ended() override { m_edit_lead_at.reset(); }

 private:
  HiprStageRunner& stages_of(ProgressiveRenderer& renderer);
  // The leading steps have passed the scored entries: the focus's lead steps come next.
  void begin_lead(ProgressiveRenderer& renderer, const RoundState& round);
  // The first round reached the tiles after the discovered ones: the edit's lead steps come next.
  void begin_edit_lead(ProgressiveRenderer& renderer, const RoundState& round);
  // Tiles per lead step.
  uint32_t lead_step_tiles(const RoundState& round) const;

  HiprStageRunner* m_given;
  bool m_reprojection = true;
  bool m_follows_focus = false;  // a focus was set: its tiles may run ahead
  bool m_focus_ahead = false;  // the focus's tiles are brought to their lead (after a first visit)
  uint32_t m_lead_at = 0;      // leading entries [0, m_lead_at) hold the edit's and focus's tiles
  bool m_lead_begun = false;   // the leading steps have passed them
  uint32_t m_lead_cursor = 0,
           m_lead_end = 0;          // the lead pass over schedule entries [0, m_lead_end)
  uint32_t m_focus_target = 0;      // what the focus's tiles are brought to (0: the round target)
  uint32_t m_edit_lead_target = 0;  // what the pixels that lead after the edit are brought to
  std::optional<uint32_t> m_edit_lead_at;  // the schedule entry before which the edit's lead runs
  bool m_edit_plan = false;                // the last plan was an edit's (not a new focus's)
};

}  // namespace hipr
