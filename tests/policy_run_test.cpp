// hipr bench's runs (src/bench/policy_run.h): every run takes the scheduler's settings whole, so
// a drag is scheduled as a single edit is (the edit's and the focus's leads included).
#include <gtest/gtest.h>

#include "bench/policy_run.h"
#include "hipr/edits.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "render/render_snapshot.h"
#include "test_support.h"

namespace hipr {
namespace {

// The Cornell box's tall block moved, rendered at 8 spp before it: what a bench run starts from,
// with steps of 4 tiles whose first visits take 2 samples, converged at 8.
struct TallBlockMove {
  Scene before = load_scene(test::asset("cornell_box.gltf"));
  Scene after = moved(before);
  ChangeSet changes = diff_scenes(before, after);
  RenderSettings settings = test::render_settings(48, 40, 8, 6, 13);
  ImageRGB reference = test::full_frame_display(after, settings, 16);
  Renderer renderer{test::context(), before, settings};
  RenderSnapshot start = rendered(renderer);
  bench::PolicyRunOptions options = run_options();

  static Scene moved(Scene scene) {
    apply_edit(scene, TransformEdit{"tall_block", glm::vec3(0.06f, 0.0f, -0.08f), std::nullopt});
    return scene;
  }
  static RenderSnapshot rendered(Renderer& renderer) {
    renderer.add_samples_full_frame(8);
    return snapshot_render(renderer);
  }
  static bench::PolicyRunOptions run_options() {
    bench::PolicyRunOptions options;
    options.schedule.tiles_per_step = 4;
    options.schedule.first_visit_spp = 2;
    options.target_spp = 8;
    options.dense_until = 1e9;  // every step evaluated
    return options;
  }
  bench::PolicyRun run() {
    bench::PolicyRun result =
        bench::run_policy(renderer, after, changes, start, reference, {}, options);
    renderer.update_scene(before, diff_scenes(after, before));  // ready for the next run
    return result;
  }
};

// A drag of one edit is that edit: measured point by point as run_policy measures it. (The drag
// once set neither the converged count nor the leads: its hipr ran without the edit's lead.)
TEST(PolicyRun, ADragOfOneEditIsScheduledAsThatEdit) {
  TallBlockMove move;
  ASSERT_GT(move.options.schedule.edit_lead, 0u);
  const bench::PolicyRun single = move.run();
  const bench::PolicyRun drag =
      bench::run_drag(move.renderer, {move.before, move.after}, {move.changes}, move.start,
                      {move.reference}, 0.25, move.options);
  ASSERT_TRUE(single.converged);
  ASSERT_TRUE(drag.converged);
  ASSERT_EQ(drag.curve.size(), single.curve.size());
  for (size_t i = 0; i < single.curve.size(); ++i) {
    EXPECT_EQ(drag.curve[i].work, single.curve[i].work) << "point " << i;
    EXPECT_EQ(drag.curve[i].relmse, single.curve[i].relmse) << "point " << i;
  }
  EXPECT_EQ(drag.final_image.rgb, single.final_image.rgb);
}

// Measured denoised, every policy ends on the same image: the final samples' filter alone, bit
// for bit, whatever frames its history kept on the way (the displays end bit-identical).
TEST(PolicyRun, EveryPolicyEndsOnTheSameDenoisedImage) {
  TallBlockMove move;
  move.options.denoise.enabled = true;  // every step a frame of the denoiser's history
  std::vector<bench::PolicyRun> runs;
  for (const Policy policy : {Policy::Hipr, Policy::Full, Policy::Spiral}) {
    move.options.schedule.policy = policy;
    runs.push_back(move.run());
  }
  for (const bench::PolicyRun& run : runs) {
    ASSERT_TRUE(run.converged);
    EXPECT_EQ(run.final_image.rgb, runs[0].final_image.rgb);
    EXPECT_EQ(run.curve.back().relmse, runs[0].curve.back().relmse);
    EXPECT_EQ(run.curve.back().flip, runs[0].curve.back().flip);
  }
}

// A restart shows the converged image of the scene before the edit until its first pass is done;
// denoised, that image stays as it was: the filter takes each value's noise from the samples
// that made it, not from the one sample of the new pass its pixel holds by then (taken from its
// neighbours, as a single sample's, the image blurred further at every step).
TEST(PolicyRun, ARestartShowsTheImageBeforeTheEditUnchangedUntilItsFirstPass) {
  TallBlockMove move;
  move.options.denoise.enabled = true;
  move.options.schedule.policy = Policy::Full;
  move.options.schedule.first_visit_spp = 1;
  const bench::PolicyRun run = move.run();
  uint32_t before_pass = 0;
  for (const bench::CurvePoint& point : run.curve) {
    if (point.work >= 1.0) break;
    EXPECT_EQ(point.relmse, run.curve[0].relmse) << "at work " << point.work;
    EXPECT_EQ(point.flip, run.curve[0].flip) << "at work " << point.work;
    ++before_pass;
  }
  EXPECT_GE(before_pass, 8u) << "steps measured during the first pass";
}

// Every setting is declared once, with a flag of its own.
TEST(ScheduleSettings, EverySettingIsDeclaredOnceWithItsOwnFlag) {
  ScheduleSettings settings;
  std::set<std::string> flags, names;
  size_t count = 0;
  for_each_schedule_setting(settings, [&](const ScheduleSettingInfo& info, auto&) {
    ++count;
    EXPECT_EQ(std::string(info.flag).rfind("--", 0), 0u) << info.flag;
    EXPECT_TRUE(flags.insert(info.flag).second) << info.flag;
    EXPECT_TRUE(names.insert(info.name).second) << info.name;
    EXPECT_GT(std::string(info.help).size(), 10u) << info.flag;
  });
  EXPECT_EQ(count, 9u);
}

}  // namespace
}  // namespace hipr
