#pragma once
// How the re-render after an edit is scheduled. Every setting is declared once, here: its field,
// its flag, its help and its range (for_each_schedule_setting). The commands' flags
// (src/app/schedule_flags.cpp), the viewer's HiPR panel and the benchmark's runs are all bound
// from this one declaration, and the scheduler takes the settings at once
// (Scheduler::configure): a setting cannot be wired in one place and forgotten in another.
#include <cstdint>
#include <optional>

#include "hipr/display_rule.h"
#include "hipr/scheduling_policy.h"

namespace hipr {

// Visits the focus's tiles run ahead of the round unless set (Scheduler::set_focus_lead).
inline constexpr uint32_t kDefaultFocusLead = 3;
// Visits the pixels that lead after an edit get before the rest of the round unless set
// (Scheduler::set_edit_lead).
inline constexpr uint32_t kDefaultEditLead = 6;

struct ScheduleSettings {
  Policy policy = Policy::Hipr;
  std::optional<DisplayRule> display;  // none: the policy's own (default_display_rule)
  uint32_t tiles_per_step = 0;  // 0: the command's default (a sixteenth of the frame; view: 1/64)
  uint32_t visit_spp = 1;
  // Samples of a tile's first visit after an edit (not for `full`); 0: the command's default
  // (replay: visit_spp; bench: 2; view: what the display rule needs, default_first_visit_spp).
  uint32_t first_visit_spp = 0;
  bool relight = true;    // relighting by linearity at light edits (policies that relight: hipr)
  bool reproject = true;  // reprojection at camera edits (hipr's stage 1)
  uint32_t focus_lead = kDefaultFocusLead;
  uint32_t edit_lead = kDefaultEditLead;

  bool operator==(const ScheduleSettings&) const = default;
};

// One setting's declaration.
struct ScheduleSettingInfo {
  const char* name;  // the field, and the viewer panel's label
  const char* flag;  // the commands' flag; a bool's flag turns it off (--no-relight)
  const char* help;  // the flag's help and the panel's tooltip
  bool live = true;  // the viewer's panel changes it while rendering (false: a start-up flag only)
  uint32_t min = 0, max = 0;  // numbers: the range the panel offers
};

// Calls `visit(info, field)` for every setting, in the order help and panel list them.
// `Settings` is ScheduleSettings or const ScheduleSettings.
template <typename Settings, typename Visitor>
void for_each_schedule_setting(Settings& s, Visitor&& visit) {
  visit(ScheduleSettingInfo{"policy", "--policy", "hipr, full, scanline, spiral or random"},
        s.policy);
  visit(
      ScheduleSettingInfo{
          "display rule", "--display",
          "How re-rendered tiles are shown: immediate, switch, blend or difference (default: "
          "difference for hipr, immediate for the others)"},
      s.display);
  visit(
      ScheduleSettingInfo{
          "tiles per step", "--tiles-per-step",
          "Tiles rendered per step (default: a sixteenth of the frame; view: a sixty-fourth)",
          false},
      s.tiles_per_step);
  visit(ScheduleSettingInfo{"visit spp", "--visit-spp", "Samples per pixel a tile gets per visit",
                            false, 1, 64},
        s.visit_spp);
  visit(
      ScheduleSettingInfo{
          "first visit spp", "--first-visit-spp",
          "Samples per pixel of a tile's first visit after an edit (default: --visit-spp; "
          "bench: 2; view: 2 where the display rule weighs estimates)",
          false},
      s.first_visit_spp);
  visit(
      ScheduleSettingInfo{
          "relight light edits", "--no-relight",
          "hipr: an edit of a light's intensity or colour shows the converged image relit at "
          "once (the flag turns it off: light edits are only re-rendered)"},
      s.relight);
  visit(
      ScheduleSettingInfo{
          "reproject camera moves", "--no-reproject",
          "hipr: after a camera move the image before it stays where the same surface is "
          "seen (the flag turns it off: camera moves restart the image)"},
      s.reproject);
  visit(
      ScheduleSettingInfo{
          "focus lead", "--focus-lead",
          "Visits the focus's tiles run ahead of the rest (0: the focus only orders)", true, 0, 16},
      s.focus_lead);
  visit(
      ScheduleSettingInfo{
          "edit lead", "--edit-lead",
          "Visits the pixels that show what an edit moved (or a surface they no longer see) get "
          "ahead of the rest (0: none)",
          true, 0, 16},
      s.edit_lead);
}

}  // namespace hipr
