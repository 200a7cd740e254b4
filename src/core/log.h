#pragma once
// Minimal logging to stderr. Warnings are one line each and never stop the program.
#include <string>
#include <string_view>

namespace hipr::log {

// `text` as one line a terminal shows as it is: line breaks and tabs become spaces; control
// characters and bytes that are not valid UTF-8 (a mutated name in a broken file) become \xNN.
std::string printable_line(std::string_view text);

void warn(std::string_view message);
void info(std::string_view message);
// Silences info() (warnings still print); used by --quiet and by tests.
void set_quiet(bool quiet);

}  // namespace hipr::log
