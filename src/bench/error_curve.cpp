#include "bench/error_curve.h"

#include <algorithm>

#include "core/error.h"

namespace hipr::bench {

double metric_of(const CurvePoint& point, Metric metric) {
  return metric == Metric::RelMse ? point.relmse : point.flip;
}

double error_auc(const ErrorCurve& curve, Metric metric, double horizon) {
  if (curve.empty() || curve.front().work != 0.0)
    throw InternalError("an error curve starts at the edit (work 0)");
  if (!(horizon > 0.0)) throw InternalError("an error AUC needs a positive horizon");
  double area = 0.0;
  for (size_t i = 0; i < curve.size(); ++i) {
    const double start = std::min(curve[i].work, horizon);
    const double end = i + 1 < curve.size() ? std::min(curve[i + 1].work, horizon) : horizon;
    if (end < start) throw InternalError("an error curve's work must not decrease");
    area += metric_of(curve[i], metric) * (end - start);
  }
  return area / horizon;
}

}  // namespace hipr::bench
