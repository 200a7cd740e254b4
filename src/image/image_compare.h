#pragma once
// Comparing two images, for screenshot-regression suites (`hipr compare`): one number in the
// chosen metric, and where the images differ (per-pixel error, pixels over the threshold and
// their bounding box). A non-finite value in either image is always a difference.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/error_metrics.h"
#include "image/image_io.h"

namespace hipr {

enum class CompareMetric {
  Flip,    // mean LDR-FLIP (perceptual, after the project's tone mapping); per pixel: the FLIP map
  RelMse,  // mean (a - b)^2 / (b^2 + 0.01) / 2 over pixels and channels (b: the second image)
  Rmse,    // root mean square of a - b; per pixel: over its channels
  Max,     // largest |a - b| of any channel; per pixel: over its channels
};

CompareMetric parse_compare_metric(const std::string& name);  // throws InputError
std::string compare_metric_name(CompareMetric metric);

struct PixelBox {
  uint32_t x0, y0, x1, y1;  // inclusive
};

struct ImageComparison {
  double value = 0.0;  // the metric over the whole image (infinite with a non-finite pixel)
  std::vector<float> pixel_error;  // per pixel, in the metric's units (infinite where non-finite)
  uint64_t pixels_over = 0;        // pixels whose error exceeds the threshold
  uint64_t nonfinite_pixels = 0;   // pixels with a NaN or infinite value in either image
  std::optional<PixelBox> box;     // bounding box of the pixels over the threshold
  bool within(double threshold) const { return nonfinite_pixels == 0 && value <= threshold; }
};

// Throws InputError when the sizes differ. With `percentile` (in (0, 100]) the value is that
// percentile of the per-pixel errors (nearest rank) instead of the metric over the whole image:
// a mean lets a handful of wrong pixels pass, the 99.9th percentile does not. `flip`: FLIP's
// display transform (exposure, tone mapper) and viewing setup.
ImageComparison compare_images(const ImageRGB& a, const ImageRGB& b, CompareMetric metric,
                               double threshold, std::optional<double> percentile = std::nullopt,
                               const FlipOptions& flip = {});

// The nearest-rank `percentile` (in (0, 100]) of `values`; 0 for none.
double nearest_rank_percentile(std::vector<float> values, double percentile);

}  // namespace hipr
