#include "bench/oracle_policy.h"

#include <algorithm>
#include <numeric>

#include "image/error_metrics.h"

namespace hipr::bench {

uint32_t OraclePolicy::plan(ProgressiveRenderer& renderer, const ChangeSet&) {
  renderer.refresh_gbuffer();
  // Tiles by descending error of what they show against the reference (ties in id order).
  const std::vector<double> error =
      relmse_tile_sums(renderer.displayed_image(), m_reference, renderer.tile_grid().tile_size);
  std::vector<uint32_t> order(error.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return error[a] > error[b]; });
  renderer.set_schedule(order);
  return 0;
}

std::unique_ptr<SchedulingPolicy> make_bench_policy(Policy policy, const ImageRGB& reference) {
  if (policy == Policy::Oracle) return std::make_unique<OraclePolicy>(reference);
  return make_policy(policy);
}

}  // namespace hipr::bench
