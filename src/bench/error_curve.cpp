#include "bench/error_curve.h"

#include <algorithm>

#include "core/error.h"

namespace hipr::bench {

double metric_of(const CurvePoint& point, Metric metric) {
  switch (metric) {
    case Metric::RelMse:
      return point.relmse;
    case Metric::Flip:
      return point.flip;
    case Metric::FocusRelMse:
      return point.focus_relmse;
    case Metric::FocusFlip:
      return point.focus_flip;
  }
  return point.relmse;
}

double error_auc(const ErrorCurve& curve, Metric metric, double horizon) {
  if (!(horizon > 0.0)) throw InternalError("an error AUC needs a positive horizon");
  return error_mean(curve, metric, 0.0, horizon);
}

double error_mean(const ErrorCurve& curve, Metric metric, double from, double to) {
  if (curve.empty() || curve.front().work != 0.0)
    throw InternalError("an error curve starts at the edit (work 0)");
  if (!(to > from) || from < 0.0) throw InternalError("an error mean needs an interval of work");
  double area = 0.0;
  for (size_t i = 0; i < curve.size(); ++i) {
    const double start = std::clamp(curve[i].work, from, to);
    const double end = i + 1 < curve.size() ? std::clamp(curve[i + 1].work, from, to) : to;
    if (end < start) throw InternalError("an error curve's work must not decrease");
    area += metric_of(curve[i], metric) * (end - start);
  }
  return area / (to - from);
}

}  // namespace hipr::bench
