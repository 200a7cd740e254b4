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

// A drag of one edit is that edit: measured point by point as run_policy measures it. (The drag
// once set neither the converged count nor the leads: its hipr ran without the edit's lead.)
TEST(PolicyRun, ADragOfOneEditIsScheduledAsThatEdit) {
  const Scene before = load_scene(test::asset("cornell_box.gltf"));
  Scene after = before;
  apply_edit(after, TransformEdit{"tall_block", glm::vec3(0.06f, 0.0f, -0.08f), std::nullopt});
  const ChangeSet changes = diff_scenes(before, after);
  const RenderSettings settings = test::render_settings(48, 40, 8, 6, 13);
  const ImageRGB reference = test::full_frame_display(after, settings, 16);

  Renderer renderer(test::context(), before, settings);
  renderer.add_samples_full_frame(8);
  const RenderSnapshot start = snapshot_render(renderer);
  bench::PolicyRunOptions options;
  options.schedule.tiles_per_step = 4;
  options.schedule.first_visit_spp = 2;
  options.target_spp = 8;
  options.dense_until = 1e9;  // both evaluate after every step
  ASSERT_GT(options.schedule.edit_lead, 0u);

  const bench::PolicyRun single =
      bench::run_policy(renderer, after, changes, start, reference, {}, options);
  renderer.update_scene(before, diff_scenes(after, before));
  const bench::PolicyRun drag =
      bench::run_drag(renderer, {before, after}, {changes}, start, {reference}, 0.25, options);
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
  const Scene before = load_scene(test::asset("cornell_box.gltf"));
  Scene after = before;
  apply_edit(after, TransformEdit{"tall_block", glm::vec3(0.06f, 0.0f, -0.08f), std::nullopt});
  const ChangeSet changes = diff_scenes(before, after);
  const RenderSettings settings = test::render_settings(48, 40, 8, 6, 13);
  const ImageRGB reference = test::full_frame_display(after, settings, 16);
  Renderer renderer(test::context(), before, settings);
  renderer.add_samples_full_frame(8);
  const RenderSnapshot start = snapshot_render(renderer);
  bench::PolicyRunOptions options;
  options.schedule.tiles_per_step = 4;
  options.schedule.first_visit_spp = 2;
  options.target_spp = 8;
  options.dense_until = 1e9;  // every step a frame of the denoiser's history
  options.denoise.enabled = true;
  std::vector<bench::PolicyRun> runs;
  for (const Policy policy : {Policy::Hipr, Policy::Full, Policy::Spiral}) {
    options.schedule.policy = policy;
    runs.push_back(bench::run_policy(renderer, after, changes, start, reference, {}, options));
    renderer.update_scene(before, diff_scenes(after, before));
  }
  for (const bench::PolicyRun& run : runs) {
    ASSERT_TRUE(run.converged);
    EXPECT_EQ(run.final_image.rgb, runs[0].final_image.rgb);
    EXPECT_EQ(run.curve.back().relmse, runs[0].curve.back().relmse);
    EXPECT_EQ(run.curve.back().flip, runs[0].curve.back().flip);
  }
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
