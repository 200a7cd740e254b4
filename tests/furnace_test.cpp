// White furnace: a white Lambert sphere in a uniform white environment reflects exactly the
// radiance it receives, so every pixel (sphere and background) converges to 1. A darker sphere
// means lost energy (e.g. self-intersection acne), brighter means double counting (MIS).
#include <gtest/gtest.h>

#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "test_support.h"

namespace hipr {
namespace {

ImageRGB render(const Scene& scene, uint32_t spp, uint32_t max_depth = 16) {
  RenderSettings s;
  s.width = s.height = 32;
  s.max_depth = max_depth;
  s.seed = 3;
  Renderer renderer(test::context(), scene, s);
  renderer.add_samples_full_frame(spp);
  EXPECT_EQ(renderer.counters().non_finite_samples, 0u);
  return renderer.image();
}

void expect_white(const ImageRGB& image, double mean_tolerance, double pixel_tolerance) {
  ASSERT_TRUE(test::all_finite(image));
  EXPECT_NEAR(test::mean(image), 1.0, mean_tolerance);
  for (size_t i = 0; i < image.rgb.size(); ++i)
    ASSERT_NEAR(image.rgb[i], 1.0, pixel_tolerance) << "pixel " << i / 3;
}

TEST(Furnace, ShippedSphereUnderUniformEnvironmentIsWhite) {
  const auto dir = test::temp_dir("furnace");
  ImageRGB env{16, 8, std::vector<float>(16 * 8 * 3, 1.0f)};
  write_image(dir / "white.exr", env);
  SceneLoadOptions options;
  options.environment = dir / "white.exr";
  const Scene scene = load_scene(test::asset("furnace_sphere.gltf"), options);
  // 64 spp: per-pixel noise is a few percent (NEE and BSDF samples of a uniform sky differ).
  expect_white(render(scene, 64), 0.01, 0.15);
}

class FurnaceAtScale : public ::testing::TestWithParam<float> {};

TEST_P(FurnaceAtScale, NoEnergyLostToSelfIntersection) {
  const float scale = GetParam();
  // Far from the origin as well, where float spacing is coarse.
  const Scene scene = test::make_furnace_scene(scale, glm::vec3(3.0f * scale, -2.0f * scale, scale), 1.0f, 1.0f);
  expect_white(render(scene, 32), 0.015, 0.2);
}

INSTANTIATE_TEST_SUITE_P(Scales, FurnaceAtScale, ::testing::Values(1e-4f, 1e-2f, 1.0f, 1e2f, 1e5f));

TEST(Furnace, GreySphereReflectsItsAlbedo) {
  // Convex sphere: light reflects once then escapes, so the sphere shows albedo x sky.
  const Scene scene = test::make_furnace_scene(1.0f, glm::vec3(0.0f), 0.5f, 2.0f);
  const ImageRGB image = render(scene, 64);
  const size_t centre = (16 * 32 + 16) * 3;
  EXPECT_NEAR(image.rgb[centre], 1.0, 0.1);
  EXPECT_NEAR(image.rgb[0], 2.0, 1e-5);  // corner: background seen directly
}

TEST(Furnace, MaxDepthZeroShowsOnlyEmitters) {
  const Scene scene = test::make_furnace_scene(1.0f, glm::vec3(0.0f), 1.0f, 1.0f);
  const ImageRGB image = render(scene, 4, 0);
  EXPECT_EQ(image.rgb[(16 * 32 + 16) * 3], 0.0f);
  EXPECT_EQ(image.rgb[0], 1.0f);
}

}  // namespace
}  // namespace hipr
