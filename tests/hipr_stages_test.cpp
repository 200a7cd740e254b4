// HiPR stages on the GPU: the radix sort, unbiased convergence of a scheduled re-render, and
// discovery on purpose-built edits of the Cornell box.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <numeric>
#include <random>

#include "hipr/edit_pipeline.h"
#include "hipr/edits.h"
#include "hipr/hipr_stages.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "render/radix_sorter.h"
#include "render/render_readback.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

class RadixSort : public ::testing::TestWithParam<uint32_t> {};

TEST_P(RadixSort, MatchesStdStableSort) {
  const uint32_t count = GetParam();
  const vk::Context& ctx = test::context();
  RadixSorter sorter(ctx, count);
  std::mt19937 rng(count);
  std::vector<uint32_t> keys(count), values(count);
  for (uint32_t i = 0; i < count; ++i) {
    // Few distinct keys in part of the range, so stability (ties by value) is exercised.
    keys[i] = i % 3 == 0 ? rng() : (rng() % 7) << 28;
    values[i] = i;
  }
  sorter.keys.upload(keys.data(), count * 4);
  sorter.values.upload(values.data(), count * 4);
  ctx.submit_and_wait([&](VkCommandBuffer cmd) { sorter.record(cmd, count); });
  std::vector<uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
  const auto sorted_keys = sorter.keys.download_all<uint32_t>();
  const auto sorted_values = sorter.values.download_all<uint32_t>();
  for (uint32_t i = 0; i < count; ++i) {
    ASSERT_EQ(sorted_values[i], order[i]) << "position " << i;
    ASSERT_EQ(sorted_keys[i], keys[order[i]]) << "position " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Counts, RadixSort,
                         ::testing::Values(1u, 2u, 255u, 256u, 257u, 1000u, 65537u, 1000000u));

RenderSettings settings() { return test::render_settings(64, 48, 8, 8, 9); }

struct Edited {
  Scene before, after;
  ChangeSet changes;
};

Edited edit_scene(Scene base, const Edit& edit) {
  Edited e{std::move(base), {}, {}};
  e.after = e.before;
  apply_edit(e.after, edit);
  e.changes = diff_scenes(e.before, e.after);
  return e;
}

Edited edit_cornell(const Edit& edit) {
  return edit_scene(load_scene(test::asset("cornell_box.gltf")), edit);
}

// The Cornell box with its back wall turned into a mirror (smooth white metal).
Scene mirror_cornell() {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Material mirror;
  mirror.name = "mirror";
  mirror.params = default_material_params();
  mirror.params.base_color = glm::vec3(0.95f);
  mirror.params.base_metalness = 1.0f;
  mirror.params.specular_roughness = 0.0f;
  scene.materials.push_back(mirror);
  for (const Node& node : scene.nodes)
    if (node.name == "back_wall")
      scene.meshes[size_t(node.mesh)].primitives[0].material = uint32_t(scene.materials.size() - 1);
  return scene;
}

// Runs the three stages after `edit` on a renderer that had converged-ish on the old scene.
std::unique_ptr<Renderer> run_stages(const Edited& e) {
  auto renderer = std::make_unique<Renderer>(test::context(), e.before, settings());
  renderer->add_samples_full_frame(2);
  hipr_stages(*renderer).stage1_visibility({});  // G-buffer of the scene as it was
  renderer->update_scene(e.after, e.changes);
  renderer->mark_all_owed();
  hipr_stages(*renderer).stage1_visibility(e.changes);
  test::discover_all(*renderer, 1);
  hipr_stages(*renderer).build_schedule();
  return renderer;
}

size_t count_flag(const std::vector<uint32_t>& flags, uint32_t bit) {
  return size_t(
      std::count_if(flags.begin(), flags.end(), [&](uint32_t f) { return (f & bit) != 0; }));
}

TEST(HiprStages, ScheduledRerenderConvergesToTheFullFrameImage) {
  for (uint32_t tile : {8u, 16u}) {
    const Edited e =
        edit_cornell(TransformEdit{"tall_block", glm::vec3(0.06f, 0.0f, -0.08f), std::nullopt});
    RenderSettings s = settings();
    s.tile_size = tile;
    Renderer renderer(test::context(), e.before, s);
    renderer.add_samples_full_frame(3);
    hipr_stages(renderer).stage1_visibility({});
    renderer.update_scene(e.after, e.changes);
    renderer.mark_all_owed();
    hipr_stages(renderer).stage1_visibility(e.changes);
    test::discover_all(renderer, 1);
    hipr_stages(renderer).build_schedule();
    // Stage 3 in steps of 5 tiles, then ordinary passes: every pixel ends with 3 samples.
    for (uint32_t offset = 0; offset < renderer.tile_count(); offset += 5)
      renderer.render_schedule(offset, 5, 1, true);
    renderer.render_schedule(0, renderer.tile_count(), 2, false);
    Renderer full(test::context(), e.after, s);
    full.add_samples_full_frame(3);
    EXPECT_EQ(renderer.image().rgb, full.image().rgb) << "tile " << tile;
    const auto counts = renderer.sample_counts();
    EXPECT_TRUE(std::all_of(counts.begin(), counts.end(), [](uint32_t c) { return c == 3; }));
  }
}

TEST(HiprStages, ScheduleListsActiveThenDiscoveredByWeightThenTheRest) {
  const auto renderer = run_stages(
      edit_cornell(TransformEdit{"tall_block", glm::vec3(0.06f, 0.0f, -0.08f), std::nullopt}));
  const auto flags = read_tile_flags(*renderer);
  const auto weights = read_tile_weights(*renderer);
  const auto order = read_schedule(*renderer);
  std::vector<uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (uint32_t i = 0; i < sorted.size(); ++i)
    ASSERT_EQ(sorted[i], i) << "the schedule is a permutation";
  const size_t active = count_flag(flags, 1);
  ASSERT_GT(active, 0u);
  for (size_t i = 0; i < order.size(); ++i) EXPECT_EQ((flags[order[i]] & 1) != 0, i < active) << i;
  for (size_t i = active + 1; i < order.size() && weights[order[i]] > 0.0; ++i)
    EXPECT_GE(weights[order[i - 1]], weights[order[i]]) << "discovered tiles by descending weight";
}

TEST(HiprStages, RecolouredWallDiscoversItsColourBleeding) {
  const auto renderer =
      run_stages(edit_cornell(MaterialEdit{"red", {{"base_color", {0.05f, 0.1f, 0.65f}}}}));
  const auto flags = read_tile_flags(*renderer);
  const auto weights = read_tile_weights(*renderer);
  // The wall's light reaches most of the box (floor, ceiling, back wall, blocks, and most of
  // all the wall facing it), so most other tiles are discovered, with weight.
  size_t others = 0, discovered = 0;
  for (uint32_t t = 0; t < flags.size(); ++t) {
    if (flags[t] & 1) continue;
    ++others;
    if ((flags[t] & 2) && weights[t] > 0.0) ++discovered;
  }
  EXPECT_GT(discovered, others / 2);
}

TEST(HiprStages, HiddenObjectWithoutLightInteractionDiscoversNothing) {
  // The short block moved far below the floor: no pixel shows it before or after.
  Edited e = edit_cornell(TransformEdit{"short_block", glm::vec3(0.0f, -5.0f, 0.0f), std::nullopt});
  e.before = e.after;
  apply_edit(e.after, TransformEdit{"short_block", glm::vec3(0.05f, 0.0f, 0.0f), std::nullopt});
  e.changes = diff_scenes(e.before, e.after);
  const auto renderer = run_stages(e);
  const auto flags = read_tile_flags(*renderer);
  EXPECT_EQ(count_flag(flags, 1), 0u);
  EXPECT_EQ(count_flag(flags, 2), 0u);
}

// Discovery completeness: tiles whose converged radiance the edit really changed (shadows,
// colour bleeding), outside the active set, must be discovered.
void expect_changed_tiles_discovered(const Edited& e) {
  const auto renderer = run_stages(e);
  const auto flags = read_tile_flags(*renderer);
  ImageRGB before, after;
  for (const auto& [scene, image] : {std::pair{&e.before, &before}, std::pair{&e.after, &after}}) {
    Renderer reference(test::context(), *scene, settings());
    reference.add_samples_full_frame(64);
    *image = reference.image();
  }
  const RenderSettings s = settings();
  std::vector<double> change(flags.size(), 0.0), level(flags.size(), 0.0);
  for (uint32_t y = 0; y < s.height; ++y)
    for (uint32_t x = 0; x < s.width; ++x) {
      const uint32_t tile = (y / s.tile_size) * renderer->tiles_x() + x / s.tile_size;
      for (size_t c = 0; c < 3; ++c) {
        const size_t i = (size_t(y) * s.width + x) * 3 + c;
        change[tile] += after.rgb[i] - before.rgb[i];
        level[tile] += before.rgb[i];
      }
    }
  size_t changed = 0, found = 0;
  for (size_t t = 0; t < flags.size(); ++t) {
    if ((flags[t] & 1) || std::abs(change[t]) <= 0.15 * level[t])
      continue;  // >15%: far above noise
    ++changed;
    found += (flags[t] & 2) ? 1 : 0;
  }
  EXPECT_GT(changed, 0u) << "the edit should change some tiles outside the active set";
  EXPECT_GE(double(found), 0.9 * double(changed))
      << found << " of " << changed << " changed tiles discovered";
}

TEST(HiprStages, TilesChangedByAMovedBlockAreDiscovered) {
  expect_changed_tiles_discovered(
      edit_cornell(TransformEdit{"tall_block", glm::vec3(0.06f, 0.0f, -0.08f), std::nullopt}));
}

TEST(HiprStages, TilesChangedByARecolouredWallAreDiscovered) {
  expect_changed_tiles_discovered(
      edit_cornell(MaterialEdit{"red", {{"base_color", {0.05f, 0.1f, 0.65f}}}}));
}

TEST(HiprStages, BlockMovedBesideAMirrorDiscoversTheMirror) {
  const Edited e = edit_scene(
      mirror_cornell(), TransformEdit{"short_block", glm::vec3(-0.05f, 0.0f, 0.1f), std::nullopt});
  expect_changed_tiles_discovered(e);
  // The mirror's tiles (back wall in the G-buffer) that are not active are discovered through
  // specular paths.
  const auto renderer = run_stages(e);
  const auto flags = read_tile_flags(*renderer);
  const auto weights = read_tile_weights(*renderer);
  const auto instances = renderer->gbuffer_instances();
  const auto scene_instances = e.after.instances();
  const RenderSettings s = settings();
  std::vector<bool> shows_mirror(flags.size(), false);
  for (uint32_t y = 0; y < s.height; ++y)
    for (uint32_t x = 0; x < s.width; ++x) {
      const uint32_t id = instances[size_t(y) * s.width + x];
      if (id != UINT32_MAX && e.after.nodes[scene_instances[id].node].name == "back_wall")
        shows_mirror[(y / s.tile_size) * renderer->tiles_x() + x / s.tile_size] = true;
    }
  size_t mirror_tiles = 0, discovered = 0;
  for (size_t t = 0; t < flags.size(); ++t) {
    if (!shows_mirror[t] || (flags[t] & 1)) continue;
    ++mirror_tiles;
    discovered += (flags[t] & 2) && weights[t] > 0.0 ? 1 : 0;
  }
  ASSERT_GT(mirror_tiles, 0u);
  EXPECT_GE(double(discovered), 0.9 * double(mirror_tiles)) << discovered << " of " << mirror_tiles;
}

TEST(HiprStages, StagesRunOnAFreshRenderer) {
  // No update_scene before the stages: the discovery kernel must still see the whole scene
  // (validation layers catch any binding left out).
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  ChangeSet changes;
  changes.instances = {0};
  renderer.mark_all_owed();
  hipr_stages(renderer).stage1_visibility(changes);
  test::discover_all(renderer, 1);
  hipr_stages(renderer).build_schedule();
  EXPECT_GT(count_flag(read_tile_flags(renderer), 1), 0u);
  EXPECT_EQ(renderer.counters().non_finite_samples, 0u);
}

// ---- Edits in a row (a drag): what the screen shows wrongly stays first.

std::vector<bool> tiles_where(const std::vector<uint32_t>& instances, const Renderer& renderer,
                              const std::function<bool(uint32_t pixel)>& test) {
  const RenderSettings& s = renderer.settings();
  std::vector<bool> tiles(renderer.tile_count(), false);
  for (uint32_t i = 0; i < instances.size(); ++i)
    if (test(i))
      tiles[(i / s.width / s.tile_size) * renderer.tiles_x() + (i % s.width) / s.tile_size] = true;
  return tiles;
}

uint32_t instance_of_node(const Scene& scene, const std::string& name) {
  const std::vector<Instance> instances = scene.instances();
  for (uint32_t i = 0; i < instances.size(); ++i)
    if (scene.nodes[instances[i].node].name == name) return i;
  return UINT32_MAX;
}

Renderer& with_samples(Renderer& renderer, uint32_t spp) {
  renderer.add_samples_full_frame(spp);
  return renderer;
}

// The Cornell box with a few samples, re-rendered by HiPR in steps of 4 tiles as edits come.
struct EditedCornellBox {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer{test::context(), scene, settings()};
  Scheduler scheduler{with_samples(renderer, 2), Policy::Hipr, 4};
  EditPipeline pipeline{scene, scheduler};
};

// Two moves without a step between them: the tiles the block covered before the first move
// belong to neither of the last two G-buffers, yet they still show the block.
TEST(HiprStages, TilesAnObjectLeftTwoEditsAgoStayActive) {
  EditedCornellBox box;
  Renderer& renderer = box.renderer;
  EditPipeline& pipeline = box.pipeline;
  const uint32_t block = instance_of_node(box.scene, "tall_block");
  const std::vector<uint32_t> start = renderer.gbuffer_instances();
  const Edit move = TransformEdit{"tall_block", glm::vec3(0.12f, 0.0f, 0.0f), std::nullopt};
  pipeline.apply(move);
  const std::vector<uint32_t> first = renderer.gbuffer_instances();
  pipeline.apply(move);
  const std::vector<uint32_t> second = renderer.gbuffer_instances();
  const std::vector<uint32_t> flags = read_tile_flags(renderer);
  const std::vector<bool> left = tiles_where(start, renderer, [&](uint32_t p) {
    return start[p] == block && first[p] != block && second[p] != block;
  });
  size_t checked = 0;
  for (uint32_t t = 0; t < left.size(); ++t) {
    if (!left[t]) continue;
    ++checked;
    EXPECT_TRUE(flags[t] & abi::kTileActive)
        << "tile " << t << " still shows the block's first place";
  }
  EXPECT_GT(checked, 0u) << "the moves must uncover tiles";
}

// A tile the last edit discovered (a shadow the block cast, light it bounced) and that was not
// re-rendered before the next edit keeps its rank: the screen still shows the old shadow there.
TEST(HiprStages, DiscoveredTilesNotYetRenderedKeepTheirRankAtTheNextEdit) {
  EditedCornellBox box;
  Renderer& renderer = box.renderer;
  Scheduler& scheduler = box.scheduler;
  EditPipeline& pipeline = box.pipeline;
  pipeline.apply(TransformEdit{"tall_block", glm::vec3(0.12f, 0.0f, 0.0f), std::nullopt});
  while (scheduler.leading_steps_pending()) scheduler.step();  // stage 2 done, stage 3 not begun
  const std::vector<uint32_t> flags1 = read_tile_flags(renderer);
  const std::vector<double> weights1 = read_tile_weights(renderer);
  pipeline.apply(TransformEdit{"short_block", glm::vec3(0.0f, 0.0f, 0.05f), std::nullopt});
  const std::vector<uint32_t> flags2 = read_tile_flags(renderer);
  const std::vector<double> weights2 = read_tile_weights(renderer);
  size_t discovered = 0;
  for (uint32_t t = 0; t < flags1.size(); ++t) {
    if ((flags1[t] & abi::kTileDiscovered) == 0 || (flags1[t] & abi::kTileActive) != 0) continue;
    ++discovered;
    EXPECT_TRUE(flags2[t] & (abi::kTileActive | abi::kTileDiscovered)) << "tile " << t;
    EXPECT_GE(weights2[t], weights1[t]) << "tile " << t;
  }
  EXPECT_GT(discovered, 0u);
}

}  // namespace
}  // namespace hipr
