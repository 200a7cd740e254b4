// Unbiasedness of light transport: BSDF sampling alone, light sampling alone and their MIS
// combination are three estimators of the same integral, so their images must agree. A wrong
// pdf (light selection, triangle area measure, environment CDF) makes one of them drift.
#include <gtest/gtest.h>

#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "test_support.h"

namespace hipr {
namespace {

double render_mean(const Scene& scene, LightSampling mode, uint32_t size, uint32_t spp,
                   uint32_t max_depth) {
  RenderSettings s;
  s.width = s.height = size;
  s.max_depth = max_depth;
  s.seed = 21;
  s.light_sampling = mode;
  Renderer renderer(test::context(), scene, s);
  for (uint32_t done = 0; done < spp; done += 64) renderer.add_samples_full_frame(64);
  EXPECT_EQ(renderer.counters().non_finite_samples, 0u);
  return test::mean(renderer.image());
}

void expect_estimators_agree(const Scene& scene, uint32_t size, uint32_t spp, uint32_t max_depth,
                             double tolerance) {
  const double mis = render_mean(scene, LightSampling::Mis, size, spp, max_depth);
  const double bsdf = render_mean(scene, LightSampling::BsdfOnly, size, spp, max_depth);
  const double light = render_mean(scene, LightSampling::LightOnly, size, spp, max_depth);
  EXPECT_GT(mis, 0.0);
  EXPECT_NEAR(bsdf / mis, 1.0, tolerance) << "BSDF sampling alone";
  EXPECT_NEAR(light / mis, 1.0, tolerance) << "light sampling alone";
}

TEST(Estimators, EmissiveTrianglesAgree) {
  // Direct light and one indirect bounce from the Cornell box's area light.
  expect_estimators_agree(load_scene(test::asset("cornell_box.gltf")), 32, 256, 2, 0.02);
}

TEST(Estimators, HalfCoveredEmitterAgrees) {
  // A stochastic (BLEND) emitter: BSDF rays find it half the time, so light sampling must
  // weight its radiance by its coverage.
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  for (Material& m : scene.materials)
    if (m.name == "light") m.params.geometry_opacity = 0.5f;
  expect_estimators_agree(scene, 32, 256, 2, 0.02);
}

TEST(Estimators, GlossyMaterialsAgree) {
  // Rough metal and a shiny dielectric: the GGX pdfs must match what the lobes sample.
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  for (Material& m : scene.materials) {
    if (m.name == "white") {
      m.params.base_metalness = 1.0f;
      m.params.specular_roughness = 0.35f;
    } else if (m.name == "red" || m.name == "green") {
      m.params.specular_weight = 1.0f;
      m.params.specular_roughness = 0.2f;
    }
  }
  expect_estimators_agree(scene, 32, 256, 2, 0.03);
}

TEST(Estimators, EnvironmentImportanceSamplingAgrees) {
  // A grey sphere under a sky with a bright "sun" patch: the environment CDF must match its pdf.
  Scene scene = test::make_furnace_scene(1.0f, glm::vec3(0.0f), 0.5f, 0.3f);
  Environment& env = *scene.environment;
  env.width = 32;
  env.height = 16;
  env.texels.assign(32 * 16, glm::vec3(0.3f, 0.35f, 0.5f));
  for (uint32_t y = 3; y < 6; ++y)
    for (uint32_t x = 20; x < 26; ++x) env.texels[y * 32 + x] = glm::vec3(8.0f, 7.0f, 5.0f);
  env.rotation = 0.4f;
  expect_estimators_agree(scene, 32, 256, 1, 0.02);
}

}  // namespace
}  // namespace hipr
