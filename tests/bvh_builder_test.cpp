// The software traversal's BVH builder: every item in exactly one leaf, bounds that hold their
// subtrees, depth within what the kernels' stacks hold, small leaves, the same tree every time.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include "render/bvh_builder.h"

namespace hipr {
namespace {

std::vector<Box> random_boxes(size_t count, uint32_t seed, float size) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> position(-10.0f, 10.0f), extent(0.0f, size);
  std::vector<Box> boxes(count);
  for (Box& b : boxes) {
    const glm::vec3 lo(position(rng), position(rng), position(rng));
    b.grow(lo);
    b.grow(lo + glm::vec3(extent(rng), extent(rng), extent(rng)));
  }
  return boxes;
}

bool contains(const abi::BvhNode& outer, const Box& inner) {
  return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) &&
         glm::all(glm::greaterThanEqual(outer.hi, inner.hi));
}

// Walks the tree checking its invariants; returns how many times each item was reached.
std::vector<int> check_tree(const Bvh& bvh, const std::vector<Box>& boxes, uint32_t& max_depth,
                            uint32_t& max_leaf) {
  std::vector<int> seen(boxes.size(), 0);
  max_depth = 0;
  max_leaf = 0;
  std::function<void(uint32_t, uint32_t)> walk = [&](uint32_t index, uint32_t depth) {
    ASSERT_LT(index, bvh.nodes.size());
    const abi::BvhNode& node = bvh.nodes[index];
    max_depth = std::max(max_depth, depth);
    if (node.count != 0) {
      const uint32_t count = node.count & ~abi::kBvhLeaf;
      max_leaf = std::max(max_leaf, count);
      for (uint32_t i = node.first; i < node.first + count; ++i) {
        ASSERT_LT(i, bvh.order.size());
        seen[bvh.order[i]] += 1;
        EXPECT_TRUE(contains(node, boxes[bvh.order[i]]))
            << "leaf " << index << " item " << bvh.order[i];
      }
      return;
    }
    for (uint32_t child = node.first; child < node.first + 2; ++child) {
      ASSERT_LT(child, bvh.nodes.size());
      EXPECT_TRUE(contains(node, Box{bvh.nodes[child].lo, bvh.nodes[child].hi}))
          << "node " << index;
      walk(child, depth + 1);
    }
  };
  walk(0, 0);
  return seen;
}

TEST(BvhBuilder, EveryItemInExactlyOneLeafUnderBoundsThatHoldIt) {
  const std::vector<Box> boxes = random_boxes(5000, 1, 0.5f);
  const Bvh bvh = build_bvh(boxes);
  uint32_t depth = 0, leaf = 0;
  const std::vector<int> seen = check_tree(bvh, boxes, depth, leaf);
  for (size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "item " << i;
  EXPECT_LE(depth, abi::kBvhMaxDepth);
  EXPECT_LE(leaf, kBvhMaxLeafItems);
  EXPECT_LE(bvh.nodes.size(), 2 * boxes.size());
  // A balanced-enough tree: 5000 items fit in 4-item leaves about 11 levels down.
  EXPECT_LE(depth, 24u);
}

TEST(BvhBuilder, SameBoxesBuildTheSameTree) {
  const std::vector<Box> boxes = random_boxes(777, 2, 2.0f);
  const Bvh a = build_bvh(boxes), b = build_bvh(boxes);
  ASSERT_EQ(a.order, b.order);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_EQ(a.nodes[i].first, b.nodes[i].first);
    EXPECT_EQ(a.nodes[i].count, b.nodes[i].count);
  }
}

TEST(BvhBuilder, CoincidentItemsStillSplitAndStayWithinTheDepthLimit) {
  // Thousands of copies of one box: no axis tells them apart, yet leaves stay small until the
  // depth limit, and every copy is still found once.
  std::vector<Box> boxes(3000);
  for (Box& b : boxes) {
    b.grow(glm::vec3(1.0f));
    b.grow(glm::vec3(2.0f));
  }
  const Bvh bvh = build_bvh(boxes);
  uint32_t depth = 0, leaf = 0;
  const std::vector<int> seen = check_tree(bvh, boxes, depth, leaf);
  for (int s : seen) ASSERT_EQ(s, 1);
  EXPECT_LE(depth, abi::kBvhMaxDepth);
  EXPECT_LE(leaf, kBvhMaxLeafItems);
}

TEST(BvhBuilder, PathologicalSpreadEndsInLeavesAtTheDepthLimit) {
  // Boxes at exponentially growing positions: SAH splits peel one item at a time, so the
  // depth limit is what stops the tree, with a bigger leaf at the bottom.
  std::vector<Box> boxes;
  for (int i = 0; i < 60; ++i) {
    Box b;
    b.grow(glm::vec3(std::ldexp(1.0f, i), 0.0f, 0.0f));
    b.grow(glm::vec3(std::ldexp(1.0f, i) + 0.5f, 1.0f, 1.0f));
    boxes.push_back(b);
  }
  const Bvh bvh = build_bvh(boxes);
  uint32_t depth = 0, leaf = 0;
  const std::vector<int> seen = check_tree(bvh, boxes, depth, leaf);
  for (int s : seen) ASSERT_EQ(s, 1);
  EXPECT_LE(depth, abi::kBvhMaxDepth);
}

// Boxes near or beyond float's range (scenes refuse them, scene/scene_limits.h, but the builder
// must not trust that): centres that overflow, infinite and NaN corners. Every item is still in
// one leaf; nothing indexes out of the bins (ASan/UBSan builds run this).
TEST(BvhBuilder, BoxesBeyondFloatsRangeStillBuildATree) {
  std::vector<Box> boxes = random_boxes(200, 3, 0.5f);
  const float inf = std::numeric_limits<float>::infinity(),
              nan = std::numeric_limits<float>::quiet_NaN();
  for (const auto& [lo, hi] :
       {std::pair{glm::vec3(3e38f), glm::vec3(3.4e38f)},
        std::pair{glm::vec3(-3.4e38f), glm::vec3(3.4e38f)},
        std::pair{glm::vec3(-inf), glm::vec3(inf)}, std::pair{glm::vec3(nan), glm::vec3(nan)},
        std::pair{glm::vec3(0.0f), glm::vec3(inf, 1.0f, nan)}})
    for (int copy = 0; copy < 20; ++copy) boxes.push_back(Box{lo, hi});
  const Bvh bvh = build_bvh(boxes);
  std::vector<int> seen(boxes.size(), 0);
  for (const abi::BvhNode& node : bvh.nodes)
    if (node.count != 0)
      for (uint32_t i = node.first; i < node.first + (node.count & ~abi::kBvhLeaf); ++i) {
        ASSERT_LT(i, bvh.order.size());
        ASSERT_LT(bvh.order[i], boxes.size());
        seen[bvh.order[i]] += 1;
      }
  for (size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "item " << i;
}

TEST(BvhBuilder, NoItemsGiveOneEmptyLeaf) {
  const Bvh bvh = build_bvh({});
  ASSERT_EQ(bvh.nodes.size(), 1u);
  EXPECT_EQ(bvh.nodes[0].count, abi::kBvhLeaf);
  EXPECT_TRUE(bvh.order.empty());
}

}  // namespace
}  // namespace hipr
