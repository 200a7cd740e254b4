#pragma once
// Minimal logging to stderr. Warnings are one line each and never stop the program.
#include <string_view>

namespace hipr::log {

void warn(std::string_view message);
void info(std::string_view message);
// Silences info() (warnings still print); used by --quiet and by tests.
void set_quiet(bool quiet);

}  // namespace hipr::log
