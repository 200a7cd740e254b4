#include "render/bvh_builder.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hipr {
namespace {

constexpr int kBins = 16;
constexpr float kTraversalCost = 1.0f;  // relative to one item test

struct Builder {
  const std::vector<Box>& boxes;
  std::vector<glm::vec3> centres;
  Bvh bvh;

  void make_leaf(abi::BvhNode& node, uint32_t begin, uint32_t end) {
    node.first = begin;
    node.count = abi::kBvhLeaf | (end - begin);
  }

  // Bounds of items [begin, end) into nodes[index], then splits it (or makes it a leaf).
  void build(uint32_t index, uint32_t begin, uint32_t end, uint32_t depth) {
    Box bounds, centre_bounds;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.grow(boxes[bvh.order[i]]);
      centre_bounds.grow(centres[bvh.order[i]]);
    }
    bvh.nodes[index].lo = bounds.lo;
    bvh.nodes[index].hi = bounds.hi;
    const uint32_t count = end - begin;
    if (count <= 1 || depth >= abi::kBvhMaxDepth) return make_leaf(bvh.nodes[index], begin, end);

    const glm::vec3 extent = centre_bounds.hi - centre_bounds.lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    uint32_t middle = begin;
    if (extent[axis] > 0.0f) {
      // Binned SAH along the widest axis of the centres.
      std::array<Box, kBins> bin_box;
      std::array<uint32_t, kBins> bin_count{};
      // In double, and NaN to bin 0: boxes too large for float arithmetic (scenes refuse them, see
      // scene/scene_limits.h) must still never index out of the bins.
      const double lo = centre_bounds.lo[axis], width = double(centre_bounds.hi[axis]) - lo;
      const auto bin_of = [&](uint32_t item) {
        const double t = (double(centres[item][axis]) - lo) / width * double(kBins);
        return t >= 0.0 ? int(std::min(t, double(kBins - 1))) : 0;
      };
      for (uint32_t i = begin; i < end; ++i) {
        const int b = bin_of(bvh.order[i]);
        bin_count[b] += 1;
        bin_box[b].grow(boxes[bvh.order[i]]);
      }
      std::array<float, kBins - 1> right_cost{};
      Box right;
      uint32_t right_items = 0;
      for (int b = kBins - 1; b > 0; --b) {
        right.grow(bin_box[b]);
        right_items += bin_count[b];
        right_cost[b - 1] = right.half_area() * float(right_items);
      }
      Box left;
      uint32_t left_items = 0;
      float best_cost = 3.0e38f;
      int best_split = -1;
      for (int b = 0; b < kBins - 1; ++b) {
        left.grow(bin_box[b]);
        left_items += bin_count[b];
        if (left_items == 0 || left_items == count) continue;
        const float cost = left.half_area() * float(left_items) + right_cost[b];
        if (cost < best_cost) {
          best_cost = cost;
          best_split = b;
        }
      }
      const float leaf_cost = bounds.half_area() * float(count);
      const float split_cost = kTraversalCost * bounds.half_area() + best_cost;
      if (count <= kBvhMaxLeafItems && (best_split < 0 || split_cost >= leaf_cost))
        return make_leaf(bvh.nodes[index], begin, end);
      if (best_split >= 0) {
        middle =
            uint32_t(std::partition(bvh.order.begin() + begin, bvh.order.begin() + end,
                                    [&](uint32_t item) { return bin_of(item) <= best_split; }) -
                     bvh.order.begin());
      }
    }
    if (middle == begin || middle == end) {
      // Centres that coincide (or one bin holding them all): halves by position in the order.
      if (count <= kBvhMaxLeafItems) return make_leaf(bvh.nodes[index], begin, end);
      middle = begin + count / 2;
      std::nth_element(bvh.order.begin() + begin, bvh.order.begin() + middle,
                       bvh.order.begin() + end, [&](uint32_t a, uint32_t b) {
                         return centres[a][axis] < centres[b][axis] ||
                                (centres[a][axis] == centres[b][axis] && a < b);
                       });
    }
    const uint32_t left_child = uint32_t(bvh.nodes.size());
    bvh.nodes.resize(bvh.nodes.size() + 2);
    bvh.nodes[index].first = left_child;
    bvh.nodes[index].count = 0;
    build(left_child, begin, middle, depth + 1);
    build(left_child + 1, middle, end, depth + 1);
  }
};

}  // namespace

float Box::half_area() const {
  if (empty()) return 0.0f;
  const glm::vec3 d = hi - lo;
  return d.x * d.y + d.y * d.z + d.z * d.x;
}

Bvh build_bvh(const std::vector<Box>& boxes) {
  Builder builder{boxes, {}, {}};
  builder.centres.reserve(boxes.size());
  for (const Box& b : boxes) {
    // Halves first: lo + hi overflows for boxes near the float range; NaN centres would break
    // the ordering the median split relies on.
    glm::vec3 centre = 0.5f * b.lo + 0.5f * b.hi;
    for (int axis = 0; axis < 3; ++axis)
      if (std::isnan(centre[axis])) centre[axis] = 0.0f;
    builder.centres.push_back(centre);
  }
  builder.bvh.order.resize(boxes.size());
  for (uint32_t i = 0; i < boxes.size(); ++i) builder.bvh.order[i] = i;
  builder.bvh.nodes.reserve(boxes.empty() ? 1 : 2 * boxes.size());
  builder.bvh.nodes.push_back({});
  if (boxes.empty()) {
    builder.bvh.nodes[0] = {glm::vec3(0.0f), 0u, glm::vec3(0.0f), abi::kBvhLeaf};
    return std::move(builder.bvh);
  }
  builder.build(0, 0, uint32_t(boxes.size()), 0);
  return std::move(builder.bvh);
}

}  // namespace hipr
