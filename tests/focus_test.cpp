// Attention-guided rendering (docs/method.md#focus): a focus changes the order of HiPR's
// re-render and nothing else. Its tiles come first, then the tiles its light paths reach, then
// the rest outward; after an edit the edit's tiles come before the focus's; every schedule still
// ends on exactly the full-frame render.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/error.h"
#include "hipr/edit_pipeline.h"
#include "hipr/edits.h"
#include "hipr/focus.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "render/render_readback.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

RenderSettings settings() { return test::render_settings(64, 48, 8, 6, 21); }

Scene cornell() { return load_scene(test::asset("cornell_box.gltf")); }

// A full-frame render of `scene`, as a display shows it.
ImageRGB fresh(const Scene& scene, uint32_t spp) {
  return test::full_frame_display(scene, settings(), spp);
}

void run_to_convergence(Scheduler& scheduler, uint32_t spp) {
  for (int s = 0; s < 10000 && scheduler.work_since_edit() < double(spp); ++s) scheduler.step();
}

// The tiles holding at least one pixel of `pixels` (row-major, one per pixel).
std::set<uint32_t> tiles_of(const std::vector<uint8_t>& pixels, const RenderSettings& s,
                            uint32_t tiles_x) {
  std::set<uint32_t> tiles;
  for (uint32_t y = 0; y < s.height; ++y)
    for (uint32_t x = 0; x < s.width; ++x)
      if (pixels[size_t(y) * s.width + x])
        tiles.insert((y / s.tile_size) * tiles_x + x / s.tile_size);
  return tiles;
}

Focus focus_on(const Scene& scene, const char* node) {
  return {{focus_on_node(scene, find_node(scene, node))}};
}

// The focus's tiles (where its object is seen) lead the schedule.
void expect_leading(const std::vector<uint32_t>& order, const std::set<uint32_t>& tiles) {
  ASSERT_FALSE(tiles.empty());
  ASSERT_LE(tiles.size(), order.size());
  const std::set<uint32_t> first(order.begin(), order.begin() + long(tiles.size()));
  EXPECT_EQ(first, tiles);
}

TEST(Focus, NodeSeedsHoldTheSubtreesInstances) {
  const Scene scene = cornell();
  const FocusSeed seed = focus_on_node(scene, find_node(scene, "tall_block"), 2.0f);
  const std::vector<Instance> instances = scene.instances();
  ASSERT_EQ(seed.instances.size(), 1u);
  EXPECT_EQ(scene.nodes[instances[seed.instances[0]].node].name, "tall_block");
  EXPECT_EQ(seed.weight, 2.0f);
  EXPECT_THROW(focus_on_node(scene, scene.nodes.size()), InputError);
  EXPECT_THROW(validate_focus_seed({.weight = 0.0f}, "f"), InputError);
  EXPECT_THROW(validate_focus_seed({.pixel = glm::vec2(3.0f), .radius = 0.0f}, "f"), InputError);
  EXPECT_NO_THROW(validate_focus_seed({.pixel = glm::vec2(3.0f), .radius = 2.0f}, "f"));
}

TEST(Focus, ScriptOpsAddSeedsUntilCleared) {
  const Scene scene = cornell();
  Focus focus = with_focus_edit(scene, {}, FocusEdit{.node = "tall_block"});
  focus = with_focus_edit(
      scene, focus, FocusEdit{.pixel = glm::vec2(10.0f, 20.0f), .radius = 5.0f, .weight = 3.0f});
  ASSERT_EQ(focus.seeds.size(), 2u);
  EXPECT_EQ(focus.seeds[1].weight, 3.0f);
  EXPECT_EQ(describe(scene, focus), "tall_block; disc (10, 20) r 5 x3");
  EXPECT_TRUE(with_focus_edit(scene, focus, FocusEdit{.clear = true}).empty());
  EXPECT_THROW(with_focus_edit(scene, focus, FocusEdit{.node = "nothing"}), InputError);
}

// From a cold start (an empty film, no edit), hipr renders the focus's tiles first, then those
// its paths reached, then the rest by distance; the order is all that changes.
TEST(Focus, ColdStartRendersTheFocusFirstAndEndsOnTheFullFrameImage) {
  const Scene scene = cornell();
  const RenderSettings s = settings();
  Renderer renderer(test::context(), scene, s);
  Scheduler scheduler(renderer, Policy::Hipr, 4);
  const Focus focus = focus_on(scene, "tall_block");
  scheduler.set_focus(focus);
  const std::set<uint32_t> focus_tiles = tiles_of(
      focus_pixels(focus, renderer.gbuffer_instances(), s.width, s.height), s, renderer.tiles_x());
  const std::vector<uint32_t> flags = read_tile_flags(renderer);
  std::set<uint32_t> active;
  for (uint32_t t = 0; t < flags.size(); ++t)
    if (flags[t] & abi::kTileActive) active.insert(t);
  EXPECT_EQ(active, focus_tiles);  // stage 1 marked where the block is seen, nothing else
  expect_leading(read_schedule(renderer), focus_tiles);
  while (scheduler.leading_steps_pending()) scheduler.step();  // stage 2 over the focus
  // Stage 3: the focus, then the tiles its paths reached (by weight), then the rest.
  const std::vector<uint32_t> order = read_schedule(renderer);
  const std::vector<uint32_t> after = read_tile_flags(renderer);
  expect_leading(order, focus_tiles);
  size_t discovered = 0;
  bool seen_undiscovered = false;
  for (size_t i = focus_tiles.size(); i < order.size(); ++i) {
    const bool reached = (after[order[i]] & abi::kTileDiscovered) != 0;
    if (reached) {
      EXPECT_FALSE(seen_undiscovered) << "a reached tile after an unreached one at " << i;
      ++discovered;
    }
    seen_undiscovered = seen_undiscovered || !reached;
  }
  EXPECT_GT(discovered, 0u);  // the block's light reaches the walls and the floor
  EXPECT_TRUE(seen_undiscovered);
  // Nothing else changed: with the same samples the image is the full-frame render's.
  const uint32_t spp = 3;
  for (int step = 0; step < 1000 && scheduler.work_since_edit() < double(spp); ++step)
    scheduler.step();
  renderer.resolve_display_all(DisplayRule::Immediate);
  const std::vector<uint32_t> counts = renderer.sample_counts();
  EXPECT_TRUE(std::all_of(counts.begin(), counts.end(), [&](uint32_t c) { return c == spp; }));
  EXPECT_EQ(renderer.displayed_image().rgb, fresh(scene, spp).rgb);
}

// A focus set midway through a round, with no edit, restarts nothing: the round ends with every
// pixel at the same count, and a converged image stays the same full-frame render.
TEST(Focus, ARefocusMidwayRestartsNothingAndKeepsCountsEven) {
  const Scene scene = cornell();
  const RenderSettings s = settings();
  Renderer renderer(test::context(), scene, s);
  Scheduler scheduler(renderer, Policy::Hipr, 5);
  renderer.add_samples_full_frame(2);
  scheduler.step();  // part of a third pass
  scheduler.step();
  scheduler.set_focus(focus_on(scene, "short_block"));
  scheduler.set_focus(
      {{FocusSeed{.pixel = glm::vec2(40.0f, 30.0f), .radius = 6.0f}}});  // again, midway
  for (int step = 0; step < 200; ++step) {
    scheduler.step();
    const std::vector<uint32_t> counts = renderer.sample_counts();
    const auto [low, high] = std::minmax_element(counts.begin(), counts.end());
    ASSERT_LE(*high - *low, 1u) << "step " << step;  // no pixel ever runs a round ahead
    if (*low == 4 && *high == 4) break;
  }
  const std::vector<uint32_t> counts = renderer.sample_counts();
  ASSERT_TRUE(std::all_of(counts.begin(), counts.end(), [](uint32_t c) { return c == 4; }));
  renderer.resolve_display_all(DisplayRule::Immediate);
  EXPECT_EQ(renderer.displayed_image().rgb, fresh(scene, 4).rgb);
}

// After an edit the edit's tiles come first, then the focus's; through edits and focus changes
// in a row every run ends on exactly the full-frame render of the edited scene.
TEST(Focus, AfterAnEditTheEditsTilesComeFirstThenTheFocus) {
  Scene scene = cornell();
  const RenderSettings s = settings();
  Renderer renderer(test::context(), scene, s);
  Scheduler scheduler(renderer, Policy::Hipr, 6);
  scheduler.set_first_visit_spp(2);
  const uint32_t spp = 3;
  renderer.add_samples_full_frame(spp);
  const Focus focus = focus_on(scene, "tall_block");
  scheduler.set_focus(focus);
  const Scene before = scene;
  apply_edit(scene, MaterialEdit{"red", {{"base_color", {0.1f, 0.2f, 0.7f}}}});
  const ChangeSet red = diff_scenes(before, scene);
  scheduler.on_edit(scene, red);
  const std::vector<uint32_t> ids = renderer.gbuffer_instances();
  const std::set<uint32_t> focus_tiles =
      tiles_of(focus_pixels(focus, ids, s.width, s.height), s, renderer.tiles_x());
  const std::vector<uint32_t> flags = read_tile_flags(renderer);
  const std::vector<uint32_t> order = read_schedule(renderer);
  const Focus red_wall{{FocusSeed{.instances = red.instances}}};
  const std::set<uint32_t> wall_tiles =
      tiles_of(focus_pixels(red_wall, ids, s.width, s.height), s, renderer.tiles_x());
  expect_leading(order, wall_tiles);
  // Then the focus's tiles not already among the wall's, before any other tile.
  std::set<uint32_t> focus_only;
  for (uint32_t t : focus_tiles)
    if (!wall_tiles.count(t)) focus_only.insert(t);
  ASSERT_FALSE(focus_only.empty());
  const std::set<uint32_t> next(order.begin() + long(wall_tiles.size()),
                                order.begin() + long(wall_tiles.size() + focus_only.size()));
  EXPECT_EQ(next, focus_only);
  for (uint32_t t : focus_only) EXPECT_NE(flags[t] & abi::kTileActive, 0u);
  run_to_convergence(scheduler, spp);
  EXPECT_EQ(scheduler.displayed_image().rgb, fresh(scene, spp).rgb);
  // A move, a new focus midway through its re-render, and the focus cleared.
  const Scene moved_from = scene;
  apply_edit(scene, TransformEdit{"short_block", glm::vec3(0.05f, 0.0f, 0.0f), std::nullopt});
  scheduler.on_edit(scene, diff_scenes(moved_from, scene));
  scheduler.step();
  scheduler.set_focus(
      {{FocusSeed{.pixel = glm::vec2(10.0f, 40.0f), .radius = 9.0f, .weight = 2.0f}}});
  scheduler.step();
  scheduler.set_focus({});
  run_to_convergence(scheduler, spp);
  EXPECT_EQ(scheduler.displayed_image().rgb, fresh(scene, spp).rgb);
}

// A camera edit makes every tile active: the focus orders them, its own first. (With the
// reprojection on, the tiles of its rejected pixels come before the focus: Reproject tests.)
TEST(Focus, OrdersACameraEditsTilesFromTheFocus) {
  Scene scene = cornell();
  const RenderSettings s = settings();
  Renderer renderer(test::context(), scene, s);
  Scheduler scheduler(renderer, Policy::Hipr, 6);
  scheduler.set_reproject(false);
  renderer.add_samples_full_frame(2);
  const FocusSeed disc{.pixel = glm::vec2(52.0f, 36.0f), .radius = 7.0f};
  scheduler.set_focus({{disc}});
  const Scene before = scene;
  apply_edit(scene, CameraEdit{glm::vec3(0.02f, 0.0f, 0.0f), std::nullopt});
  scheduler.on_edit(scene, diff_scenes(before, scene));
  const std::set<uint32_t> disc_tiles =
      tiles_of(focus_pixels({{disc}}, renderer.gbuffer_instances(), s.width, s.height), s,
               renderer.tiles_x());
  const std::vector<uint32_t> order = read_schedule(renderer);
  expect_leading(order, disc_tiles);
  // The other tiles go outward from the disc: distance never decreases along the schedule.
  const auto distance = [&](uint32_t tile) {
    uint32_t best = UINT32_MAX;
    for (uint32_t f : disc_tiles) {
      const int dx = int(tile % renderer.tiles_x()) - int(f % renderer.tiles_x());
      const int dy = int(tile / renderer.tiles_x()) - int(f / renderer.tiles_x());
      best = std::min(best, uint32_t(dx * dx + dy * dy));
    }
    return best;
  };
  for (size_t i = disc_tiles.size() + 1; i < order.size(); ++i)
    EXPECT_LE(distance(order[i - 1]), distance(order[i])) << i;
  run_to_convergence(scheduler, 2);
  EXPECT_EQ(scheduler.displayed_image().rgb, fresh(scene, 2).rgb);
}

// Knowing where the render converges, the focus's tiles run ahead of the round by the lead
// (whole visits), never past that count: the focus converges first and every pixel ends with
// the same samples, on the full-frame image.
TEST(Focus, TheFocusRunsAheadButNeverPastTheConvergedCount) {
  const Scene scene = cornell();
  const RenderSettings s = settings();
  for (const uint32_t spp : {4u, 2u}) {
    Renderer renderer(test::context(), scene, s);
    Scheduler scheduler(renderer, Policy::Hipr, 4);
    scheduler.set_converged_spp(spp);
    scheduler.set_focus_lead(2);
    scheduler.set_focus(focus_on(scene, "tall_block"));
    while (scheduler.leading_steps_pending()) scheduler.step();
    std::vector<uint32_t> counts = renderer.sample_counts();
    EXPECT_EQ(*std::max_element(counts.begin(), counts.end()), 1u)
        << "first one visit, where the focus is";
    EXPECT_TRUE(scheduler.lead_pass_pending());
    while (scheduler.lead_pass_pending()) scheduler.step();
    const std::vector<uint32_t> flags = read_tile_flags(renderer);
    counts = renderer.sample_counts();
    uint32_t focus_pixels = 0;
    for (uint32_t y = 0; y < s.height; ++y)
      for (uint32_t x = 0; x < s.width; ++x) {
        const uint32_t tile = (y / s.tile_size) * renderer.tiles_x() + x / s.tile_size;
        const uint32_t count = counts[size_t(y) * s.width + x];
        if (flags[tile] & abi::kTileFocus) {
          EXPECT_EQ(count, std::min(1u + 2u, spp)) << "a focus pixel after its lead";
          ++focus_pixels;
        } else {
          EXPECT_EQ(count, 0u) << "the rest waits its turn";
        }
      }
    EXPECT_GT(focus_pixels, 0u);
    for (int step = 0; step < 1000 && scheduler.work_since_edit() < double(spp); ++step) {
      scheduler.step();
      const std::vector<uint32_t> now = renderer.sample_counts();
      ASSERT_LE(*std::max_element(now.begin(), now.end()), spp)
          << "no pixel passes the converged count";
    }
    const std::vector<uint32_t> final_counts = renderer.sample_counts();
    EXPECT_TRUE(std::all_of(final_counts.begin(), final_counts.end(),
                            [&](uint32_t c) { return c == spp; }));
    renderer.resolve_display_all(DisplayRule::Immediate);
    EXPECT_EQ(renderer.displayed_image().rgb, fresh(scene, spp).rgb) << spp;
  }
}

// Policies other than hipr keep their order.
TEST(Focus, BucketOrdersIgnoreIt) {
  const Scene scene = cornell();
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Spiral, 4);
  const std::vector<uint32_t> order = read_schedule(renderer);
  scheduler.set_focus(focus_on(scene, "tall_block"));
  EXPECT_EQ(read_schedule(renderer), order);
  EXPECT_FALSE(scheduler.leading_steps_pending());
}

// A script's focus op goes through the edit pipeline: the scene does not change, the scheduler
// follows the focus, and the next edit is planned with it.
TEST(Focus, EditPipelineHandsScriptFocusToTheScheduler) {
  Scene scene = cornell();
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 4);
  renderer.add_samples_full_frame(1);
  EditPipeline pipeline(scene, scheduler);
  const std::string hash = scene.content_hash;
  EXPECT_TRUE(pipeline.apply(FocusEdit{.node = "short_block", .weight = 2.0f}).empty());
  ASSERT_EQ(scheduler.focus().seeds.size(), 1u);
  EXPECT_EQ(scheduler.focus().seeds[0].weight, 2.0f);
  EXPECT_THROW(pipeline.apply(FocusEdit{.node = "no_such_node"}), InputError);
  EXPECT_EQ(scheduler.focus().seeds.size(), 1u);  // a refused op changes nothing
  pipeline.apply(FocusEdit{.clear = true});
  EXPECT_TRUE(scheduler.focus().empty());
  EXPECT_EQ(scene.content_hash, hash);
}

}  // namespace
}  // namespace hipr
