// Scheduling policies: every policy converges to exactly the full-frame image of the edited
// scene, pending edits are never lost, and the tile orders are what their names say.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

#include "bench/oracle_policy.h"
#include "core/error.h"

#include "hipr/edits.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "image/error_metrics.h"
#include "render/render_readback.h"
#include "test_support.h"

namespace hipr {
namespace {

RenderSettings settings() { return test::render_settings(48, 40, 8, 6, 13); }

// Steps until every pixel has `spp` samples since the last edit.
void run_to_convergence(Scheduler& scheduler, uint32_t spp) {
  for (int s = 0; s < 10000 && scheduler.work_since_edit() < double(spp); ++s) scheduler.step();
}

// A full-frame render of `scene`, as a display shows it.
ImageRGB fresh(const Scene& scene, uint32_t spp) {
  return test::full_frame_display(scene, settings(), spp);
}

struct PolicyCase {
  Policy policy;
  DisplayRule display;
  uint32_t first_visit_spp;
};

class EveryPolicy : public ::testing::TestWithParam<PolicyCase> {};

// Whatever the order, display rule and samples per visit, the display ends on exactly the
// full-frame image of the edited scene with exactly --spp samples per pixel.
TEST_P(EveryPolicy, ConvergesToTheFullFrameImageOfTheEditedScene) {
  const PolicyCase c = GetParam();
  const uint32_t spp = 3;
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  ImageRGB expected;  // the oracle's reference, current at each edit
  Scheduler scheduler(renderer, bench::make_bench_policy(c.policy, expected), 7);
  scheduler.set_display_rule(c.display);
  scheduler.set_first_visit_spp(c.first_visit_spp);
  renderer.add_samples_full_frame(spp);
  for (const Edit& edit : load_edit_script(test::asset("cornell_box.edits.json"))) {
    const Scene before = scene;
    apply_edit(scene, edit);
    expected = fresh(scene, spp);
    scheduler.on_edit(scene, diff_scenes(before, scene));
    run_to_convergence(scheduler, spp);
    EXPECT_EQ(scheduler.displayed_image().rgb, expected.rgb) << describe(edit);
    EXPECT_NEAR(scheduler.work_since_edit(), double(spp), 1e-9);
  }
}

INSTANTIATE_TEST_SUITE_P(Policies, EveryPolicy,
                         ::testing::Values(PolicyCase{Policy::Hipr, DisplayRule::Difference, 2},
                                           PolicyCase{Policy::Hipr, DisplayRule::Blend, 2},
                                           PolicyCase{Policy::Hipr, DisplayRule::Switch, 2},
                                           PolicyCase{Policy::Hipr, DisplayRule::Immediate, 1},
                                           PolicyCase{Policy::Full, DisplayRule::Immediate, 1},
                                           PolicyCase{Policy::Scanline, DisplayRule::Immediate, 2},
                                           PolicyCase{Policy::Spiral, DisplayRule::Blend, 1},
                                           PolicyCase{Policy::Random, DisplayRule::Immediate, 1},
                                           PolicyCase{Policy::Oracle, DisplayRule::Difference, 2},
                                           PolicyCase{Policy::Hipr, DisplayRule::Difference, 1}),
                         [](const auto& case_info) {
                           return policy_name(case_info.param.policy) + "_" +
                                  display_rule_name(case_info.param.display) + "_first" +
                                  std::to_string(case_info.param.first_visit_spp);
                         });

TEST(Scheduler, TheOracleNeedsAReference) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  EXPECT_THROW(Scheduler(renderer, Policy::Oracle, 7), InputError);
}

// The oracle visits tiles by the true error of what they show: the recoloured wall's tiles come
// before any tile the edit left alone.
TEST(Scheduler, TheOracleVisitsTheMostWrongTilesFirst) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  ImageRGB reference;
  Scheduler scheduler(renderer, std::make_unique<bench::OraclePolicy>(reference), 1);
  renderer.add_samples_full_frame(4);
  renderer.resolve_display_all(DisplayRule::Immediate);
  const ImageRGB stale = renderer.displayed_image();
  const Scene before = scene;
  apply_edit(scene, MaterialEdit{"red", {{"base_color", {0.05f, 0.1f, 0.65f}}}});
  reference = fresh(scene, 4);
  scheduler.on_edit(scene, diff_scenes(before, scene));
  const std::vector<uint32_t> order = read_schedule(renderer);
  const std::vector<double> error = relmse_tile_sums(stale, reference, settings().tile_size);
  for (size_t i = 1; i < order.size(); ++i) EXPECT_GE(error[order[i - 1]], error[order[i]]) << i;
}

TEST(Scheduler, FiftyRapidEditsEndInExactlyTheFinalScene) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 5);
  renderer.add_samples_full_frame(1);
  for (int i = 0; i < 50; ++i) {
    const Scene before = scene;
    apply_edit(scene,
               TransformEdit{"tall_block", glm::vec3(0.003f * float(i % 5) - 0.006f, 0.0f, 0.002f),
                             std::nullopt});
    scheduler.on_edit(scene, diff_scenes(before, scene));
    scheduler
        .step();  // one step per edit (part of stage 2): schedules are interrupted all the time
  }
  run_to_convergence(scheduler, 1);
  EXPECT_EQ(scheduler.displayed_image().rgb, fresh(scene, 1).rgb);
}

TEST(Scheduler, UntouchedTilesKeepShowingThePreviousImage) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Scanline, 3);
  renderer.add_samples_full_frame(2);
  renderer.resolve_display_all(DisplayRule::Immediate);
  const ImageRGB before_edit = renderer.displayed_image();
  const Scene before = scene;
  apply_edit(scene, MaterialEdit{"white", {{"base_color", {0.2f, 0.2f, 0.2f}}}});
  scheduler.on_edit(scene, diff_scenes(before, scene));
  scheduler.step();  // tiles 0..2 (top row, left) re-rendered
  const ImageRGB shown = scheduler.displayed_image();
  const size_t last_pixel = (size_t(40) * 48 - 1) * 3;  // bottom-right: not visited yet
  EXPECT_EQ(shown.rgb[last_pixel], before_edit.rgb[last_pixel]);
}

// Where an edit's time goes: every step is counted once, as one of HiPR's stage 2 steps or a
// scheduled one; stage 1 and the sort ran; a new edit starts the tally over.
TEST(Scheduler, EditTimesCountEveryPart) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 5);
  renderer.add_samples_full_frame(1);
  for (int edit = 0; edit < 2; ++edit) {
    const Scene before = scene;
    apply_edit(scene,
               MaterialEdit{"white", {{"base_color", {0.2f + 0.3f * float(edit), 0.2f, 0.2f}}}});
    const ChangeSet changes = diff_scenes(before, scene);
    const auto start = std::chrono::steady_clock::now();
    scheduler.on_edit(scene, changes);
    uint32_t steps = 0;
    for (; steps < 10000 && scheduler.work_since_edit() < 1.0; ++steps) scheduler.step();
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Scheduler::EditTimes& t = scheduler.edit_times();
    EXPECT_EQ(t.leading_steps + t.steps, steps) << "edit " << edit;
    EXPECT_GT(t.leading_steps, 0u);
    EXPECT_GT(t.steps, 0u);
    EXPECT_GT(t.plan_seconds, 0.0);
    EXPECT_GT(t.sort_seconds, 0.0);
    EXPECT_GT(t.leading_step_seconds, 0.0);
    EXPECT_GE(t.scene_seconds, 0.0);
    // Every part of the edit's work is counted once: together they are the time it took (the
    // loop's own bookkeeping aside), neither more nor much less.
    const double parts = t.capture_seconds + t.scene_seconds + t.plan_seconds + t.sort_seconds +
                         t.focus_seconds + t.leading_step_seconds + t.step_seconds;
    EXPECT_LE(parts, wall) << "edit " << edit;
    EXPECT_GE(parts, 0.8 * wall) << "edit " << edit;
  }
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
