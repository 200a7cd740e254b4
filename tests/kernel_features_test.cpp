// "Skip what a scene doesn't need": the kernel features a scene needs (render/kernel_features.h),
// a specialized kernel rendering exactly what the uber kernel renders, and the rays nobody
// needs (no segment toward a last vertex where nothing emits; no camera ray in a tile that sees
// only background) left out without changing a single sample.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <regex>
#include <string>

#include "card_scene.h"
#include "hipr/edits.h"
#include "hipr/hipr_stages.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "render/background_tiles.h"
#include "render/kernel_features.h"
#include "render/render_readback.h"
#include "shaders/shared/abi.h"
#include "test_support.h"
#include "vk/embedded_shaders.h"

namespace hipr {
namespace {

uint32_t bit(const char* define) { return kernel_feature_bit(define); }

// ---- which features a scene needs (CPU) ----

TEST(KernelFeatures, TableFollowsFeaturesGlsl) {
  std::string glsl;
  for (const vk::EmbeddedShaderFile& file : vk::embedded_shader_files())
    if (file.path == "common/features.glsl") glsl = std::string(file.text);
  ASSERT_FALSE(glsl.empty());
  std::vector<std::string> defines;
  const std::regex guard("#ifndef (HIPR_FEATURE_[A-Z_]+)");
  for (auto it = std::sregex_iterator(glsl.begin(), glsl.end(), guard);
       it != std::sregex_iterator(); ++it)
    defines.push_back((*it)[1]);
  std::vector<std::string> table;
  uint32_t bits = 0;
  for (const KernelFeature& f : kernel_feature_table()) {
    table.emplace_back(f.define);
    EXPECT_EQ(bits & f.bit, 0u) << f.define << " shares a bit";
    bits |= f.bit;
    EXPECT_NE(f.material_needs == nullptr, f.scene_needs == nullptr)
        << f.define << ": one kind of test";
  }
  EXPECT_EQ(table, defines)
      << "kernel_features.cpp and features.glsl list the same features in the same order";
  EXPECT_EQ(bits, all_kernel_features());
}

TEST(KernelFeatures, TheLambertCornellBoxNeedsOnlyEmission) {
  EXPECT_EQ(kernel_features(load_scene(test::asset("cornell_box.gltf"))),
            bit("HIPR_FEATURE_EMISSION"));
  EXPECT_EQ(kernel_features(load_scene(test::asset("cornell_sphere.glb"))),
            bit("HIPR_FEATURE_EMISSION") | bit("HIPR_FEATURE_PUNCTUAL_LIGHTS"));
}

TEST(KernelFeatures, EachFeatureIsFoundWhereTheSceneUsesIt) {
  const Scene box = load_scene(test::asset("cornell_box.gltf"));
  const uint32_t base = kernel_features(box);
  const auto with = [&](auto change) {
    Scene scene = box;
    change(scene, scene.materials[0].params);  // "white", used by the walls
    return kernel_features(scene) & ~base;
  };
  using M = MaterialParameters;
  EXPECT_EQ(with([](Scene&, M& m) { m.metallic_roughness_texture = 0; }),
            bit("HIPR_FEATURE_TEXTURES"));
  EXPECT_EQ(with([](Scene&, M& m) {
              m.base_metalness = 1.0f;
              m.specular_weight = 1.0f;
            }),
            bit("HIPR_FEATURE_METAL"));
  // The texture scales metalness down: the dielectric specular shows where it does.
  EXPECT_EQ(
      with([](Scene&, M& m) {
        m.base_metalness = 1.0f;
        m.specular_weight = 1.0f;
        m.metallic_roughness_texture = 0;
      }),
      bit("HIPR_FEATURE_METAL") | bit("HIPR_FEATURE_SPECULAR") | bit("HIPR_FEATURE_TEXTURES"));
  EXPECT_EQ(with([](Scene&, M& m) { m.normal_texture = 0; }),
            bit("HIPR_FEATURE_TEXTURES") | bit("HIPR_FEATURE_NORMAL_MAP"));
  EXPECT_EQ(with([](Scene&, M& m) { m.geometry_opacity = 0.5f; }), bit("HIPR_FEATURE_CUTOUT"));
  EXPECT_EQ(with([](Scene&, M& m) { m.alpha_cutoff = 0.5f; }), bit("HIPR_FEATURE_CUTOUT"));
  EXPECT_EQ(with([](Scene&, M& m) {
              m.transmission_weight = 1.0f;
              m.transmission_depth = 0.1f;
              m.flags &=
                  ~abi::kMaterialThinWalled;  // glTF without KHR_materials_volume is thin-walled
            }),
            bit("HIPR_FEATURE_TRANSMISSION") | bit("HIPR_FEATURE_VOLUME"));
  EXPECT_EQ(with([](Scene&, M& m) {
              m.transmission_weight = 1.0f;
              m.transmission_depth = 0.1f;
              m.flags |= abi::kMaterialThinWalled;  // a thin wall has no inside to absorb in
            }),
            bit("HIPR_FEATURE_TRANSMISSION"));
  EXPECT_EQ(with([](Scene& s, M&) { s.environment = test::uniform_environment(1.0f); }),
            bit("HIPR_FEATURE_ENVIRONMENT"));
  EXPECT_EQ(with([](Scene& s, M&) {
              s.lights.push_back({});
              s.nodes.back().light = 0;
            }),
            bit("HIPR_FEATURE_PUNCTUAL_LIGHTS"));
  // A material no primitive uses needs nothing.
  EXPECT_EQ(with([](Scene& s, M&) {
              Material unused{"unused", default_material_params()};
              unused.params.coat_weight = 1.0f;
              s.materials.push_back(unused);
            }),
            0u);

  // Emission as the kernel sees it: colour x luminance, a negative pair or NaN included.
  Scene dark = load_scene(test::asset("furnace_sphere.gltf"));
  dark.environment.reset();
  EXPECT_EQ(kernel_features(dark), 0u);
  dark.materials[0].params.emission_color = glm::vec3(-1.0f, 0.0f, 0.0f);
  dark.materials[0].params.emission_luminance = -2.0f;
  EXPECT_EQ(kernel_features(dark), bit("HIPR_FEATURE_EMISSION"));
  dark.materials[0].params.emission_luminance = std::nanf("");
  EXPECT_EQ(kernel_features(dark), bit("HIPR_FEATURE_EMISSION"));
}

// ---- a specialized kernel renders what the uber kernel renders ----

RenderSettings settings() { return test::render_settings(48, 48, 8, 6, 3); }

struct Rendered {
  ImageRGB image;
  RenderCounters counters;
  uint32_t features = 0;
};

Rendered render(const Scene& scene, const RenderSettings& s, uint32_t spp) {
  Renderer renderer(test::context(), scene, s);
  renderer.add_samples_full_frame(spp);
  return {renderer.image(), renderer.counters(), renderer.kernel_features()};
}

Rendered render_uber(const Scene& scene, RenderSettings s, uint32_t spp) {
  s.specialize_kernel = false;
  return render(scene, s, spp);
}

// The Cornell sphere lit by its point lamp alone: nothing emits, there is no environment.
Scene lamp_only() {
  Scene scene = load_scene(test::asset("cornell_sphere.glb"));
  for (Material& m : scene.materials) m.params.emission_luminance = 0.0f;
  scene.lights[0].intensity = 2.0f;
  return scene;
}

// A textured card of 60% stochastic opacity in front of an emissive card, under a sky.
Scene textured_blend_card() {
  Scene scene = test::make_card_camera_scene(0.5f);
  MaterialParameters glow = test::black_material();
  glow.emission_luminance = 2.0f;
  test::add_card(scene, "glow", glm::translate(glm::mat4(1.0f), {0.3f, 0.2f, -1.0f}), glow);
  Image image;
  image.name = "checker";
  image.width = image.height = 2;
  image.rgba8 = {255, 40, 40, 255, 40, 255, 40, 255, 40, 40, 255, 255, 230, 230, 230, 255};
  scene.images.push_back(image);
  Texture texture;
  texture.name = "checker";
  scene.textures.push_back(texture);
  MaterialParameters card = default_material_params();
  card.base_color_texture = 0;
  card.geometry_opacity = 0.6f;
  card.flags |= abi::kMaterialIgnoreTextureAlpha;
  test::add_card(scene, "card", glm::scale(glm::mat4(1.0f), glm::vec3(0.7f)), card);
  return scene;
}

// A metal card whose metallic-roughness texture makes half of it dielectric, under a sky.
Scene half_metal_card() {
  Scene scene = test::make_card_camera_scene(1.0f);
  Image image;
  image.name = "metalness";
  image.width = image.height = 2;
  image.rgba8 = {0, 128, 255, 255, 0, 60, 0,   255,
                 0, 200, 0,   255, 0, 30, 255, 255};  // G roughness, B metalness
  scene.images.push_back(image);
  Texture texture;
  texture.name = "metalness";
  texture.flags = abi::kTextureNearest;
  scene.textures.push_back(texture);
  MaterialParameters card = default_material_params();
  card.base_color = glm::vec3(0.9f, 0.6f, 0.3f);
  card.base_metalness = 1.0f;
  card.metallic_roughness_texture = 0;
  test::add_card(scene, "card", glm::rotate(glm::mat4(1.0f), 0.4f, glm::vec3(1.0f, 0.0f, 0.0f)),
                 card);
  return scene;
}

struct SceneCase {
  const char* name;
  Scene (*make)();
  bool fewer_rays;  // the specialized kernel leaves out rays the uber kernel traces
};

class SpecializedKernel : public ::testing::TestWithParam<SceneCase> {};

TEST_P(SpecializedKernel, RendersWhatTheUberKernelRendersBitForBit) {
  const Scene scene = GetParam().make();
  const Rendered specialized = render(scene, settings(), 2);
  const Rendered uber = render_uber(scene, settings(), 2);
  EXPECT_EQ(specialized.features, kernel_features(scene));
  EXPECT_EQ(uber.features, all_kernel_features());
  EXPECT_GT(test::mean(uber.image), 0.0) << "a black image would prove nothing";
  EXPECT_EQ(specialized.image.rgb, uber.image.rgb);
  if (GetParam().fewer_rays)
    EXPECT_LT(specialized.counters.rays, uber.counters.rays);
  else
    EXPECT_EQ(specialized.counters.rays, uber.counters.rays);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, SpecializedKernel,
    ::testing::Values(
        SceneCase{"CornellBox", [] { return load_scene(test::asset("cornell_box.gltf")); }, false},
        SceneCase{"CornellSphere", [] { return load_scene(test::asset("cornell_sphere.glb")); },
                  false},
        SceneCase{"LampOnly", lamp_only, true},
        SceneCase{"TexturedBlendCard", textured_blend_card, false},
        SceneCase{"HalfMetalCard", half_metal_card, false},
        SceneCase{"FurnaceUnderSky",
                  [] { return test::make_furnace_scene(1.0f, glm::vec3(0.0f), 0.8f, 1.0f); },
                  false}),
    [](const testing::TestParamInfo<SceneCase>& param_info) {
      return std::string(param_info.param.name);
    });

// ---- rays nobody needs ----

TEST(RaysNobodyNeeds, AnUnlitSceneTracesNone) {
  Scene scene = test::make_furnace_scene(1.0f, glm::vec3(0.0f), 0.8f, 1.0f);
  scene.environment.reset();  // no emitter, no light, no environment: black
  const Rendered specialized = render(scene, settings(), 2);
  const Rendered uber = render_uber(scene, settings(), 2);
  EXPECT_EQ(specialized.counters.rays, 0u);
  EXPECT_GT(uber.counters.rays, 0u);
  EXPECT_EQ(specialized.counters.samples, uber.counters.samples);
  EXPECT_EQ(specialized.image.rgb, uber.image.rgb);
  EXPECT_EQ(test::mean(uber.image), 0.0);
}

// ---- tiles that see only background ----

// Renders with and without the background-tile shortcut: the same samples, fewer rays.
void expect_background_tiles_change_nothing(const Scene& scene, double max_ray_share,
                                            const RenderSettings& skip = settings()) {
  RenderSettings trace = skip;
  trace.skip_background_tiles = false;
  const Rendered a = render(scene, skip, 2);
  const Rendered b = render(scene, trace, 2);
  EXPECT_EQ(a.image.rgb, b.image.rgb);
  EXPECT_EQ(a.counters.samples, b.counters.samples);
  EXPECT_EQ(a.counters.non_finite_samples, b.counters.non_finite_samples);
  EXPECT_LT(double(a.counters.rays), max_ray_share * double(b.counters.rays));
}

std::vector<uint32_t> background_mask(const Scene& scene, const RenderSettings& s = settings()) {
  return BackgroundTiles(scene).mask(scene, s.width, s.height, s.tile_size);
}

size_t count_background(const std::vector<uint32_t>& mask) {
  return size_t(std::count(mask.begin(), mask.end(), 1u));
}

Scene cornell_from_afar() {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  apply_edit(scene, CameraEdit{glm::vec3(0.0f, 0.0f, -6.0f), std::nullopt});  // it looks down +Z
  return scene;
}

// The furnace sphere fills the middle of the frame: 64 x 64 pixels in tiles of 8 leave its
// corners empty (its bounding box would cover them; its triangles' boxes do not).
RenderSettings furnace_settings() {
  RenderSettings s = settings();
  s.width = s.height = 64;
  return s;
}

TEST(BackgroundTiles, FurnaceSphereUnderASkyHasItsCornersWithoutRayQueries) {
  const Scene scene = test::make_furnace_scene(1.0f, glm::vec3(3.0f, -2.0f, 1.0f), 0.8f, 1.0f);
  const size_t background = count_background(background_mask(scene, furnace_settings()));
  EXPECT_GE(background, 4u) << "the sphere leaves the frame's corners empty";
  EXPECT_LT(background, 64u / 4);
  expect_background_tiles_change_nothing(scene, 0.97, furnace_settings());
}

TEST(BackgroundTiles, FurnaceSphereWithoutEnvironment) {
  Scene scene = test::make_furnace_scene(1.0f, glm::vec3(0.0f), 0.8f, 1.0f);
  scene.environment.reset();
  scene.materials[0].params.emission_luminance = 1.0f;  // something to see: the sphere glows
  expect_background_tiles_change_nothing(scene, 0.97, furnace_settings());
}

TEST(BackgroundTiles, CornellBoxFromAfar) {
  const Scene scene = cornell_from_afar();
  EXPECT_GT(count_background(background_mask(scene)), 36u / 2);
  expect_background_tiles_change_nothing(scene, 0.7);
}

TEST(BackgroundTiles, FollowTheCameraAndTheObjects) {
  // Renders from afar, then moves a block into the empty part of the frame and the camera a bit:
  // the mask is recomputed, so the edited scene renders exactly as without the shortcut.
  Scene scene = cornell_from_afar();
  Renderer renderer(test::context(), scene, settings());
  renderer.add_samples_full_frame(1);
  const std::vector<uint32_t> before = background_mask(scene);
  for (const Edit& edit :
       std::vector<Edit>{TransformEdit{"tall_block", glm::vec3(0.9f, 0.3f, 0.0f), std::nullopt},
                         CameraEdit{glm::vec3(0.2f, 0.0f, 0.5f), std::nullopt}}) {
    const Scene previous = scene;
    apply_edit(scene, edit);
    renderer.update_scene(scene, diff_scenes(previous, scene));
  }
  EXPECT_NE(background_mask(scene), before);
  renderer.reset();
  renderer.add_samples_full_frame(2);
  RenderSettings trace = settings();
  trace.skip_background_tiles = false;
  EXPECT_EQ(renderer.image().rgb, render(scene, trace, 2).image.rgb);
}

// HiPR from afar: a block outside the box moves back in, so the tiles it left are active and see
// only background now (stage 2 renders them with the shortcut). Stages 1-3 and the scheduled
// re-render give the same tile flags, weights, schedule and image with and without it.
TEST(BackgroundTiles, HiprStagesAreTheSameWithTheShortcut) {
  Scene before = cornell_from_afar();
  apply_edit(before, TransformEdit{"short_block", glm::vec3(-0.9f, 0.0f, 0.0f), std::nullopt});
  const Scene after = cornell_from_afar();
  const ChangeSet changes = diff_scenes(before, after);
  const std::vector<uint32_t> left = background_mask(after);
  struct Result {
    std::vector<uint32_t> flags, schedule;
    std::vector<double> weights;
    ImageRGB image;
    uint64_t rays;
  };
  const auto run = [&](bool skip) {
    RenderSettings s = settings();
    s.skip_background_tiles = skip;
    Renderer renderer(test::context(), before, s);
    renderer.add_samples_full_frame(1);
    hipr_stages(renderer).stage1_visibility({});
    renderer.update_scene(after, changes);
    renderer.mark_all_owed();
    renderer.reset_counters();
    hipr_stages(renderer).stage1_visibility(changes);
    test::discover_all(renderer, 2);
    hipr_stages(renderer).build_schedule();
    renderer.render_schedule(0, renderer.tile_count(), 2, true);
    return Result{read_tile_flags(renderer), read_schedule(renderer), read_tile_weights(renderer),
                  renderer.image(), renderer.counters().rays};
  };
  const Result skipped = run(true), traced = run(false);
  size_t active_background = 0;
  for (size_t t = 0; t < left.size(); ++t)
    active_background += left[t] && (traced.flags[t] & abi::kTileActive) ? 1 : 0;
  EXPECT_GT(active_background, 0u);
  EXPECT_EQ(skipped.flags, traced.flags);
  EXPECT_EQ(skipped.weights, traced.weights);
  EXPECT_EQ(skipped.schedule, traced.schedule);
  EXPECT_EQ(skipped.image.rgb, traced.image.rgb);
  EXPECT_LT(skipped.rays, traced.rays);
}

TEST(BackgroundTiles, NoneAroundACameraInsideGeometryAllWhenEverythingIsBehind) {
  Scene inside = load_scene(test::asset("cornell_box.gltf"));
  EXPECT_EQ(count_background(background_mask(inside)), 0u);
  // The camera inside the tall block: every direction may hit it.
  apply_edit(inside, CameraEdit{std::nullopt, glm::translate(glm::mat4(1.0f),
                                                             glm::vec3(0.3685f, 0.15f, 0.35125f))});
  EXPECT_EQ(count_background(background_mask(inside)), 0u);
  // In front of the box, turned away from it (down -Z): nothing to see.
  Scene away = load_scene(test::asset("cornell_box.gltf"));
  apply_edit(away, CameraEdit{std::nullopt,
                              glm::translate(glm::mat4(1.0f), glm::vec3(0.278f, 0.273f, -0.8f))});
  EXPECT_EQ(count_background(background_mask(away)), 36u);
  // Hidden instances are never hit.
  Scene hidden = cornell_from_afar();
  const size_t shown = count_background(background_mask(hidden));
  for (Node& node : hidden.nodes)
    node.visible = node.name != "tall_block" && node.name != "short_block";
  EXPECT_GE(count_background(background_mask(hidden)), shown);
  for (Node& node : hidden.nodes) node.visible = false;
  EXPECT_EQ(count_background(background_mask(hidden)), 36u);
}

}  // namespace
}  // namespace hipr
