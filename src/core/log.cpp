#include "core/log.h"

#include <atomic>
#include <cstdio>

namespace hipr::log {
namespace {
std::atomic<bool> g_quiet{false};
}

void warn(std::string_view message) {
  std::fprintf(stderr, "hipr: warning: %.*s\n", int(message.size()), message.data());
}

void info(std::string_view message) {
  if (!g_quiet) std::fprintf(stderr, "hipr: %.*s\n", int(message.size()), message.data());
}

void set_quiet(bool quiet) { g_quiet = quiet; }

}  // namespace hipr::log
