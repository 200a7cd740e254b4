// The light tree's builder: every light with power in exactly one leaf that points back at it,
// nodes that bound their children (space, power, emission cone), a bounded depth, lights at
// infinity and black ones left out, the same tree every time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>

#include "render/light_tree.h"

namespace hipr {
namespace {

abi::Light triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  abi::Light l{};
  l.type = abi::kLightTriangle;
  l.position = a;
  l.edge1 = b - a;
  l.edge2 = c - a;
  l.area = 0.5f * glm::length(glm::cross(b - a, c - a));
  return l;
}

struct Lights {
  std::vector<abi::Light> table;
  std::vector<LightBounds> bounds;

  void add(const abi::Light& light, float radiance = 1.0f, bool two_sided = false) {
    bounds.push_back(light_bounds(light, radiance, two_sided));
    bounds.back().light = uint32_t(table.size());
    table.push_back(light);
  }
};

// Triangles facing every way, point and spot lights, a sun and an environment, spread over a
// clustered space (lamps come in groups in real scenes).
Lights random_lights(size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), small(0.0f, 0.2f);
  Lights lights;
  for (size_t i = 0; i < count; ++i) {
    const glm::vec3 cluster = 10.0f * glm::vec3(float(i % 5), 0.0f, float(i % 3));
    const glm::vec3 p = cluster + glm::vec3(unit(rng), unit(rng), unit(rng));
    switch (i % 4) {
      case 0:
      case 1:
        lights.add(triangle(p, p + glm::vec3(small(rng), small(rng), 0.0f),
                            p + glm::vec3(0.0f, small(rng), small(rng))),
                   1.0f + small(rng), i % 8 == 1);
        break;
      case 2: {
        abi::Light l{};
        l.type = abi::kLightPoint;
        l.position = p;
        l.intensity = glm::vec3(2.0f);
        lights.add(l);
        break;
      }
      default: {
        abi::Light l{};
        l.type = abi::kLightSpot;
        l.position = p;
        l.direction = glm::normalize(glm::vec3(unit(rng), -1.0f, unit(rng)));
        l.spotCosOuter = 0.7f;
        l.spotCosInner = 0.9f;
        l.intensity = glm::vec3(5.0f);
        lights.add(l);
      }
    }
  }
  abi::Light sun{};
  sun.type = abi::kLightDirectional;
  sun.direction = glm::vec3(0, -1, 0);
  sun.intensity = glm::vec3(3.0f);
  lights.add(sun);
  abi::Light env{};
  env.type = abi::kLightEnvironment;
  lights.add(env);
  lights.add(triangle(glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f),
                      glm::vec3(2.0f, 0.0f, 0.0f)));  // degenerate
  lights.add(triangle(glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)),
             0.0f);  // black
  return lights;
}

// `count` equal point lights at the origin.
Lights points_at_origin(int count) {
  Lights lights;
  abi::Light point{};
  point.type = abi::kLightPoint;
  point.intensity = glm::vec3(1.0f);
  for (int i = 0; i < count; ++i) lights.add(point);
  return lights;
}

float angle_between(const glm::vec3& a, const glm::vec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
}

TEST(LightTree, EveryLightWithPowerHasOneLeafAndNodesBoundTheirChildren) {
  Lights lights = random_lights(600, 7);
  const std::vector<abi::LightTreeNode> tree = build_light_tree(lights.bounds, lights.table);
  ASSERT_FALSE(tree.empty());
  EXPECT_EQ(tree[0].parent, abi::kInvalidIndex);
  std::vector<int> reached(lights.table.size(), 0);
  uint32_t deepest = 0;
  std::function<void(uint32_t, uint32_t)> walk = [&](uint32_t index, uint32_t depth) {
    ASSERT_LT(index, tree.size());
    deepest = std::max(deepest, depth);
    const abi::LightTreeNode& node = tree[index];
    EXPECT_GT(node.power, 0.0f);
    if (node.child & abi::kLightTreeLeaf) {
      const uint32_t light = node.child & abi::kLightTreeIndexMask;
      ASSERT_LT(light, lights.table.size());
      ++reached[light];
      EXPECT_EQ(lights.table[light].treeLeaf, index);
      // Every ancestor's cone holds the light's own (each direction it emits toward, as far past
      // its normals as it reaches), and its sphere holds the light.
      const LightBounds& own = lights.bounds[light];
      const float own_spread = std::acos(std::clamp(own.cos_spread, -1.0f, 1.0f));
      for (uint32_t a = index; a != abi::kInvalidIndex; a = tree[a].parent) {
        const LightTreeNodeCone cone = light_tree_node_cone(tree[a]);
        const float spread = std::acos(std::clamp(cone.cos_spread, -1.0f, 1.0f));
        if (spread < 3.14159f) {
          EXPECT_LE(angle_between(tree[a].axis, own.axis) + own_spread, spread + 1e-3f);
        }
        EXPECT_LE(cone.cos_reach, own.cos_reach);
        if (own.two_sided) {
          EXPECT_TRUE(cone.two_sided);
        }
        for (int k = 0; k < 8; ++k) {
          const glm::vec3 corner((k & 1) ? own.hi.x : own.lo.x, (k & 2) ? own.hi.y : own.lo.y,
                                 (k & 4) ? own.hi.z : own.lo.z);
          const glm::vec3 d = corner - tree[a].centre;
          EXPECT_LE(glm::dot(d, d), tree[a].radius2);
        }
        // A plane bound holds only one-sided triangles facing its way, each in front of it.
        if (std::isfinite(cone.front)) {
          const abi::Light& l = lights.table[light];
          ASSERT_EQ(l.type, abi::kLightTriangle);
          EXPECT_FALSE(own.two_sided);
          EXPECT_EQ(own.axis, tree[a].axis);
          for (const glm::vec3& v : {l.position, l.position + l.edge1, l.position + l.edge2})
            EXPECT_GE(glm::dot(tree[a].axis, v), cone.front);
        }
      }
      return;
    }
    float power = 0.0f;
    const uint32_t first = node.child & abi::kLightTreeIndexMask;
    for (uint32_t c : {first, first + 1}) {
      ASSERT_LT(c, tree.size());
      const abi::LightTreeNode& child = tree[c];
      EXPECT_EQ(child.parent, index);
      // Below a node taken by power every node is (the walk never returns to importances).
      if ((node.child & abi::kLightTreeByPower) && !(child.child & abi::kLightTreeLeaf)) {
        EXPECT_TRUE(child.child & abi::kLightTreeByPower);
      }
      EXPECT_LE(light_tree_node_cone(node).cos_reach, light_tree_node_cone(child).cos_reach);
      power += child.power;
      walk(c, depth + 1);
    }
    EXPECT_NEAR(node.power, power, 1e-4f * power);
  };
  walk(0, 0);
  const size_t n = lights.table.size();
  for (size_t i = 0; i + 4 < n; ++i) EXPECT_EQ(reached[i], 1) << "light " << i;
  // The sun, the environment, the degenerate and the black triangle are not in it.
  for (size_t i = n - 4; i < n; ++i) {
    EXPECT_EQ(reached[i], 0) << "light " << i;
    EXPECT_EQ(lights.table[i].treeLeaf, abi::kInvalidIndex);
  }
  EXPECT_LE(deepest, 48u + 10u);
}

TEST(LightTree, ASpotConeAndATriangleSideAreTheirBounds) {
  Lights lights;
  lights.add(triangle(glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)),
             2.0f);
  const LightBounds& b = lights.bounds[0];
  EXPECT_NEAR(b.axis.y, -1.0f, 1e-6f);  // (x cross z) = -y: counter-clockwise seen from below
  EXPECT_FLOAT_EQ(b.cos_spread, 1.0f);
  EXPECT_FLOAT_EQ(b.cos_reach, 0.0f);
  EXPECT_FLOAT_EQ(b.power, 2.0f * 0.5f);
  abi::Light spot{};
  spot.type = abi::kLightSpot;
  spot.direction = glm::vec3(0, 0, -1);
  spot.spotCosOuter = 0.5f;
  spot.intensity = glm::vec3(1.0f, 2.0f, 3.0f);
  const LightBounds s = light_bounds(spot, 0.0f, false);
  EXPECT_FLOAT_EQ(s.cos_spread, 0.5f);
  EXPECT_FLOAT_EQ(s.cos_reach, 1.0f);
  EXPECT_NEAR(s.power, 0.2126f + 2.0f * 0.7152f + 3.0f * 0.0722f, 1e-5f);
}

// A ceiling light of two triangles facing down is bounded by its plane: a point above the
// ceiling (behind it) is told apart from one just below, which the cone bound cannot do from
// inside the node's sphere. A point light or a two-sided triangle among them has no plane.
TEST(LightTree, OneSidedLightsFacingOneWayAreBoundedByTheirPlane) {
  Lights ceiling;
  const float h = 5.48f;
  ceiling.add(
      triangle(glm::vec3(2.1f, h, 2.3f), glm::vec3(3.4f, h, 2.3f), glm::vec3(3.4f, h, 3.3f)));
  ceiling.add(
      triangle(glm::vec3(2.1f, h, 2.3f), glm::vec3(3.4f, h, 3.3f), glm::vec3(2.1f, h, 3.3f)));
  ASSERT_EQ(ceiling.bounds[0].axis, glm::vec3(0.0f, -1.0f, 0.0f));
  const std::vector<abi::LightTreeNode> tree = build_light_tree(ceiling.bounds, ceiling.table);
  ASSERT_EQ(tree.size(), 3u);
  for (const abi::LightTreeNode& node : tree) {
    const float front = light_tree_node_cone(node).front;
    ASSERT_TRUE(std::isfinite(front));
    EXPECT_NEAR(front, -h, 1e-3f);
    EXPECT_LT(glm::dot(node.axis, glm::vec3(0.0f, h + 0.01f, 0.0f)), front) << "above";
    EXPECT_GT(glm::dot(node.axis, glm::vec3(2.5f, h - 0.01f, 2.5f)), front) << "below";
    EXPECT_LT(glm::dot(node.axis, glm::vec3(2.5f, h, 2.5f)), front + 1e-3f);
  }

  Lights mixed = ceiling;
  abi::Light point{};
  point.type = abi::kLightPoint;
  point.position = glm::vec3(1.0f, 1.0f, 1.0f);
  point.intensity = glm::vec3(1.0f);
  mixed.add(point);
  const std::vector<abi::LightTreeNode> with_point = build_light_tree(mixed.bounds, mixed.table);
  EXPECT_EQ(light_tree_node_cone(with_point[0]).front, -INFINITY);
  size_t planes = 0;
  for (const abi::LightTreeNode& node : with_point)
    planes += std::isfinite(light_tree_node_cone(node).front);
  EXPECT_EQ(planes, 3u) << "the ceiling's subtree keeps its plane";

  Lights two_sided;
  two_sided.add(ceiling.table[0], 1.0f, true);
  EXPECT_EQ(light_tree_node_cone(build_light_tree(two_sided.bounds, two_sided.table)[0]).front,
            -INFINITY);
}

TEST(LightTree, OneLightIsALeafRootAndNoLightNoTree) {
  Lights one;
  abi::Light point{};
  point.type = abi::kLightPoint;
  point.intensity = glm::vec3(1.0f);
  one.add(point);
  const auto tree = build_light_tree(one.bounds, one.table);
  ASSERT_EQ(tree.size(), 1u);
  EXPECT_EQ(tree[0].child, 0u | abi::kLightTreeLeaf);
  EXPECT_EQ(one.table[0].treeLeaf, 0u);
  Lights none;
  abi::Light env{};
  env.type = abi::kLightEnvironment;
  none.add(env);
  EXPECT_TRUE(build_light_tree(none.bounds, none.table).empty());
  EXPECT_EQ(none.table[0].treeLeaf, abi::kInvalidIndex);
}

TEST(LightTree, LightsAtOnePointStillMakeAShallowTree) {
  // No plane separates them: the builder halves the list instead of recursing forever.
  Lights lights = points_at_origin(1000);
  const auto tree = build_light_tree(lights.bounds, lights.table);
  EXPECT_EQ(tree.size(), 2u * 1000u - 1u);
  uint32_t deepest = 0;
  for (const abi::Light& l : lights.table) {
    uint32_t depth = 0;
    for (uint32_t n = l.treeLeaf; tree[n].parent != abi::kInvalidIndex; n = tree[n].parent) ++depth;
    deepest = std::max(deepest, depth);
  }
  EXPECT_LE(deepest, 11u);
}

// Spots aimed the same way (an axis whose dot with itself rounds below 1): their node keeps
// their cone instead of widening to every direction, and decodes it no narrower than built.
TEST(LightTree, LightsSharingAnAxisKeepTheirCone) {
  Lights spots;
  abi::Light spot{};
  spot.type = abi::kLightSpot;
  spot.direction = glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f));
  spot.spotCosOuter = 0.9f;
  spot.intensity = glm::vec3(1.0f);
  for (int i = 0; i < 4; ++i) {
    spot.position = glm::vec3(float(i), 0.0f, 0.0f);
    spots.add(spot);
  }
  const auto tree = build_light_tree(spots.bounds, spots.table);
  for (const abi::LightTreeNode& node : tree) {
    const LightTreeNodeCone cone = light_tree_node_cone(node);
    EXPECT_EQ(node.axis, spot.direction);
    EXPECT_LE(cone.cos_spread, 0.9f);
    EXPECT_GT(cone.cos_spread, 0.899f);
    EXPECT_LE(cone.cos_reach, 1.0f);
    EXPECT_GT(cone.cos_reach, 0.999f);
  }
  // A tilted lamp: copies of one triangle side by side (normals equal bit for bit) keep the
  // plane bound in every node, the root of all of them too.
  Lights lamp;
  const glm::vec3 a(0.0f), b(2.0f, -1.0f, 0.0f), c(3.0f, 0.0f, -1.0f);  // normal (1, 2, 3)
  for (int i = 0; i < 6; ++i) {
    const glm::vec3 at = float(i) * (b - a);
    lamp.add(triangle(a + at, b + at, c + at));
  }
  for (const abi::LightTreeNode& node : build_light_tree(lamp.bounds, lamp.table))
    EXPECT_TRUE(std::isfinite(light_tree_node_cone(node).front));
}

TEST(LightTree, TheSameLightsGiveTheSameTree) {
  Lights a = random_lights(300, 3), b = random_lights(300, 3);
  const auto ta = build_light_tree(a.bounds, a.table), tb = build_light_tree(b.bounds, b.table);
  ASSERT_EQ(ta.size(), tb.size());
  EXPECT_EQ(std::memcmp(ta.data(), tb.data(), ta.size() * sizeof(abi::LightTreeNode)), 0);
}

// The lights below a node: the leaves of its subtree.
size_t lights_below(const std::vector<abi::LightTreeNode>& tree, uint32_t node) {
  if (tree[node].child & abi::kLightTreeLeaf) return 1;
  const uint32_t first = tree[node].child & abi::kLightTreeIndexMask;
  return lights_below(tree, first) + lights_below(tree, first + 1);
}

bool by_power(const abi::LightTreeNode& node) {
  return (node.child & abi::kLightTreeByPower) != 0u;
}

// A quad lamp's two triangles share its box and normal: no split can make either half's bounds
// smaller, so the walk takes them by power instead of weighing two importances. Two lamps apart,
// or a card's two faces turned away from each other, are told apart by importance.
TEST(LightTree, ALampsTrianglesGoByPowerAndLampsApartByImportance) {
  const auto quad = [](Lights& lights, const glm::vec3& at) {
    const glm::vec3 x(1.3f, 0.0f, 0.0f), z(0.0f, 0.0f, 1.0f);
    lights.add(triangle(at, at + x, at + x + z));
    lights.add(triangle(at, at + x + z, at + z));
  };
  Lights one;
  quad(one, glm::vec3(2.0f, 5.0f, 2.0f));
  const auto lamp = build_light_tree(one.bounds, one.table);
  ASSERT_EQ(lamp.size(), 3u);
  EXPECT_TRUE(by_power(lamp[0]));

  Lights two;
  quad(two, glm::vec3(2.0f, 5.0f, 2.0f));
  quad(two, glm::vec3(12.0f, 5.0f, 2.0f));
  const auto lamps = build_light_tree(two.bounds, two.table);
  ASSERT_EQ(lamps.size(), 7u);
  EXPECT_FALSE(by_power(lamps[0])) << "two lamps 10 m apart";
  const uint32_t first = lamps[0].child & abi::kLightTreeIndexMask;
  for (uint32_t c : {first, first + 1}) {
    EXPECT_EQ(lights_below(lamps, c), 2u);
    EXPECT_TRUE(by_power(lamps[c])) << "each lamp's triangles";
  }

  Lights card;  // one triangle facing up, one facing down, in one place
  const glm::vec3 a(0.0f), b(1.0f, 0.0f, 0.0f), c(0.0f, 0.0f, 1.0f);
  card.add(triangle(a, b, c));
  card.add(triangle(a, c, b));
  EXPECT_FALSE(by_power(build_light_tree(card.bounds, card.table)[0]));

  // Many lights at one point: no plane divides them; groups of up to 8 go by power.
  Lights points = points_at_origin(40);
  const auto tree = build_light_tree(points.bounds, points.table);
  size_t taken_by_power = 0;
  for (uint32_t n = 0; n < tree.size(); ++n) {
    if (!by_power(tree[n])) continue;
    EXPECT_LE(lights_below(tree, n), 8u);
    if (tree[n].parent == abi::kInvalidIndex || !by_power(tree[tree[n].parent]))
      taken_by_power += lights_below(tree, n);
  }
  EXPECT_EQ(taken_by_power, 40u);
}

}  // namespace
}  // namespace hipr
