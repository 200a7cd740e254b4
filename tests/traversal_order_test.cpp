// The order in which triangles go to the device's acceleration-structure build
// (render/traversal_order.h): a permutation, along space, decided by the geometry alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include <glm/geometric.hpp>

#include "render/traversal_order.h"

namespace hipr {
namespace {

// A 32 x 32 grid of quads (two triangles each) whose triangles are listed in a shuffled order.
struct Grid {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
};

Grid shuffled_grid(uint32_t seed) {
  constexpr uint32_t n = 32;
  Grid g;
  for (uint32_t y = 0; y <= n; ++y)
    for (uint32_t x = 0; x <= n; ++x) g.positions.emplace_back(float(x), float(y), 0.0f);
  std::vector<std::array<uint32_t, 3>> triangles;
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) {
      const uint32_t a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  std::mt19937 rng(seed);
  std::shuffle(triangles.begin(), triangles.end(), rng);
  for (const auto& t : triangles) g.indices.insert(g.indices.end(), t.begin(), t.end());
  return g;
}

glm::vec3 centroid(const Grid& g, uint32_t t) {
  return (g.positions[g.indices[3 * t]] + g.positions[g.indices[3 * t + 1]] +
          g.positions[g.indices[3 * t + 2]]) /
         3.0f;
}

// Mean distance between the centroids of triangles one after the other in `order`.
double mean_step(const Grid& g, const std::vector<uint32_t>& order) {
  double sum = 0.0;
  for (size_t k = 1; k < order.size(); ++k)
    sum += glm::length(centroid(g, order[k]) - centroid(g, order[k - 1]));
  return sum / double(order.size() - 1);
}

TEST(TraversalOrder, IsAPermutationThatWalksThroughSpace) {
  const Grid g = shuffled_grid(7);
  const std::vector<uint32_t> order = spatial_triangle_order(g.positions, g.indices);
  ASSERT_EQ(order.size(), g.indices.size() / 3);
  std::vector<uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<uint32_t> every(order.size());
  std::iota(every.begin(), every.end(), 0u);
  EXPECT_EQ(sorted, every);
  // The shuffled list steps about a third of the grid's width from one triangle to the next;
  // a Morton walk mostly to a neighbour.
  std::vector<uint32_t> as_listed(order.size());
  std::iota(as_listed.begin(), as_listed.end(), 0u);
  const double listed = mean_step(g, as_listed), walked = mean_step(g, order);
  EXPECT_GT(listed, 8.0);
  EXPECT_LT(walked, 1.5) << "listed " << listed;
}

TEST(TraversalOrder, KeepsAListTheBuilderAlreadyCutsAsWell) {
  const Grid shuffled = shuffled_grid(5);
  const std::vector<uint32_t> order = spatial_triangle_order(shuffled.positions, shuffled.indices);
  // The same triangles listed in that order already: nothing to gain, the list stays.
  Grid listed{shuffled.positions, {}};
  for (uint32_t t : order)
    listed.indices.insert(listed.indices.end(), shuffled.indices.begin() + 3 * t,
                          shuffled.indices.begin() + 3 * t + 3);
  std::vector<uint32_t> as_listed(order.size());
  std::iota(as_listed.begin(), as_listed.end(), 0u);
  EXPECT_EQ(spatial_triangle_order(listed.positions, listed.indices), as_listed);
}

TEST(TraversalOrder, DependsOnTheGeometryAloneAndPutsBrokenTrianglesLast) {
  Grid g = shuffled_grid(3);
  EXPECT_EQ(spatial_triangle_order(g.positions, g.indices),
            spatial_triangle_order(g.positions, g.indices));
  // Two triangles that cannot be placed: a NaN vertex, and an index past the vertices.
  g.positions.push_back(glm::vec3(std::numeric_limits<float>::quiet_NaN()));
  g.indices.insert(g.indices.end(), {0, 1, uint32_t(g.positions.size() - 1)});
  g.indices.insert(g.indices.end(), {0, 1, uint32_t(g.positions.size() + 5)});
  const std::vector<uint32_t> order = spatial_triangle_order(g.positions, g.indices);
  const uint32_t triangles = uint32_t(g.indices.size() / 3);
  ASSERT_EQ(order.size(), size_t(triangles));
  EXPECT_EQ(order[triangles - 2], triangles - 2);
  EXPECT_EQ(order[triangles - 1], triangles - 1);
  EXPECT_TRUE(spatial_triangle_order(g.positions, {}).empty());
}

}  // namespace
}  // namespace hipr
