// Ray queries trace BLASes built from each primitive's triangles in spatial order
// (render/traversal_order.h) and map the triangle a query reports back to its own index. A
// wrong map shades a hit with another triangle's vertices: the shuffled mesh below would show
// another surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "card_scene.h"
#include "hipr/renderer.h"
#include "test_support.h"

namespace hipr {
namespace {

// A wavy sheet over the card camera's view, 24 x 24 quads, grey, its triangles listed row by
// row or shuffled with `shuffle` (0: not; the same vertices either way).
Scene wavy_sheet_scene(uint32_t shuffle) {
  Scene scene = test::make_card_camera_scene(1.0f);
  MaterialParameters grey = test::black_material();
  grey.base_color = glm::vec3(0.7f);
  test::add_card(scene, "sheet", glm::mat4(1.0f), grey);
  MeshPrimitive& sheet = scene.meshes.back().primitives[0];
  constexpr uint32_t n = 24;
  sheet.positions.clear();
  sheet.normals.clear();
  sheet.tangents.clear();
  sheet.uvs.clear();
  sheet.uvs1.clear();
  for (uint32_t j = 0; j <= n; ++j)
    for (uint32_t i = 0; i <= n; ++i) {
      const float x = -1.1f + 2.2f * float(i) / n, y = -1.1f + 2.2f * float(j) / n;
      // z = 0.3 sin(4x) cos(3y): valleys that shade and shadow one another.
      const float z = 0.3f * std::sin(4.0f * x) * std::cos(3.0f * y);
      const glm::vec3 dx(1.0f, 0.0f, 1.2f * std::cos(4.0f * x) * std::cos(3.0f * y));
      const glm::vec3 dy(0.0f, 1.0f, -0.9f * std::sin(4.0f * x) * std::sin(3.0f * y));
      sheet.positions.emplace_back(x, y, z);
      sheet.normals.push_back(glm::normalize(glm::cross(dx, dy)));
      sheet.tangents.emplace_back(glm::normalize(dx), 1.0f);
      sheet.uvs.emplace_back(float(i) / n, float(j) / n);
      sheet.uvs1.push_back(sheet.uvs.back());
    }
  sheet.indices = test::grid_triangles(n, shuffle);
  scene.meshes.back().revision = mesh_revision(scene.meshes.back());
  return scene;
}

TEST(TriangleOrder, AShuffledMeshRendersAsItsOrderedSelf) {
  const RenderSettings settings = test::render_settings(48, 48, 16, 3, 2);
  const ImageRGB ordered = test::render_finite(wavy_sheet_scene(0), settings, 4);
  const ImageRGB shuffled = test::render_finite(wavy_sheet_scene(11), settings, 4);
  const ImageRGB reshuffled = test::render_finite(wavy_sheet_scene(12), settings, 4);
  // Two shuffles of one list are cut at the same medians: one structure, every hit the same
  // triangle, so the images are equal bit for bit.
  EXPECT_EQ(shuffled.rgb, reshuffled.rgb);
  // The list row by row may keep its own order (traversal_order.h): the same surfaces, up to a
  // ray through an edge taking the other side's triangle.
  EXPECT_NEAR(test::mean(shuffled), test::mean(ordered), 0.002 * test::mean(ordered));
  size_t same = 0;
  for (size_t i = 0; i < ordered.rgb.size(); ++i) same += ordered.rgb[i] == shuffled.rgb[i];
  EXPECT_GE(double(same), 0.95 * double(ordered.rgb.size()));
  // And the sheet is there, shaded: not one grey everywhere.
  float lo = 1e9f, hi = 0.0f;
  for (float v : ordered.rgb) lo = std::min(lo, v), hi = std::max(hi, v);
  EXPECT_GT(hi - lo, 0.2f);
}

}  // namespace
}  // namespace hipr
