// The scheduling policies hipr ships (the oracle is hipr bench's: src/bench/oracle_policy.cpp)
// and the factory that makes them by name.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "core/error.h"
#include "hipr/hipr_stages.h"
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

// The paper: stage 1 marks the active tiles and orders them by change score; stage 2 renders
// them (the leading steps) and discovers where their light goes; stage 3 sorts the rest.
class HiprPolicy final : public SchedulingPolicy {
 public:
  // `given`: stages of another progressive renderer; none: hipr's, on the renderer's device state.
  explicit HiprPolicy(HiprStageRunner* given = nullptr) : m_given(given) {}
  Policy id() const override { return Policy::Hipr; }
  bool relights() const override { return true; }
  void set_reprojection(bool reproject) override { m_reprojection = reproject; }
  void start(ProgressiveRenderer& renderer) override {
    HiprStageRunner& stages = stages_of(renderer);
    stages.set_focus({});  // the stages outlive schedulers: no focus of an earlier one stays
    stages.stage1_visibility({});
  }
  uint32_t plan(ProgressiveRenderer& renderer, const ChangeSet& changes) override {
    HiprStageRunner& stages = stages_of(renderer);
    stages.set_reprojection(m_reprojection);
    const uint32_t active = stages.stage1_visibility(changes);
    stages.build_schedule();  // active tiles first, by change score: the order of stage 2
    return active;
  }
  void render_leading(ProgressiveRenderer& renderer, uint32_t offset, uint32_t count,
                      uint32_t samples_per_pixel,
                      std::optional<DisplayRule> then_resolve) override {
    stages_of(renderer).stage2_discover(offset, count, samples_per_pixel, then_resolve);
  }
  void finish_leading(ProgressiveRenderer& renderer) override {
    stages_of(renderer).build_schedule();
  }
  uint32_t seeded_leading(ProgressiveRenderer& renderer) override {
    return stages_of(renderer).seeded_tiles();
  }
  uint32_t lead_tiles(ProgressiveRenderer& renderer) override {
    return stages_of(renderer).lead_tiles();
  }
  uint32_t discovered_entries(ProgressiveRenderer& renderer) override {
    return stages_of(renderer).discovered_tiles();
  }
  // The focus is a changed set for ordering only: stage 1 marks where it is seen (after what
  // an edit left unrendered), stage 2 discovers from there, stage 3 orders the rest outward.
  std::optional<uint32_t> refocus(ProgressiveRenderer& renderer, const Focus& focus) override {
    HiprStageRunner& stages = stages_of(renderer);
    stages.set_focus(focus);
    const uint32_t active = stages.stage1_focus();
    stages.build_schedule();
    return active;
  }

 private:
  HiprStageRunner& stages_of(ProgressiveRenderer& renderer) {
    return m_given ? *m_given : static_cast<HiprStageRunner&>(hipr_stages(renderer));
  }

  HiprStageRunner* m_given;
  bool m_reprojection = true;
};

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

std::unique_ptr<SchedulingPolicy> make_hipr_policy(HiprStageRunner& stages) {
  return std::make_unique<HiprPolicy>(&stages);
}

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
