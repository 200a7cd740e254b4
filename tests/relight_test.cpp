// Relighting by linearity (light groups, relight.comp): the film keeps each emitter's share of
// the radiance apart, and an edit that only scales emitters shows the converged image relit.
#include <gtest/gtest.h>

#include <cmath>

#include "hipr/edits.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "test_support.h"

namespace hipr {
namespace {

RenderSettings settings(uint32_t seed = 4) { return test::render_settings(32, 32, 8, 6, seed); }

Scene sphere_box() { return load_scene(test::asset("cornell_sphere.glb")); }

ImageRGB render(const Scene& scene, const RenderSettings& s, uint32_t spp) {
  Renderer renderer(test::context(), scene, s);
  renderer.add_samples_full_frame(spp);
  return renderer.image();
}

// The displayed image right after an edit the renderer relit from `spp` converged samples.
ImageRGB relit_after(const Scene& before, const Edit& edit, uint32_t spp, bool* relit = nullptr) {
  Renderer renderer(test::context(), before, settings());
  renderer.add_samples_full_frame(spp);
  renderer.resolve_display_all(DisplayRule::Immediate);
  renderer.capture_stale_display();
  Scene after = before;
  apply_edit(after, edit);
  const bool done = renderer.relight(diff_scenes(before, after).emitter_scales);
  if (relit) *relit = done;
  return renderer.displayed_image();
}

double max_relative_difference(const ImageRGB& a, const ImageRGB& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.rgb.size(); ++i)
    worst = std::max(
        worst, std::abs(double(a.rgb[i]) - b.rgb[i]) / std::max(1e-3, double(std::abs(b.rgb[i]))));
  return worst;
}

TEST(LightGroups, EachEmitterHasAGroupAndTheSharesSumToTheImage) {
  Renderer renderer(test::context(), sphere_box(), settings());
  renderer.add_samples_full_frame(8);
  EXPECT_EQ(renderer.light_group_names(),
            (std::vector<std::string>{"light lamp", "emission light", "environment (none yet)"}));
  EXPECT_TRUE(renderer.pooled_emitters().empty());
  const ImageRGB image = renderer.image();
  const ImageRGB lamp = renderer.light_group_image(0), ceiling = renderer.light_group_image(1);
  double lamp_total = 0.0, ceiling_total = 0.0;
  for (size_t i = 0; i < image.rgb.size(); ++i) {
    EXPECT_NEAR(lamp.rgb[i] + ceiling.rgb[i], image.rgb[i], 1e-5 + 1e-5 * image.rgb[i]) << i;
    EXPECT_EQ(renderer.light_group_image(2).rgb[i], 0.0f) << "no environment";
    lamp_total += lamp.rgb[i];
    ceiling_total += ceiling.rgb[i];
  }
  EXPECT_GT(lamp_total, 0.0);
  EXPECT_GT(ceiling_total, 0.0);
}

// Keeping groups changes no radiance bit: the kernels with and without them make one image.
TEST(LightGroups, RadianceIsTheSameBitForBitWithoutGroups) {
  RenderSettings without = settings();
  without.light_groups = 0;
  for (const Scene& scene :
       {sphere_box(), load_scene(test::asset("furnace_sphere.gltf"), {.environment = "sky"})})
    EXPECT_EQ(render(scene, settings(), 4).rgb, render(scene, without, 4).rgb);
}

TEST(LightGroups, OverTheBudgetEmittersArePooledAndNotRelit) {
  RenderSettings one = settings();
  one.light_groups = 1;
  Renderer renderer(test::context(), sphere_box(), one);
  EXPECT_EQ(renderer.light_group_names(), std::vector<std::string>{"light lamp"});
  EXPECT_EQ(renderer.pooled_emitters(), std::vector<std::string>{"emission light"});
  const uint32_t lamp = uint32_t(find_node(sphere_box(), "lamp"));
  EXPECT_FALSE(renderer.relight({{EmitterScale::Kind::Material, 3, glm::vec3(2.0f)}}));
  EXPECT_FALSE(renderer.relight({{EmitterScale::Kind::PunctualLight, lamp, glm::vec3(2.0f)},
                                 {EmitterScale::Kind::Material, 3, glm::vec3(2.0f)}}));
  EXPECT_TRUE(renderer.relight({{EmitterScale::Kind::PunctualLight, lamp, glm::vec3(2.0f)}}));
}

// With one emitter every path's radiance is in its group, and light selection does not depend
// on its power: the relit image is the edited scene's render, up to float rounding.
TEST(Relight, OneEmitterRelitIsTheEditedRenderExactly) {
  const Scene before = load_scene(test::asset("cornell_box.gltf"));
  const Edit dimmer = MaterialEdit{
      "light", {{"emission_luminance", {2.5f}}, {"emission_color", {1.0f, 0.5f, 0.25f}}}};
  bool relit = false;
  const ImageRGB image = relit_after(before, dimmer, 16, &relit);
  ASSERT_TRUE(relit);
  Scene after = before;
  apply_edit(after, dimmer);
  EXPECT_LT(max_relative_difference(image, render(after, settings(), 16)), 1e-4);
  EXPECT_GT(max_relative_difference(render(before, settings(), 16), render(after, settings(), 16)),
            0.5);
}

// With two emitters, light selection follows their powers, so the edited scene's samples differ;
// the relit image is an unbiased estimate of it: equal within noise, unlike the stale image.
TEST(Relight, TwoEmittersRelitMatchesTheEditedSceneWithinNoise) {
  const Scene before = sphere_box();
  const Edit lamp = LightEdit{"lamp", 0.125f, glm::vec3(0.3f, 0.6f, 1.0f), std::nullopt};
  Scene after = before;
  apply_edit(after, lamp);
  RenderSettings s = settings();
  std::vector<ImageRGB> relit;
  for (uint32_t seed : {11u, 12u, 13u}) {
    Renderer renderer(test::context(), before, test::render_settings(32, 32, 8, 6, seed));
    renderer.add_samples_full_frame(64);
    renderer.resolve_display_all(DisplayRule::Immediate);
    renderer.capture_stale_display();
    ASSERT_TRUE(renderer.relight(diff_scenes(before, after).emitter_scales));
    relit.push_back(renderer.displayed_image());
  }
  s.seed = 99;
  const ImageRGB reference = render(after, s, 1024);
  EXPECT_LT(test::error_to_noise_ratio(relit, reference), 1.6);
  std::vector<ImageRGB> stale;
  for (uint32_t seed : {11u, 12u, 13u})
    stale.push_back(render(before, test::render_settings(32, 32, 8, 6, seed), 64));
  EXPECT_GT(test::error_to_noise_ratio(stale, reference), 3.0);
}

// A slider drag: edits in a row with no sample between them relight the relit image again.
TEST(Relight, EditsInARowCompose) {
  const Scene before = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), before, settings());
  renderer.add_samples_full_frame(16);
  renderer.resolve_display_all(DisplayRule::Immediate);
  Scene scene = before;
  for (float nits : {10.0f, 5.0f, 2.5f}) {
    const Scene previous = scene;
    apply_edit(scene, MaterialEdit{"light", {{"emission_luminance", {nits}}}});
    renderer.capture_stale_display();
    ASSERT_TRUE(renderer.relight(diff_scenes(previous, scene).emitter_scales));
    renderer.mark_all_owed();  // as the scheduler does: the accumulation is no longer current
  }
  EXPECT_LT(max_relative_difference(renderer.displayed_image(), render(scene, settings(), 16)),
            1e-4);
}

// The viewer's flow for a scene loaded without light: switch the studio on, then turn its
// intensity: the group kept for an environment makes the second edit a relight.
TEST(Relight, AnEnvironmentSwitchedOnLaterIsRelitToo) {
  Scene scene = load_scene(test::asset("furnace_sphere.gltf"), {.environment = "none"});
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 4);
  Scene before = scene;
  apply_edit(scene, EnvironmentEdit{.source = std::filesystem::path("studio")});
  scheduler.on_edit(scene, diff_scenes(before, scene));
  EXPECT_FALSE(scheduler.relit());
  while (scheduler.work_since_edit() < 16.0) scheduler.step();
  before = scene;
  apply_edit(scene, EnvironmentEdit{.intensity = 0.25f});
  scheduler.on_edit(scene, diff_scenes(before, scene));
  ASSERT_TRUE(scheduler.relit());
  EXPECT_LT(max_relative_difference(scheduler.displayed_image(), render(scene, settings(), 16)),
            1e-4);
}

TEST(Relight, OnlyLinearEditsScaleEmitters) {
  const Scene base = sphere_box();
  const auto scales = [&](const Edit& edit) {
    Scene after = base;
    apply_edit(after, edit);
    return diff_scenes(base, after).emitter_scales;
  };
  EXPECT_EQ(scales(LightEdit{"lamp", 2.0f, std::nullopt, std::nullopt}).size(), 1u);
  EXPECT_EQ(scales(MaterialEdit{"light", {{"emission_luminance", {3.0f}}}}).size(), 1u);
  EXPECT_TRUE(scales(LightEdit{"lamp", std::nullopt, std::nullopt, 2.0f}).empty()) << "range";
  EXPECT_TRUE(scales(TransformEdit{"lamp", glm::vec3(0.1f, 0.0f, 0.0f), std::nullopt}).empty())
      << "moved";
  EXPECT_TRUE(
      scales(MaterialEdit{"light",
                          {{"emission_luminance", {3.0f}}, {"base_color", {0.5f, 0.5f, 0.5f}}}})
          .empty())
      << "emission and more";
  EXPECT_TRUE(
      scales(MaterialEdit{"white",
                          {{"emission_color", {1.0f, 1.0f, 1.0f}}, {"emission_luminance", {3.0f}}}})
          .empty())
      << "from black";
  const EmitterScale lamp =
      scales(LightEdit{"lamp", 0.25f, glm::vec3(1.0f, 0.5f, 0.0f), std::nullopt})[0];
  EXPECT_EQ(lamp.kind, EmitterScale::Kind::PunctualLight);
  EXPECT_FLOAT_EQ(lamp.factor.r, 0.5f);  // 0.5 cd -> 0.25 cd
  EXPECT_FLOAT_EQ(lamp.factor.g, 0.25f);
  EXPECT_FLOAT_EQ(lamp.factor.b, 0.0f);
  Scene sky = load_scene(test::asset("furnace_sphere.gltf"), {.environment = "studio"});
  Scene brighter = sky;
  apply_edit(brighter, EnvironmentEdit{.intensity = 3.0f});
  ASSERT_EQ(diff_scenes(sky, brighter).emitter_scales.size(), 1u);
  EXPECT_EQ(diff_scenes(sky, brighter).emitter_scales[0].factor, glm::vec3(3.0f));
  apply_edit(brighter, EnvironmentEdit{.rotation = 1.0f});
  EXPECT_TRUE(diff_scenes(sky, brighter).emitter_scales.empty()) << "rotated";
}

// Through the scheduler: the HiPR policy relights, shows the relit image before any sample, and
// still ends on the full-frame render of the edited scene, bit for bit.
TEST(Relight, TheSchedulerShowsItAtOnceAndEndsOnTheFreshRender) {
  Scene scene = sphere_box();
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 4);
  while (scheduler.work_since_edit() < 32.0) scheduler.step();
  const Scene before = scene;
  apply_edit(scene, LightEdit{"lamp", 2.0f, std::nullopt, std::nullopt});
  scheduler.on_edit(scene, diff_scenes(before, scene));
  EXPECT_TRUE(scheduler.relit());
  const ImageRGB shown = scheduler.displayed_image();
  EXPECT_LT(test::error_to_noise_ratio({shown, render(scene, settings(21), 32)},
                                       render(scene, settings(22), 512)),
            2.0);
  // Moving the lamp cannot be relit.
  const Scene lit = scene;
  apply_edit(scene, TransformEdit{"lamp", glm::vec3(0.05f, 0.0f, 0.0f), std::nullopt});
  scheduler.on_edit(scene, diff_scenes(lit, scene));
  EXPECT_FALSE(scheduler.relit());
  while (scheduler.work_since_edit() < 32.0) scheduler.step();
  EXPECT_EQ(scheduler.displayed_image().rgb, render(scene, settings(), 32).rgb);
}

// The relit image is the edited scene's estimate from every converged sample: while pixels have
// fewer fresh samples than that, the weighing rules show it as it is (fresh noise cannot improve
// it), and the run still ends on the full-frame render.
TEST(Relight, TheRelitValueStaysUntilTheFreshSamplesAreAsMany) {
  for (const DisplayRule rule : {DisplayRule::Difference, DisplayRule::Blend}) {
    Scene scene = sphere_box();
    Renderer renderer(test::context(), scene, settings());
    Scheduler scheduler(renderer, Policy::Hipr, 4);
    scheduler.set_display_rule(rule);
    scheduler.set_first_visit_spp(2);
    while (scheduler.work_since_edit() < 8.0) scheduler.step();
    const Scene before = scene;
    apply_edit(scene, LightEdit{"lamp", 0.5f, glm::vec3(1.0f, 0.8f, 0.6f), std::nullopt});
    scheduler.on_edit(scene, diff_scenes(before, scene));
    ASSERT_TRUE(scheduler.relit());
    const ImageRGB relit = scheduler.displayed_image();
    while (scheduler.work_since_edit() < 6.0) scheduler.step();  // every pixel has 2 to 6 samples
    EXPECT_EQ(scheduler.displayed_image().rgb, relit.rgb) << display_rule_name(rule);
    while (scheduler.work_since_edit() < 8.0) scheduler.step();
    EXPECT_EQ(scheduler.displayed_image().rgb, render(scene, settings(), 8).rgb)
        << display_rule_name(rule);
  }
}

}  // namespace
}  // namespace hipr
