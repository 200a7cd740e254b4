#pragma once
#include <cstdint>

namespace hipr::app {

// A one-line progress bar on stderr, drawn only when stderr is a terminal.
class ProgressBar {
 public:
  explicit ProgressBar(uint64_t total, bool enabled = true);
  void update(uint64_t done, double elapsed_seconds);
  void finish();

 private:
  uint64_t m_total;
  bool m_enabled;
  bool m_drawn = false;
};

}  // namespace hipr::app
