#pragma once
// Error of the displayed image after each scheduling step, and what the benchmark summarises
// from it (docs/method.md#measuring-run-time-against-error).
#include <cstdint>
#include <vector>

namespace hipr::bench {

struct CurvePoint {
  uint32_t step = 0;     // 0: the moment of the edit (the stale image)
  double work = 0.0;     // full-frame 1-spp passes since the edit
  double wall_ms = 0.0;  // scheduling and rendering time since the edit (evaluation excluded)
  double relmse = 0.0;
  double flip = 0.0;
  double focus_relmse = -1.0;  // relMSE over the focus region's pixels; -1: no region measured
  double focus_flip = -1.0;    // FLIP over the focus region's pixels; -1: no region measured
};

using ErrorCurve = std::vector<CurvePoint>;

// Which error a summary reads.
enum class Metric { RelMse, Flip, FocusRelMse, FocusFlip };
double metric_of(const CurvePoint& point, Metric metric);

// Mean error over the first `horizon` work units after the edit. The image shown after point i
// stays on screen until point i + 1 (a step function of work); past the last point its error
// holds. Points must be in increasing work, starting at work 0.
double error_auc(const ErrorCurve& curve, Metric metric, double horizon);
// The same over the work interval [from, to] (to > from >= 0).
double error_mean(const ErrorCurve& curve, Metric metric, double from, double to);

}  // namespace hipr::bench
