// Unbiasedness of light transport: BSDF sampling alone, light sampling alone and their MIS
// combination are three estimators of the same integral, so their images must agree. A wrong
// pdf (light selection, triangle area measure, environment CDF) makes one of them drift.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "test_support.h"

namespace hipr {
namespace {

ImageRGB render_image(const Scene& scene, LightSampling mode, uint32_t size, uint32_t spp,
                      uint32_t max_depth, LightSelection selection = LightSelection::Tree,
                      uint32_t seed = 21) {
  RenderSettings s;
  s.width = s.height = size;
  s.max_depth = max_depth;
  s.seed = seed;
  s.light_sampling = mode;
  s.light_selection = selection;
  Renderer renderer(test::context(), scene, s);
  for (uint32_t done = 0; done < spp; done += 64) renderer.add_samples_full_frame(64);
  EXPECT_EQ(renderer.counters().non_finite_samples, 0u);
  return renderer.image();
}

double render_mean(const Scene& scene, LightSampling mode, uint32_t size, uint32_t spp,
                   uint32_t max_depth, LightSelection selection = LightSelection::Tree) {
  return test::mean(render_image(scene, mode, size, spp, max_depth, selection));
}

// With the light tree (the default) and with the power CDF alone.
void expect_estimators_agree(const Scene& scene, uint32_t size, uint32_t spp, uint32_t max_depth,
                             double tolerance) {
  for (LightSelection selection : {LightSelection::Tree, LightSelection::Power}) {
    SCOPED_TRACE(light_selection_name(selection));
    const double mis = render_mean(scene, LightSampling::Mis, size, spp, max_depth, selection);
    const double bsdf =
        render_mean(scene, LightSampling::BsdfOnly, size, spp, max_depth, selection);
    const double light =
        render_mean(scene, LightSampling::LightOnly, size, spp, max_depth, selection);
    EXPECT_GT(mis, 0.0);
    EXPECT_NEAR(bsdf / mis, 1.0, tolerance) << "BSDF sampling alone";
    EXPECT_NEAR(light / mis, 1.0, tolerance) << "light sampling alone";
  }
}

double rmse(const ImageRGB& a, const ImageRGB& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.rgb.size(); ++i)
    sum += double(a.rgb[i] - b.rgb[i]) * (a.rgb[i] - b.rgb[i]);
  return std::sqrt(sum / double(a.rgb.size()));
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

TEST(Estimators, LightTreeAgreesOnManyEmitters) {
  // lamp_hall's 96 emissive panels without its point lamps (BSDF sampling cannot find those):
  // the tree's pick and its pmf at emitter hits must be one distribution, and the hall's
  // environment-free light must come out the same with either selection.
  // (BSDF sampling alone, which does not depend on the selection, finds 0.2 m panels too
  // rarely to say anything at a test's sample counts.)
  Scene scene = load_scene(test::asset("lamp_hall.glb"));
  for (Node& node : scene.nodes) node.light = -1;
  const double tree = render_mean(scene, LightSampling::Mis, 24, 256, 1, LightSelection::Tree);
  const double tree_lights =
      render_mean(scene, LightSampling::LightOnly, 24, 256, 1, LightSelection::Tree);
  const double power = render_mean(scene, LightSampling::Mis, 24, 256, 1, LightSelection::Power);
  EXPECT_GT(tree, 0.0);
  EXPECT_NEAR(tree_lights / tree, 1.0, 0.02) << "light sampling alone";
  EXPECT_NEAR(power / tree, 1.0, 0.02) << "power selection";
}

TEST(Estimators, LightTreeIsUnbiasedAndLessNoisyAmongManyLamps) {
  // Point lamps and panels: both selections estimate the same image; the tree, which picks
  // the lamps near each point, is closer to a long render at equal samples.
  const Scene scene = load_scene(test::asset("lamp_hall.glb"));
  const ImageRGB reference =
      render_image(scene, LightSampling::Mis, 24, 1024, 1, LightSelection::Tree, 5);
  const ImageRGB tree = render_image(scene, LightSampling::Mis, 24, 64, 1, LightSelection::Tree);
  const ImageRGB power = render_image(scene, LightSampling::Mis, 24, 64, 1, LightSelection::Power);
  const ImageRGB power_long =
      render_image(scene, LightSampling::Mis, 24, 256, 1, LightSelection::Power);
  EXPECT_NEAR(test::mean(power_long) / test::mean(reference), 1.0, 0.03);
  EXPECT_NEAR(test::mean(tree) / test::mean(reference), 1.0, 0.03);
  EXPECT_LT(rmse(tree, reference), 0.7 * rmse(power, reference))
      << "power at 256 spp: " << rmse(power_long, reference);
}

// lamp_hall's first `lamps` point lamps (skipping `skip`), without its emissive panels.
Scene lamps_of_hall(size_t skip, size_t lamps) {
  Scene scene = load_scene(test::asset("lamp_hall.glb"));
  for (Material& m : scene.materials) m.params.emission_luminance = 0.0f;
  size_t seen = 0;
  for (Node& node : scene.nodes) {
    if (node.light < 0) continue;
    if (seen < skip || seen >= skip + lamps) node.light = -1;
    ++seen;
  }
  return scene;
}

TEST(Estimators, FewPunctualLightsAreEachSampledAndAgreeWithAPick) {
  // Two to kEachPunctualLights (8) punctual lights are each sampled at every vertex; one more,
  // or one alone, and the tree picks. Direct light is linear in the lights: eight lamps sampled
  // each plus the ninth alone must be the nine picked.
  const Scene eight = lamps_of_hall(0, 8), ninth = lamps_of_hall(8, 1), nine = lamps_of_hall(0, 9);
  const double each = render_mean(eight, LightSampling::Mis, 24, 256, 1) +
                      render_mean(ninth, LightSampling::Mis, 24, 256, 1);
  const double picked = render_mean(nine, LightSampling::Mis, 24, 256, 1);
  EXPECT_GT(each, 0.0);
  EXPECT_NEAR(picked / each, 1.0, 0.02);
  // The pick's noise is gone: two seeds of the eight lamps differ by their pixels' jitter alone.
  const double each_noise =
      rmse(render_image(eight, LightSampling::Mis, 24, 16, 1, LightSelection::Tree, 1),
           render_image(eight, LightSampling::Mis, 24, 16, 1, LightSelection::Tree, 2));
  const double pick_noise =
      rmse(render_image(nine, LightSampling::Mis, 24, 16, 1, LightSelection::Tree, 1),
           render_image(nine, LightSampling::Mis, 24, 16, 1, LightSelection::Tree, 2));
  EXPECT_LT(each_noise, 0.3 * pick_noise);
}

TEST(Estimators, PunctualLightsThatBringLittleTraceFewShadowRays) {
  // One of eight lamps 20x brighter: where it outshines the others, a lamp bringing under a
  // tenth of the lamps' unshadowed light traces its shadow ray by Russian roulette, its light
  // divided by the probability. The image is still the bright lamp's plus the seven others'.
  Scene eight = lamps_of_hall(0, 8);
  Scene bright = lamps_of_hall(0, 1), seven = lamps_of_hall(1, 7);
  for (Scene* scene : {&eight, &bright}) {
    const auto lamp = std::find_if(scene->nodes.begin(), scene->nodes.end(),
                                   [](const Node& node) { return node.light >= 0; });
    scene->lights[size_t(lamp->light)].intensity *= 20.0f;
  }
  const double sum = render_mean(bright, LightSampling::Mis, 24, 256, 1) +
                     render_mean(seven, LightSampling::Mis, 24, 256, 1);
  RenderSettings s;
  s.width = s.height = 24;
  s.max_depth = 1;
  Renderer renderer(test::context(), eight, s);
  for (int i = 0; i < 4; ++i) renderer.add_samples_full_frame(64);
  EXPECT_NEAR(test::mean(renderer.image()) / sum, 1.0, 0.02);
  const RenderCounters counters = renderer.counters();
  // Sampled each without the roulette, a floor point traces eight (7.1 a camera ray here): at
  // most half of that.
  EXPECT_LT(double(counters.shadow_rays) / double(counters.camera_rays), 4.0)
      << counters.shadow_rays << " shadow rays for " << counters.camera_rays << " camera rays";
}

}  // namespace
}  // namespace hipr
