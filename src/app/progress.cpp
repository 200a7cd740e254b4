#include "app/progress.h"

#include <cstdio>

#include <unistd.h>

namespace hipr::app {

ProgressBar::ProgressBar(uint64_t total, bool enabled)
    : m_total(total == 0 ? 1 : total), m_enabled(enabled && isatty(STDERR_FILENO)) {}

void ProgressBar::update(uint64_t done, double elapsed) {
  if (!m_enabled) return;
  constexpr int kWidth = 32;
  const double fraction = double(done) / double(m_total);
  const int filled = int(fraction * kWidth);
  char bar[kWidth + 1];
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kWidth] = '\0';
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r[%s] %3d%%  %.1fs elapsed, %.1fs left ", bar, int(fraction * 100.0),
               elapsed, eta);
  std::fflush(stderr);
  m_drawn = true;
}

void ProgressBar::finish() {
  if (m_drawn) std::fprintf(stderr, "\n");
  m_drawn = false;
}

}  // namespace hipr::app
