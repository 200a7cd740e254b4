#pragma once
#include <chrono>
#include <ctime>

namespace hipr {

class Timer {
 public:
  Timer() : m_start(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  }

 private:
  std::chrono::steady_clock::time_point m_start;
};

// CPU time of the whole process (every thread, the CPU device's workers included): on a shared
// machine it measures the work done, where wall time also measures the neighbours.
class CpuTimer {
 public:
  CpuTimer() : m_start(now()) {}
  double seconds() const { return now() - m_start; }

 private:
  static double now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
  }
  double m_start;
};

}  // namespace hipr
