// Dispatches wider than the device allows are folded into rows of workgroups
// (vk/compute_pipeline.cpp, shaders/common/dispatch.glsl): a 2048x2048 image already needs more
// than the 65535 workgroups lavapipe, AMD and Intel run in one row. With the width forced down to
// a few workgroups every kernel runs folded, with a partial last row, and must not notice.
#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "hipr/edits.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "render/radix_sorter.h"
#include "render/render_readback.h"
#include "render/viewer_sources.h"
#include "test_support.h"

namespace hipr {
namespace {

constexpr uint32_t kFoldWidth = 5;

vk::ContextOptions folding_options() {
  vk::ContextOptions options;
  options.validation = true;
  options.dispatch_width_limit = kFoldWidth;
  return options;
}

const vk::Context& folding_context() {
  static const vk::Context ctx(folding_options());
  return ctx;
}

struct HiprRun {
  std::vector<uint32_t> flags, schedule;
  std::vector<double> weights;
  std::vector<float> image, shown;
};

// A HiPR edit of the Cornell box through stage 1, stage 2, the sort, stage 3 and the display.
HiprRun run_hipr_edit(const vk::Context& ctx) {
  RenderSettings s;
  s.width = 64;  // 48 tiles and 48 pixel workgroups: 10 rows of 5, the last one of 3
  s.height = 48;
  s.tile_size = 8;
  s.max_depth = 6;
  s.seed = 4;
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(ctx, scene, s);
  Scheduler scheduler(renderer, Policy::Hipr, 7);
  renderer.add_samples_full_frame(2);
  const Scene before = scene;
  apply_edit(scene, TransformEdit{"tall_block", glm::vec3(0.08f, 0.0f, 0.0f), std::nullopt});
  scheduler.on_edit(scene, diff_scenes(before, scene));
  for (int i = 0; i < 64 && scheduler.work_since_edit() < 2.0; ++i) scheduler.step();
  EXPECT_FALSE(scheduler.leading_steps_pending());
  return {read_tile_flags(renderer), read_schedule(renderer), read_tile_weights(renderer),
          renderer.image().rgb, scheduler.displayed_image().rgb};
}

TEST(FoldedDispatch, AHiprEditRendersSortsAndShowsExactlyAsInOneRow) {
  const HiprRun folded = run_hipr_edit(folding_context());
  const HiprRun plain = run_hipr_edit(test::context());
  EXPECT_EQ(folded.flags, plain.flags);
  EXPECT_EQ(folded.weights, plain.weights);
  EXPECT_EQ(folded.schedule, plain.schedule);
  EXPECT_EQ(folded.image, plain.image);
  EXPECT_EQ(folded.shown, plain.shown);
  EXPECT_EQ(folding_context().validation_errors(), 0u);
}

TEST(FoldedDispatch, TheRadixSortStaysStable) {
  const uint32_t count = 9000;  // 36 blocks of 256 keys: 8 rows of 5, the last one of 1
  RadixSorter sorter(folding_context(), count);
  std::mt19937 rng(11);
  std::vector<uint32_t> keys(count), values(count);
  for (uint32_t i = 0; i < count; ++i) {
    keys[i] = (rng() % 13) << 24 | (rng() & 0xffu);
    values[i] = i;
  }
  sorter.keys.upload(keys.data(), count * 4);
  sorter.values.upload(values.data(), count * 4);
  folding_context().submit_and_wait([&](VkCommandBuffer cmd) { sorter.record(cmd, count); });
  std::vector<uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
  EXPECT_EQ(sorter.values.download_all<uint32_t>(), order);
  EXPECT_EQ(folding_context().validation_errors(), 0u);
}

// The denoiser's blend works in tiles of 16 x 8 pixels and the exposure meter in workgroups of
// 128 with shared memory: folded, their workgroups map to the same tiles and pixels.
struct DisplayPasses {
  std::vector<float> denoised;
  float exposure = 0.0f;
};

DisplayPasses run_display_passes(const vk::Context& ctx) {
  RenderSettings s;
  s.width = 70;  // 5 x 7 blend tiles (the last column and row partial), 20 meter workgroups
  s.height = 50;
  s.tile_size = 8;
  s.max_depth = 4;
  s.seed = 2;
  Renderer renderer(ctx, load_scene(test::asset("cornell_box.gltf")), s);
  renderer.add_samples_full_frame(2);
  renderer.resolve_display_all(DisplayRule::Immediate);
  DenoiseSettings denoise;
  denoise.enabled = true;
  return {renderer.denoised_image(denoise).rgb, metered_display_exposure(renderer)};
}

TEST(FoldedDispatch, TheDenoiserAndTheExposureMeterSeeTheSamePixels) {
  const DisplayPasses folded = run_display_passes(folding_context());
  const DisplayPasses plain = run_display_passes(test::context());
  EXPECT_EQ(folded.denoised, plain.denoised);
  EXPECT_EQ(folded.exposure, plain.exposure);
  EXPECT_NE(plain.exposure, 0.0f) << "a lit image";
  EXPECT_EQ(folding_context().validation_errors(), 0u);
}

}  // namespace
}  // namespace hipr
