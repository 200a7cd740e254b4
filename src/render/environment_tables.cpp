#include "render/environment_tables.h"

#include <cmath>

namespace hipr {

std::vector<float> build_environment_buffer(const Environment& env) {
  const size_t w = env.width, h = env.height;
  std::vector<float> out;
  out.reserve(3 * w * h + (h + 1) + h * (w + 1));
  for (const glm::vec3& c : env.texels) out.insert(out.end(), {c.x, c.y, c.z});

  std::vector<double> weight(w * h);
  double total = 0.0;
  for (size_t y = 0; y < h; ++y) {
    const double s = std::sin((double(y) + 0.5) / double(h) * M_PI);
    for (size_t x = 0; x < w; ++x) {
      const glm::vec3& c = env.texels[y * w + x];
      weight[y * w + x] = s * (0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z);
      total += weight[y * w + x];
    }
  }
  if (!(total > 0.0)) {
    for (size_t y = 0; y < h; ++y)
      for (size_t x = 0; x < w; ++x)
        weight[y * w + x] = std::sin((double(y) + 0.5) / double(h) * M_PI);
  }

  std::vector<double> row_sum(h, 0.0);
  for (size_t y = 0; y < h; ++y)
    for (size_t x = 0; x < w; ++x) row_sum[y] += weight[y * w + x];
  double all = 0.0;
  for (double r : row_sum) all += r;

  double running = 0.0;
  out.push_back(0.0f);
  for (size_t y = 0; y < h; ++y) {
    running += row_sum[y];
    out.push_back(y + 1 == h ? 1.0f : float(running / all));
  }
  for (size_t y = 0; y < h; ++y) {
    double row_running = 0.0;
    out.push_back(0.0f);
    for (size_t x = 0; x < w; ++x) {
      row_running += weight[y * w + x];
      const float value =
          row_sum[y] > 0.0 ? float(row_running / row_sum[y]) : float(x + 1) / float(w);
      out.push_back(x + 1 == w ? 1.0f : value);
    }
  }
  return out;
}

}  // namespace hipr
