// Path guiding (docs/method.md#path-guiding): the guide only reshapes where paths go, so every
// estimator with it converges to the image without it; it is learnt from the scene state alone,
// so images stay the same bits whatever the order of the work, and an edit gets a guide of its
// own; and what it learns is where light comes from.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numeric>

#include "hipr/hipr_stages.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "image/image_compare.h"
#include "render/render_state.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

uint32_t node_named(const Scene& scene, const std::string& name) {
  for (uint32_t n = 0; n < scene.nodes.size(); ++n)
    if (scene.nodes[n].name == name) return n;
  ADD_FAILURE() << "no node " << name;
  return 0;
}

uint32_t material_named(const Scene& scene, const std::string& name) {
  for (uint32_t m = 0; m < scene.materials.size(); ++m)
    if (scene.materials[m].name == name) return m;
  ADD_FAILURE() << "no material " << name;
  return 0;
}

// The shipped Cornell box with a white shade a little larger than its ceiling lamp, hung just
// below it: the lamp lights the ceiling around the shade and the room sees mostly that.
Scene shaded_lamp_box() {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  const uint32_t lamp = node_named(scene, "light");
  const glm::mat4 world = scene.world_transform(lamp);
  Mesh shade = scene.meshes[scene.nodes[lamp].mesh];
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (MeshPrimitive& p : shade.primitives) {
    for (glm::vec3& v : p.positions) {
      v = glm::vec3(world * glm::vec4(v, 1.0f));
      lo = glm::min(lo, v), hi = glm::max(hi, v);
    }
  }
  // World space, on a root node: 1.5 times the lamp's width, a quarter of it below.
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float drop = 0.25f * std::max(hi.x - lo.x, hi.z - lo.z);
  for (MeshPrimitive& p : shade.primitives) {
    for (glm::vec3& v : p.positions)
      v = centre + glm::vec3(1.5f, 1.0f, 1.5f) * (v - centre) - glm::vec3(0.0f, drop, 0.0f);
    for (glm::vec3& n : p.normals) n = glm::normalize(glm::vec3(world * glm::vec4(n, 0.0f)));
    for (glm::vec4& t : p.tangents)
      t = glm::vec4(glm::normalize(glm::vec3(world * glm::vec4(glm::vec3(t), 0.0f))), t.w);
    p.material = p.default_material = material_named(scene, "white");
  }
  shade.name = "shade";
  shade.revision = mesh_revision(shade);
  scene.meshes.push_back(shade);
  Node node;
  node.name = "shade";
  node.mesh = int(scene.meshes.size() - 1);
  scene.nodes.push_back(node);
  scene.children.emplace_back();
  scene.root_nodes.push_back(uint32_t(scene.nodes.size() - 1));
  return scene;
}

RenderSettings settings(uint32_t size, bool guiding, uint32_t max_depth = 6) {
  RenderSettings s;
  s.width = s.height = size;
  s.max_depth = max_depth;
  s.seed = 5;
  s.guiding = guiding;
  s.light_groups = 0;
  s.difference_estimate = false;
  return s;
}

ImageRGB render(const Scene& scene, const RenderSettings& s, uint32_t spp) {
  Renderer renderer(test::context(), scene, s);
  for (uint32_t done = 0; done < spp; done += 64) {
    renderer.add_samples_full_frame(std::min(64u, spp - done));
  }
  EXPECT_EQ(renderer.counters().non_finite_samples, 0u);
  if (s.guiding) {
    EXPECT_GT(renderer.counters().guide_rays, 0u) << "the guide was trained";
  }
  return renderer.image();
}

TEST(Guiding, EveryEstimatorAgreesWithTheGuide) {
  // BSDF-and-guide sampling alone, light sampling alone and their MIS estimate one image (a
  // wrong guide density, or MIS weights that forget the guide, make one drift), and it is the
  // image without the guide.
  const Scene scene = shaded_lamp_box();
  RenderSettings s = settings(24, true, 3);
  const double mis = test::mean(render(scene, s, 512));
  s.light_sampling = LightSampling::BsdfOnly;
  const double bsdf = test::mean(render(scene, s, 512));
  s.light_sampling = LightSampling::LightOnly;
  const double light = test::mean(render(scene, s, 512));
  const double unguided = test::mean(render(scene, settings(24, false, 3), 512));
  ASSERT_GT(mis, 0.0);
  EXPECT_NEAR(bsdf / mis, 1.0, 0.03) << "BSDF and guide sampling alone";
  EXPECT_NEAR(light / mis, 1.0, 0.03) << "light sampling alone";
  EXPECT_NEAR(unguided / mis, 1.0, 0.03) << "without the guide";
}

TEST(Guiding, ImagesDoNotDependOnTheOrderOfTheWork) {
  // Tiles in another order and other batches: the same guide, the same bits.
  const Scene scene = shaded_lamp_box();
  const RenderSettings s = settings(40, true);
  Renderer a(test::context(), scene, s);
  a.add_samples_full_frame(6);
  Renderer b(test::context(), scene, s);
  std::vector<uint32_t> tiles(b.tile_count());
  std::iota(tiles.rbegin(), tiles.rend(), 0u);
  b.add_samples(std::span(tiles).first(2), 2);
  b.add_samples(tiles, 2);
  b.add_samples(std::span(tiles).subspan(2), 2);
  b.add_samples(std::span(tiles).first(2), 2);
  b.add_samples(std::span(tiles).subspan(2), 2);
  EXPECT_EQ(a.image().rgb, b.image().rgb);
}

TEST(Guiding, AnEditIsRenderedWithItsOwnGuide) {
  // A renderer that rendered the box before its lamp moved ends, after the edit, on the bits of
  // a fresh render of the moved lamp: what was learnt before the edit is gone.
  const Scene before = shaded_lamp_box();
  Scene after = before;
  for (const char* name : {"light", "shade"})
    after.nodes[node_named(after, name)].local =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.12f, 0.0f, 0.0f)) *
        after.nodes[node_named(after, name)].local;
  const RenderSettings s = settings(32, true);
  Renderer edited(test::context(), before, s);
  edited.add_samples_full_frame(4);
  const ImageRGB old_image = edited.image();
  edited.update_scene(after, diff_scenes(before, after));
  edited.reset();
  edited.add_samples_full_frame(4);
  Renderer fresh(test::context(), after, s);
  fresh.add_samples_full_frame(4);
  EXPECT_EQ(edited.image().rgb, fresh.image().rgb);
  EXPECT_NE(old_image.rgb, fresh.image().rgb) << "the edit changes the image";
  // One training per scene state, its time counted; the guide's buffers are the same size.
  EXPECT_EQ(edited.guide_cost().trainings, 2u);
  EXPECT_EQ(fresh.guide_cost().trainings, 1u);
  EXPECT_GT(edited.guide_cost().training_seconds, 0.0);
  EXPECT_GT(edited.guide_cost().bytes, 0u);
  EXPECT_EQ(edited.guide_cost().bytes, fresh.guide_cost().bytes);
  EXPECT_EQ(Renderer(test::context(), before, settings(32, false)).guide_cost().bytes, 0u);
}

TEST(Guiding, HiprScheduleEndsOnTheFullFrameImageOfTheEdit) {
  // HiPR's stages after the lamp and its shade moved (stage 2's discovery paths are guided
  // too): the schedule, tile group by tile group, ends on the full-frame render of the edit.
  const Scene before = shaded_lamp_box();
  Scene after = before;
  for (const char* name : {"light", "shade"})
    after.nodes[node_named(after, name)].local =
        glm::translate(glm::mat4(1.0f), glm::vec3(-0.1f, 0.0f, 0.05f)) *
        after.nodes[node_named(after, name)].local;
  RenderSettings s = settings(32, true);
  s.tile_size = 8;
  Renderer renderer(test::context(), before, s);
  renderer.add_samples_full_frame(2);
  renderer.resolve_display_all(DisplayRule::Immediate);
  hipr_stages(renderer).stage1_visibility({});
  const ChangeSet changes = diff_scenes(before, after);
  renderer.update_scene(after, changes);
  renderer.mark_all_owed();
  hipr_stages(renderer).stage1_visibility(changes);
  test::discover_all(renderer, 1);
  hipr_stages(renderer).build_schedule();
  for (uint32_t offset = 0; offset < renderer.tile_count(); offset += 3)
    renderer.render_schedule(offset, 3, 1, true);
  renderer.render_schedule(0, renderer.tile_count(), 2, false);
  Renderer full(test::context(), after, s);
  full.add_samples_full_frame(3);
  EXPECT_EQ(renderer.image().rgb, full.image().rgb);
}

// Mean squared difference of two images: for two independent renders of one scene, twice the
// variance of a pixel's estimate.
double mean_squared_difference(const ImageRGB& a, const ImageRGB& b) {
  const double rmse = compare_images(a, b, CompareMetric::Rmse, 0.0).value;
  return rmse * rmse;
}

TEST(Guiding, VarianceDoesNotCompoundAlongAPath) {
  // The shared Cornell box (a small bright light, glass and mirror, a closed box of pale walls:
  // paths of many diffuse vertices). One-sample MIS of guide and BSDF weighs a direction by at
  // most 1 / (1 - share) of what BSDF sampling would, so the second moment of a step can double;
  // guided at every vertex, a long path multiplied that, and a few pixels took hundreds of times
  // their value (the variance below was 5.1x BSDF sampling's). A path is now guided at the first
  // vertex where the guide has a share, so it costs at most one such factor (1.7x).
  if (!test::shared_scenes_available()) GTEST_SKIP() << "../shared/scenes is not available";
  const Scene scene = load_scene(test::shared_scene("CornellBox/cornellBox.gltf"));
  const auto variance = [&](bool guiding) {
    double sum = 0.0;
    for (uint32_t pair = 0; pair < 2; ++pair) {
      RenderSettings s = settings(32, guiding, 32);
      s.seed = 11 + 2 * pair;
      const ImageRGB a = render(scene, s, 64);
      s.seed += 1;
      sum += 0.5 * mean_squared_difference(a, render(scene, s, 64));
    }
    return sum / 2.0;
  };
  const double bsdf = variance(false), guided = variance(true);
  ASSERT_GT(bsdf, 0.0);
  EXPECT_LT(guided / bsdf, 2.0) << "guided variance " << guided << " against BSDF sampling's "
                                << bsdf;
}

TEST(Guiding, LearnsWhereLightComesFrom) {
  // The shipped Cornell box: a floor cell in front of the blocks receives its light from above,
  // most of it steeply (the lamp, the ceiling and the back wall it lights; cosine-weighted): its
  // learnt distribution keeps nothing below the floor but the uniform share, holds most of its
  // mass in the quarter of the sphere within 60 degrees of straight up, and the cell guides.
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  // 128^2 pixels x 4 training paths: 512 cells, 7 cm wide (the blocks stand out of this one).
  Renderer renderer(test::context(), scene, settings(128, true));
  renderer.add_samples(std::vector<uint32_t>{0}, 1);  // trains the guide first
  const RenderState& state = *renderer.render_state();
  const abi::FrameParams& frame = state.gpu.frame();
  ASSERT_GT(frame.guideCells, 0u);
  const auto [lo, hi] = scene.bounds();
  // In the middle of the open front, away from the blocks and walls.
  const glm::vec3 floor_middle(0.5f * (lo.x + hi.x), lo.y + 0.01f * (hi.y - lo.y),
                               lo.z + 0.05f * (hi.z - lo.z));
  const glm::uvec3 index = glm::uvec3((floor_middle - frame.guideLo) * frame.guideInvCell);
  const uint32_t cell =
      (index.z * frame.guideResolutionY + index.y) * frame.guideResolutionX + index.x;
  const std::vector<float> guide = state.gpu.guide.download_all<float>();
  const float* cdf = guide.data() + size_t(cell) * abi::kGuideSlots;
  const auto band = [&](uint32_t c) {  // probability of cos-to-+Y band c
    const uint32_t first = c * abi::kGuidePhiBins, last = first + abi::kGuidePhiBins - 1;
    return cdf[last] - (first == 0 ? 0.0f : cdf[first - 1]);
  };
  float below = 0.0f;
  for (uint32_t c = 0; c < abi::kGuideCosBins / 2; ++c) below += band(c);
  EXPECT_NEAR(below, 0.1f * 0.5f, 1e-3f) << "below the floor: only the uniform share";
  const float steep = band(abi::kGuideCosBins - 1) + band(abi::kGuideCosBins - 2);
  EXPECT_GT(steep, 0.5f) << "within 60 degrees of straight up (a quarter of the sphere)";
  EXPECT_GT(cdf[abi::kGuideBins], 0.25f) << "the cell guides";
}

}  // namespace
}  // namespace hipr
