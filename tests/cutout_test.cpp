// Opacity cutout (alphaMode MASK / BLEND, geometry_opacity) in every ray query: camera rays,
// shadow rays, stage 1's G-buffer; determinism with stochastic coverage; opaque geometry flags.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "card_scene.h"
#include "hipr/hipr_stages.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "render/gpu_scene.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

RenderSettings card_settings(uint32_t tile = 16) {
  return test::render_settings(32, 32, tile, 4, 5);
}

MaterialParameters cutout(float opacity, float cutoff) {
  MaterialParameters m = test::black_material();
  m.geometry_opacity = opacity;
  m.alpha_cutoff = cutoff;
  return m;
}

// A black card in front of a uniform environment of radiance 1: the image mean is the
// fraction of camera rays the card lets through.
Scene card_before_sky(const MaterialParameters& card) {
  Scene scene = test::make_card_camera_scene(1.0f);
  test::add_card(scene, "card", glm::mat4(1.0f), card);
  return scene;
}

ImageRGB render(const Scene& scene, const RenderSettings& s, uint32_t spp) {
  Renderer renderer(test::context(), scene, s);
  renderer.add_samples_full_frame(spp);
  return renderer.image();
}

TEST(Cutout, MaskBelowTheCutoffIsInvisible) {
  EXPECT_NEAR(test::mean(render(card_before_sky(cutout(0.4f, 0.5f)), card_settings(), 2)), 1.0,
              1e-4);
  EXPECT_NEAR(test::mean(render(card_before_sky(cutout(0.4f, 0.3f)), card_settings(), 2)), 0.0,
              1e-6);
}

TEST(Cutout, BlendCoversTheFractionOfItsOpacity) {
  const double through =
      test::mean(render(card_before_sky(cutout(0.25f, -1.0f)), card_settings(), 16));
  EXPECT_NEAR(through, 0.75, 0.02);  // 16k samples: the standard error is 0.0034
}

// A 2x2 texture whose alpha is 1 on the diagonal and 0 off it.
void add_diagonal_alpha(Scene& scene, MaterialParameters& card) {
  Image image;
  image.name = "diagonal";
  image.width = image.height = 2;
  image.rgba8 = {255, 255, 255, 255, 255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 255};
  scene.images.push_back(image);
  Texture texture;
  texture.name = "diagonal";
  texture.flags = abi::kTextureNearest;
  scene.textures.push_back(texture);
  card.base_color_texture = 0;
  card.base_color = glm::vec3(0.0f);
}

TEST(Cutout, TextureAlphaCutsOutTexels) {
  MaterialParameters card = cutout(1.0f, 0.5f);
  Scene scene = test::make_card_camera_scene(1.0f);
  add_diagonal_alpha(scene, card);
  test::add_card(scene, "card", glm::mat4(1.0f), card);
  const ImageRGB image = render(scene, card_settings(), 1);
  const auto at = [&](uint32_t x, uint32_t y) { return image.rgb[(size_t(y) * 32 + x) * 3]; };
  EXPECT_EQ(at(8, 8), 0.0f);   // texel (0,0): opaque, black card
  EXPECT_EQ(at(24, 8), 1.0f);  // texel (1,0): cut out, sky
  EXPECT_EQ(at(8, 24), 1.0f);
  EXPECT_EQ(at(24, 24), 0.0f);
  // OPAQUE materials ignore texture alpha.
  scene.materials[0].params = card;
  scene.materials[0].params.alpha_cutoff = -1.0f;
  scene.materials[0].params.flags |= abi::kMaterialIgnoreTextureAlpha;
  EXPECT_EQ(test::mean(render(scene, card_settings(), 1)), 0.0);
}

// A white floor filling the view, lit straight on by a directional light of 1 lux, under a
// card behind the camera (unseen) that shadows all of it.
Scene shadowed_floor(const MaterialParameters& blocker) {
  Scene scene = test::make_card_camera_scene(0.0f);
  MaterialParameters white = default_material_params();
  white.base_color = glm::vec3(1.0f);
  white.specular_weight = 0.0f;
  test::add_card(scene, "floor", glm::mat4(1.0f), white);
  test::add_card(scene, "blocker",
                 glm::scale(glm::translate(glm::mat4(1.0f), {0, 0, 5}), glm::vec3(3.0f)), blocker);
  PunctualLight sun;
  sun.name = "sun";
  sun.type = LightType::Directional;
  scene.lights.push_back(sun);
  Node node;
  node.name = "sun";
  node.light = 0;  // lights travel down their node's -Z: toward the floor
  scene.nodes.push_back(node);
  scene.children.push_back({});
  scene.root_nodes.push_back(uint32_t(scene.nodes.size() - 1));
  return scene;
}

TEST(Cutout, ShadowRaysHonourTheCutout) {
  const double lit = 1.0 / M_PI;  // white Lambert under 1 lux
  EXPECT_NEAR(test::mean(render(shadowed_floor(cutout(0.4f, 0.5f)), card_settings(), 2)), lit,
              1e-3);
  EXPECT_NEAR(test::mean(render(shadowed_floor(cutout(0.4f, 0.3f)), card_settings(), 2)), 0.0,
              1e-6);
  EXPECT_NEAR(test::mean(render(shadowed_floor(cutout(0.25f, -1.0f)), card_settings(), 16)),
              0.75 * lit, 0.01);
}

TEST(Cutout, StageOneSeesThroughCutouts) {
  for (const float cutoff : {0.5f, 0.3f}) {
    Renderer renderer(test::context(), card_before_sky(cutout(0.4f, cutoff)), card_settings());
    hipr_stages(renderer).stage1_visibility(ChangeSet{});
    const uint32_t expected = cutoff > 0.4f ? UINT32_MAX : 0u;  // the sky, or instance 0 (the card)
    for (uint32_t id : renderer.gbuffer_instances()) ASSERT_EQ(id, expected) << "cutoff " << cutoff;
  }
}

TEST(Cutout, StochasticCoverageIsDeterministic) {
  const Scene scene = card_before_sky(cutout(0.5f, -1.0f));
  const ImageRGB reference = render(scene, card_settings(16), 4);
  for (uint32_t tile : {1u, 7u, 13u, 32u})
    EXPECT_EQ(render(scene, card_settings(tile), 4).rgb, reference.rgb) << tile;
  // The same holds for a card whose shadow is stochastic.
  const Scene shadow = shadowed_floor(cutout(0.5f, -1.0f));
  EXPECT_EQ(render(shadow, card_settings(8), 4).rgb, render(shadow, card_settings(11), 4).rgb);
}

TEST(Cutout, OpaqueScenesBuildOpaqueGeometry) {
  const Scene cornell = load_scene(test::asset("cornell_box.gltf"));
  EXPECT_EQ(Renderer(test::context(), cornell, card_settings()).scene_stats().cutout_geometries,
            0u);
  EXPECT_EQ(Renderer(test::context(), card_before_sky(cutout(1.0f, -1.0f)), card_settings())
                .scene_stats()
                .cutout_geometries,
            0u);
  EXPECT_EQ(Renderer(test::context(), card_before_sky(cutout(1.0f, 0.5f)), card_settings())
                .scene_stats()
                .cutout_geometries,
            1u);
}

TEST(Cutout, OpacityEditOfAnOpaqueMaterialRebuildsItsGeometry) {
  Scene scene = card_before_sky(cutout(1.0f, -1.0f));
  Renderer renderer(test::context(), scene, card_settings());
  renderer.add_samples_full_frame(1);
  EXPECT_EQ(test::mean(renderer.image()), 0.0);
  ChangeSet changes;
  changes.materials = true;
  scene.materials[0].params.geometry_opacity = 0.0f;
  renderer.update_scene(scene, changes);
  EXPECT_EQ(renderer.scene_stats().cutout_geometries, 1u);
  renderer.reset();
  renderer.add_samples_full_frame(1);
  EXPECT_NEAR(test::mean(renderer.image()), 1.0, 1e-4);
  scene.materials[0].params.geometry_opacity = 1.0f;
  renderer.update_scene(scene, changes);
  EXPECT_EQ(renderer.scene_stats().cutout_geometries, 0u);
  renderer.reset();
  renderer.add_samples_full_frame(1);
  EXPECT_EQ(test::mean(renderer.image()), 0.0);
}

}  // namespace
}  // namespace hipr
