#include "image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "image/error_metrics.h"

namespace hipr {
namespace {

bool finite_pixel(const ImageRGB& image, size_t i) {
  return std::isfinite(image.rgb[i * 3]) && std::isfinite(image.rgb[i * 3 + 1]) &&
         std::isfinite(image.rgb[i * 3 + 2]);
}

// A copy whose non-finite values are 0, so FLIP's filters do not spread them over neighbours
// (those pixels count on their own as differences).
ImageRGB finite_copy(const ImageRGB& image) {
  ImageRGB copy = image;
  for (float& v : copy.rgb)
    if (!std::isfinite(v)) v = 0.0f;
  return copy;
}

}  // namespace

CompareMetric parse_compare_metric(const std::string& name) {
  for (CompareMetric m :
       {CompareMetric::Flip, CompareMetric::RelMse, CompareMetric::Rmse, CompareMetric::Max})
    if (compare_metric_name(m) == name) return m;
  throw InputError("unknown metric '" + name + "' (flip, relmse, rmse, max)");
}

std::string compare_metric_name(CompareMetric metric) {
  switch (metric) {
    case CompareMetric::Flip:
      return "flip";
    case CompareMetric::RelMse:
      return "relmse";
    case CompareMetric::Rmse:
      return "rmse";
    case CompareMetric::Max:
      return "max";
  }
  return "?";
}

double nearest_rank_percentile(std::vector<float> values, double percentile) {
  if (values.empty()) return 0.0;
  const double rank = std::ceil(percentile / 100.0 * double(values.size()));
  const size_t k = size_t(std::clamp(rank, 1.0, double(values.size()))) - 1;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

ImageComparison compare_images(const ImageRGB& a, const ImageRGB& b, CompareMetric metric,
                               double threshold, std::optional<double> percentile,
                               const FlipOptions& flip) {
  if (a.width != b.width || a.height != b.height)
    throw InputError("the images differ in size: " + std::to_string(a.width) + "x" +
                     std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                     std::to_string(b.height));
  const size_t pixels = size_t(a.width) * a.height;
  if (a.rgb.size() != pixels * 3 || b.rgb.size() != pixels * 3)
    throw InternalError("an image without 3 channels");
  ImageComparison result;
  result.pixel_error.assign(pixels, 0.0f);
  double sum = 0.0, peak = 0.0;
  if (metric == CompareMetric::Flip) {
    result.pixel_error = flip_error_map(finite_copy(a), finite_copy(b), flip);
    for (float e : result.pixel_error) sum += e;
  } else {
    for (size_t i = 0; i < pixels; ++i) {
      double pixel = 0.0;
      for (size_t c = 0; c < 3; ++c) {
        const double x = a.rgb[i * 3 + c], y = b.rgb[i * 3 + c], d = x - y;
        if (metric == CompareMetric::RelMse)
          pixel += d * d / (y * y + 0.01) / 2.0 / 3.0;
        else if (metric == CompareMetric::Rmse)
          pixel += d * d / 3.0;
        else
          pixel = std::max(pixel, std::abs(d));
      }
      sum += pixel;
      peak = std::max(peak, pixel);
      result.pixel_error[i] = float(metric == CompareMetric::Rmse ? std::sqrt(pixel) : pixel);
    }
  }
  result.value = metric == CompareMetric::Max    ? peak
                 : metric == CompareMetric::Rmse ? std::sqrt(pixels ? sum / double(pixels) : 0.0)
                                                 : (pixels ? sum / double(pixels) : 0.0);
  for (size_t i = 0; i < pixels; ++i) {
    if (!finite_pixel(a, i) || !finite_pixel(b, i)) {
      ++result.nonfinite_pixels;
      result.pixel_error[i] = std::numeric_limits<float>::infinity();
    }
    if (!(result.pixel_error[i] > threshold)) continue;
    ++result.pixels_over;
    const uint32_t x = uint32_t(i % a.width), y = uint32_t(i / a.width);
    if (!result.box) result.box = PixelBox{x, y, x, y};
    result.box->x0 = std::min(result.box->x0, x);
    result.box->y0 = std::min(result.box->y0, y);
    result.box->x1 = std::max(result.box->x1, x);
    result.box->y1 = std::max(result.box->y1, y);
  }
  if (percentile) result.value = nearest_rank_percentile(result.pixel_error, *percentile);
  if (result.nonfinite_pixels) result.value = std::numeric_limits<double>::infinity();
  return result;
}

}  // namespace hipr
