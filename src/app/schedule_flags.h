#pragma once
// The scheduling settings' flags, bound from their one declaration (hipr/schedule_settings.h)
// for every command that schedules re-renders (replay, bench, view).
#include <CLI/CLI.hpp>

#include <set>
#include <string>

#include "hipr/schedule_settings.h"

namespace hipr::app {

// Adds a flag for every setting but those named in `except` (bench: "policy", which it lists
// as --policies). Values are checked as they are parsed: an unknown policy or display rule is
// a parse error.
void add_schedule_flags(CLI::App& cmd, ScheduleSettings& settings,
                        const std::set<std::string>& except = {});

}  // namespace hipr::app
