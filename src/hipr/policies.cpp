// The scheduling policies hipr ships (the oracle is hipr bench's: src/bench/oracle_policy.cpp)
// and the factory that makes them by name.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/error.h"
#include "hipr/hipr_policy.h"
#include "hipr/scheduling_policy.h"

namespace hipr {

const std::vector<Policy>& all_policies() {
  static const std::vector<Policy> list = {Policy::Hipr,   Policy::Full,   Policy::Scanline,
                                           Policy::Spiral, Policy::Random, Policy::Oracle};
  return list;
}

Policy parse_policy(const std::string& name) {
  for (Policy p : all_policies())
    if (policy_name(p) == name) return p;
  throw InputError("unknown policy '" + name + "' (hipr, full, scanline, spiral, random, oracle)");
}

std::string policy_name(Policy policy) {
  switch (policy) {
    case Policy::Hipr:
      return "hipr";
    case Policy::Full:
      return "full";
    case Policy::Scanline:
      return "scanline";
    case Policy::Spiral:
      return "spiral";
    case Policy::Random:
      return "random";
    case Policy::Oracle:
      return "oracle";
  }
  return "?";
}

DisplayRule default_display_rule(Policy policy) {
  return policy == Policy::Hipr || policy == Policy::Oracle ? DisplayRule::Difference
                                                            : DisplayRule::Immediate;
}

std::vector<uint32_t> tile_order(Policy policy, uint32_t tiles_x, uint32_t tiles_y, uint32_t seed) {
  std::vector<uint32_t> order(size_t(tiles_x) * tiles_y);
  std::iota(order.begin(), order.end(), 0u);
  if (policy == Policy::Random) {
    std::mt19937 rng(seed);
    std::shuffle(order.begin(), order.end(), rng);
  } else if (policy == Policy::Spiral) {
    // Outward from the centre: by distance, then by angle, as bucket renderers spiral.
    const double cx = (tiles_x - 1) * 0.5, cy = (tiles_y - 1) * 0.5;
    const auto key = [&](uint32_t t) {
      const double dx = double(t % tiles_x) - cx, dy = double(t / tiles_x) - cy;
      return std::make_pair(std::max(std::abs(dx), std::abs(dy)), std::atan2(dy, dx));
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
  }
  return order;
}

namespace {

// Full-frame restart, as full-frame progressive viewers do.
class FullPolicy final : public SchedulingPolicy {
 public:
  Policy id() const override { return Policy::Full; }
  bool whole_passes() const override { return true; }
  uint32_t plan(ProgressiveRenderer& renderer, const ChangeSet&) override {
    const TileGrid grid = renderer.tile_grid();
    renderer.set_schedule(tile_order(Policy::Full, grid.tiles_x, grid.tiles_y, grid.seed));
    return 0;
  }
};

// A fixed bucket order (scanline, spiral, random), each tile shown as soon as it is rendered.
class BucketOrderPolicy final : public SchedulingPolicy {
 public:
  explicit BucketOrderPolicy(Policy order) : m_order(order) {}
  Policy id() const override { return m_order; }
  uint32_t plan(ProgressiveRenderer& renderer, const ChangeSet&) override {
    const TileGrid grid = renderer.tile_grid();
    renderer.set_schedule(tile_order(m_order, grid.tiles_x, grid.tiles_y, grid.seed));
    return 0;
  }

 private:
  Policy m_order;
};

}  // namespace

std::unique_ptr<SchedulingPolicy> make_policy(Policy policy) {
  switch (policy) {
    case Policy::Hipr:
      return std::make_unique<HiprPolicy>();
    case Policy::Full:
      return std::make_unique<FullPolicy>();
    case Policy::Scanline:
    case Policy::Spiral:
    case Policy::Random:
      return std::make_unique<BucketOrderPolicy>(policy);
    case Policy::Oracle:
      break;
  }
  throw InputError("the oracle policy needs a reference image: use hipr bench");
}

}  // namespace hipr
