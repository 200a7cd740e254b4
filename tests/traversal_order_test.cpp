// The order in which triangles go to the device's acceleration-structure build
// (render/traversal_order.h): a permutation, along space, decided by the geometry alone, and
// kept from one upload to the next while the mesh is unchanged (render/triangle_orders.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/geometric.hpp>

#include "render/traversal_order.h"
#include "render/triangle_orders.h"
#include "test_support.h"

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
  g.indices = test::grid_triangles(n, seed);
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

Mesh grid_mesh(uint32_t seed) {
  const Grid g = shuffled_grid(seed);
  Mesh mesh;
  mesh.primitives.resize(1);
  mesh.primitives[0].positions = g.positions;
  mesh.primitives[0].indices = g.indices;
  mesh.revision = mesh_revision(mesh);
  return mesh;
}

TEST(TriangleOrders, SortAMeshAgainOnlyWhenItsGeometryChanged) {
  TriangleOrders orders;
  const Mesh a = grid_mesh(3), b = grid_mesh(4);
  const auto first_a = orders.of(a), first_b = orders.of(b);
  orders.end_upload();
  EXPECT_EQ(orders.primitives_sorted(), 2u);
  EXPECT_EQ(first_a[0], spatial_triangle_order(a.primitives[0].positions, a.primitives[0].indices));
  // The next upload: b first now (a removal before it), and a deformed.
  Mesh deformed = a;
  deformed.primitives[0].positions[0].z = 0.5f;
  deformed.revision = mesh_revision(deformed);
  EXPECT_EQ(orders.of(b), first_b);
  EXPECT_EQ(orders.primitives_sorted(), 2u);
  const auto second_a = orders.of(deformed);
  EXPECT_EQ(orders.primitives_sorted(), 3u);
  EXPECT_EQ(second_a[0], spatial_triangle_order(deformed.primitives[0].positions,
                                                deformed.primitives[0].indices));
  orders.end_upload();
  // The undo brings a back: the last upload dropped it, and it is kept one upload more.
  EXPECT_EQ(orders.of(a), first_a);
  EXPECT_EQ(orders.of(b), first_b);
  EXPECT_EQ(orders.primitives_sorted(), 3u);
  orders.end_upload();
  // The redo: the deformed mesh, dropped by the undo, comes back unsorted too.
  EXPECT_EQ(orders.of(deformed), second_a);
  EXPECT_EQ(orders.primitives_sorted(), 3u);
  orders.end_upload();
  // Two uploads without a mesh forget it: b was last asked two uploads ago.
  orders.end_upload();
  EXPECT_EQ(orders.of(b), first_b);
  EXPECT_EQ(orders.primitives_sorted(), 4u);
  // A mesh without a fingerprint is sorted each time.
  Mesh unset = b;
  unset.revision = 0;
  EXPECT_EQ(orders.of(unset), first_b);
  EXPECT_EQ(orders.of(unset), first_b);
  EXPECT_EQ(orders.primitives_sorted(), 6u);
}

}  // namespace
}  // namespace hipr
