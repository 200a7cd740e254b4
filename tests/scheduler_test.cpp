// Scheduling policies: every policy converges to exactly the full-frame image of the edited
// scene, pending edits are never lost, and the tile orders are what their names say.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"

#include "hipr/edits.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "test_support.h"

namespace hipr {
namespace {

RenderSettings settings() {
  RenderSettings s;
  s.width = 48;
  s.height = 40;
  s.tile_size = 8;
  s.max_depth = 6;
  s.seed = 13;
  return s;
}

// Steps until every pixel has `spp` samples since the last edit (one more for HiPR's stage 2).
void run_to_convergence(Scheduler& scheduler, const Renderer& renderer, uint32_t spp, uint32_t per_step) {
  const uint32_t steps = spp * ((renderer.tile_count() + per_step - 1) / per_step) + (scheduler.policy() == Policy::Hipr ? 1 : 0);
  for (uint32_t s = 0; s < steps; ++s) scheduler.step();
}

ImageRGB fresh(const Scene& scene, uint32_t spp) {
  Renderer renderer(test::context(), scene, settings());
  renderer.add_samples_full_frame(spp);
  return renderer.image();
}

class EveryPolicy : public ::testing::TestWithParam<Policy> {};

TEST_P(EveryPolicy, ConvergesToTheFullFrameImageOfTheEditedScene) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, GetParam(), 7);
  renderer.add_samples_full_frame(2);
  for (const Edit& edit : load_edit_script(test::asset("cornell_box.edits.json"))) {
    const Scene before = scene;
    apply_edit(scene, edit);
    scheduler.on_edit(scene, diff_scenes(before, scene));
    run_to_convergence(scheduler, renderer, 2, 7);
    EXPECT_EQ(scheduler.displayed_image().rgb, fresh(scene, 2).rgb) << describe(edit);
    EXPECT_NEAR(scheduler.work_since_edit(), 2.0, 1e-9);
  }
}

INSTANTIATE_TEST_SUITE_P(Policies, EveryPolicy,
                         ::testing::Values(Policy::Hipr, Policy::Full, Policy::Scanline, Policy::Spiral, Policy::Random),
                         [](const auto& test_info) { return policy_name(test_info.param); });

TEST(Scheduler, FiftyRapidEditsEndInExactlyTheFinalScene) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 5);
  renderer.add_samples_full_frame(1);
  for (int i = 0; i < 50; ++i) {
    const Scene before = scene;
    apply_edit(scene, TransformEdit{"tall_block", glm::vec3(0.003f * float(i % 5) - 0.006f, 0.0f, 0.002f), std::nullopt});
    scheduler.on_edit(scene, diff_scenes(before, scene));
    scheduler.step();  // one step per edit (stage 2): schedules are interrupted all the time
  }
  // Stage 2 of the last edit is done; one round of stage 3 gives every pixel its sample.
  for (uint32_t s = 0; s < (renderer.tile_count() + 4) / 5; ++s) scheduler.step();
  EXPECT_EQ(scheduler.displayed_image().rgb, fresh(scene, 1).rgb);
}

TEST(Scheduler, UntouchedTilesKeepShowingThePreviousImage) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Scanline, 3);
  renderer.add_samples_full_frame(2);
  const ImageRGB before_edit = renderer.image();
  const Scene before = scene;
  apply_edit(scene, MaterialEdit{"white", {{"base_color", {0.2f, 0.2f, 0.2f}}}});
  scheduler.on_edit(scene, diff_scenes(before, scene));
  scheduler.step();  // tiles 0..2 (top row, left) re-rendered
  const ImageRGB shown = scheduler.displayed_image();
  const size_t last_pixel = (size_t(40) * 48 - 1) * 3;  // bottom-right: not visited yet
  EXPECT_EQ(shown.rgb[last_pixel], before_edit.rgb[last_pixel]);
}

TEST(TileOrder, PoliciesArePermutationsWithTheirShape) {
  for (Policy p : {Policy::Scanline, Policy::Spiral, Policy::Random}) {
    std::vector<uint32_t> order = tile_order(p, 7, 5, 1);
    std::vector<uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i) << policy_name(p);
  }
  EXPECT_EQ(tile_order(Policy::Scanline, 7, 5, 1)[1], 1u);
  EXPECT_EQ(tile_order(Policy::Spiral, 7, 5, 1)[0], 2u * 7 + 3);  // the centre tile first
  EXPECT_NE(tile_order(Policy::Random, 7, 5, 1), tile_order(Policy::Random, 7, 5, 2));
  EXPECT_THROW(parse_policy("zigzag"), InputError);
}

}  // namespace
}  // namespace hipr
