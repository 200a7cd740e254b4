// The software traversal (hipr's own BVH, for devices without ray queries) against ray queries
// on the same device. Camera rays must find the same surfaces pixel for pixel (stage 1's
// G-buffer). Paths trace the same sample sequences, so images agree far more closely than two
// seeds do, though not exactly: rounding moves a hit point by an ulp, and a path whose later
// choices hang on it (a stochastic cutout hashes the ray's bits) goes its own way from there.
// The HiPR stages, cutout and determinism suites also run with HIPR_TRAVERSAL=software
// (tests/CMakeLists.txt: render_test_software_traversal).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "card_scene.h"
#include "hipr/hipr_stages.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "test_support.h"

namespace hipr {
namespace {

const vk::Context& software_context() {
  static const std::unique_ptr<vk::Context> ctx = [] {
    vk::ContextOptions options;
    options.validation = true;
    options.traversal = vk::Traversal::Software;
    return std::make_unique<vk::Context>(options);
  }();
  return *ctx;
}

ImageRGB render(const vk::Context& ctx, const Scene& scene, const RenderSettings& settings,
                uint32_t spp) {
  Renderer renderer(ctx, scene, settings);
  renderer.add_samples_full_frame(spp);
  return renderer.image();
}

// Mean squared difference relative to the pixels' own magnitude (relMSE's form).
double relative_difference(const ImageRGB& a, const ImageRGB& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.rgb.size(); ++i) {
    const double d = double(a.rgb[i]) - double(b.rgb[i]);
    const double m = 0.5 * (double(a.rgb[i]) + double(b.rgb[i]));
    sum += d * d / (m * m + 1e-2);
  }
  return sum / double(a.rgb.size());
}

std::vector<uint32_t> camera_hits(const vk::Context& ctx, const Scene& scene,
                                  const RenderSettings& settings) {
  Renderer renderer(ctx, scene, settings);
  hipr_stages(renderer).stage1_visibility(ChangeSet{});
  return renderer.gbuffer_instances();
}

// Renders with both traversals (and ray queries with another seed, the scale of noise).
void expect_traversals_agree(const Scene& scene, RenderSettings settings, uint32_t spp) {
  if (!test::context().has_ray_queries())
    GTEST_SKIP() << test::context().device_name() << " has no ray queries";
  if (test::context().software_traversal())
    GTEST_SKIP() << "the shared context traces in software (HIPR_TRAVERSAL)";
  ASSERT_TRUE(software_context().software_traversal());
  const std::vector<uint32_t> query_hits = camera_hits(test::context(), scene, settings);
  const std::vector<uint32_t> software_hits = camera_hits(software_context(), scene, settings);
  ASSERT_EQ(query_hits.size(), software_hits.size());
  size_t same = 0;
  for (size_t i = 0; i < query_hits.size(); ++i) same += query_hits[i] == software_hits[i];
  // A ray through an edge may take either side's triangle (the scenes keep their edges off the
  // pixel centres, where every traversal would have to break ties); nothing else may differ.
  EXPECT_GE(double(same), 0.999 * double(query_hits.size())) << same << " of " << query_hits.size();

  const ImageRGB queries = render(test::context(), scene, settings, spp);
  const ImageRGB software = render(software_context(), scene, settings, spp);
  settings.seed += 1;
  const ImageRGB other_seed = render(test::context(), scene, settings, spp);
  EXPECT_TRUE(test::all_finite(software));
  const double traversal_gap = relative_difference(queries, software);
  const double noise = relative_difference(queries, other_seed);
  EXPECT_LT(traversal_gap, 0.25 * noise) << "traversals " << traversal_gap << ", seeds " << noise;
  EXPECT_NEAR(test::mean(software), test::mean(queries), 0.01 * test::mean(queries));
  EXPECT_EQ(software_context().validation_errors(), 0u);
}

TEST(SoftwareTraversal, RendersWhatRayQueriesRender) {
  const Scene scene = load_scene(test::asset("cornell_sphere.glb"));
  expect_traversals_agree(scene, test::render_settings(64, 64, 16, 4, 3), 8);
}

TEST(SoftwareTraversal, AgreesOnRotatedMirroredHiddenAndCutoutInstances) {
  Scene scene = test::make_card_camera_scene(1.0f);
  MaterialParameters grey = test::black_material();
  grey.base_color = glm::vec3(0.6f);
  MaterialParameters mask = grey;
  mask.geometry_opacity = 0.4f;
  mask.alpha_cutoff = 0.5f;  // below the cutoff: invisible
  MaterialParameters blend = grey;
  blend.geometry_opacity = 0.5f;
  blend.alpha_cutoff = -1.0f;  // half the rays pass
  // Sizes and places that put no edge through a pixel centre.
  const glm::mat4 small = glm::scale(glm::mat4(1.0f), glm::vec3(0.437f));
  test::add_card(scene, "rotated",
                 glm::translate(glm::mat4(1.0f), glm::vec3(-0.483f, 0.511f, 0.0f)) *
                     glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(0.3f, 1.0f, 0.2f)) * small,
                 grey);
  test::add_card(scene, "mirrored",
                 glm::translate(glm::mat4(1.0f), glm::vec3(0.509f, 0.523f, -0.2f)) *
                     glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)) * small,
                 grey);
  test::add_card(scene, "masked",
                 glm::translate(glm::mat4(1.0f), glm::vec3(-0.491f, -0.517f, 0.0f)) * small, mask);
  test::add_card(scene, "blended",
                 glm::translate(glm::mat4(1.0f), glm::vec3(0.513f, -0.489f, 0.0f)) * small, blend);
  test::add_card(scene, "hidden",
                 glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 0.5f)) * small, grey);
  scene.nodes.back().visible = false;
  // A floor behind the cards, for shadows and bounces between instances.
  test::add_card(scene, "back",
                 glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -1.0f)) *
                     glm::scale(glm::mat4(1.0f), glm::vec3(3.0f)),
                 grey);
  expect_traversals_agree(scene, test::render_settings(64, 64, 16, 4, 5), 8);
}

TEST(SoftwareTraversal, SameSettingsTwiceAreBitIdentical) {
  const Scene scene = load_scene(test::asset("cornell_sphere.glb"));
  const RenderSettings settings = test::render_settings(32, 32, 16, 3, 1);
  EXPECT_EQ(render(software_context(), scene, settings, 2).rgb,
            render(software_context(), scene, settings, 2).rgb);
}

}  // namespace
}  // namespace hipr
