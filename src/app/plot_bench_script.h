#pragma once
// tools/plot_bench.py, embedded at build time (cmake/embed_text.cmake) so `hipr bench` can plot
// from any folder.
#include <string_view>

namespace hipr::app {
std::string_view plot_bench_script();
}
