// The scheduler drives any progressive renderer through the narrow ProgressiveRenderer
// interface: a CPU fake that only records what it is asked proves that the policies need
// nothing else, and pins down the step protocol (leading steps, rounds, display rules). Also
// the edit pipeline, which diffs edits into change sets and skips edits that change nothing.
#include <gtest/gtest.h>

#include <numeric>

#include "core/error.h"
#include "hipr/edit_pipeline.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "test_support.h"

namespace hipr {
namespace {

// HiPR's stages as calls, driven by the HiPR policy (make_hipr_policy): stage 1 reports `active`
// tiles (stage1_focus `focus_active`).
struct FakeStages final : HiprStageRunner {
  uint32_t active = 3, focus_active = 2, seeded = 3, leading = 0, discovered = 0;
  uint32_t stage1_calls = 0, focus_calls = 0, schedule_builds = 0;
  std::vector<std::pair<uint32_t, uint32_t>> stage2;  // (offset, count) per call
  Focus focus;
  uint32_t stage1_visibility(const ChangeSet&) override {
    ++stage1_calls;
    return active;
  }
  void set_focus(const Focus& f) override { focus = f; }
  void set_reprojection(bool) override {}
  uint32_t seeded_tiles() const override { return seeded; }
  uint32_t lead_tiles() const override { return leading; }
  uint32_t discovered_tiles() const override { return discovered; }
  uint32_t stage1_focus() override {
    ++focus_calls;
    return focus_active;
  }
  void stage2_discover(uint32_t offset, uint32_t count, uint32_t,
                       std::optional<DisplayRule>) override {
    stage2.emplace_back(offset, count);
  }
  void build_schedule() override { ++schedule_builds; }
};

// A renderer that renders nothing: it keeps the schedule and per tile a sample count (as the
// trace kernel counts: a restart at the first visit after an edit, the round target), and logs
// the calls.
struct FakeRenderer final : ProgressiveRenderer {
  TileGrid grid{32, 24, 8, 4, 3, 5};
  std::vector<uint32_t> tile_samples = std::vector<uint32_t>(12, 0);
  std::vector<bool> tile_owed = std::vector<bool>(12, false);
  uint32_t target = 0, focus_target = 0, lead_target = 0;
  std::vector<std::pair<uint32_t, uint32_t>> lead_calls;  // render_lead (offset, count)
  std::vector<uint32_t> order;
  std::vector<uint32_t> rendered;       // tile ids, in the order rendered
  std::vector<uint32_t> samples_given;  // spp per render_schedule call
  std::vector<std::optional<DisplayRule>> step_rules;
  std::vector<DisplayRule> whole_resolves;
  uint32_t captures = 0, owed_marks = 0, scene_updates = 0;
  uint64_t samples = 0;
  std::optional<FakeStages> stages;

  TileGrid tile_grid() const override { return grid; }
  void update_scene(const Scene&, const ChangeSet&) override { ++scene_updates; }
  void set_schedule(std::span<const uint32_t> o) override { order.assign(o.begin(), o.end()); }
  void render_schedule(uint32_t offset, uint32_t count, uint32_t spp, bool,
                       std::optional<DisplayRule> then_resolve) override {
    count = std::min(count, grid.tile_count() - offset);
    for (uint32_t i = offset; i < offset + count; ++i) {
      const uint32_t tile = order[i];
      rendered.push_back(tile);
      const uint32_t have = tile_owed[tile] ? 0 : tile_samples[tile];
      const uint32_t add = target == 0 ? spp : (have >= target ? 0 : target - have);
      tile_samples[tile] = have + add;
      tile_owed[tile] = false;
      samples += uint64_t(add) * grid.tile_size * grid.tile_size;
    }
    samples_given.push_back(spp);
    step_rules.push_back(then_resolve);
  }
  void render_lead(uint32_t offset, uint32_t count, std::optional<DisplayRule>) override {
    lead_calls.emplace_back(offset, count);
  }
  void mark_all_owed() override {
    ++owed_marks;
    tile_owed.assign(tile_owed.size(), true);
  }
  void set_sample_target(uint32_t t, uint32_t focus, uint32_t lead) override {
    target = t;
    focus_target = focus;
    lead_target = lead;
  }
  std::pair<uint32_t, uint32_t> sample_count_range() const override {
    uint32_t fewest = UINT32_MAX, most = 0;
    for (size_t t = 0; t < tile_samples.size(); ++t) {
      fewest = std::min(fewest, tile_owed[t] ? 0 : tile_samples[t]);
      most = std::max(most, tile_owed[t] ? 0 : tile_samples[t]);
    }
    return {fewest, most};
  }
  void resolve_display_all(DisplayRule rule) override { whole_resolves.push_back(rule); }
  void capture_stale_display() override { ++captures; }
  ImageRGB displayed_image() const override { return {grid.width, grid.height, {}}; }
  void refresh_gbuffer() override {}
  uint64_t samples_since_reset() const override { return samples; }
  void reset_counters() override { samples = 0; }
};

TEST(SchedulingInterface, BucketOrderRendersItsOrderInStepsAndShowsEachStep) {
  FakeRenderer renderer;
  Scheduler scheduler(renderer, Policy::Spiral, 5);
  scheduler.set_first_visit_spp(2);
  scheduler.on_edit(Scene{}, ChangeSet{});
  EXPECT_EQ(renderer.captures, 1u);
  EXPECT_EQ(renderer.owed_marks, 1u);
  EXPECT_EQ(renderer.scene_updates, 1u);
  EXPECT_EQ(renderer.order, tile_order(Policy::Spiral, 4, 3, 5));
  for (int s = 0; s < 4; ++s) scheduler.step();  // 12 tiles: 5 + 5 + 2, then a second round
  const std::vector<uint32_t> spiral = tile_order(Policy::Spiral, 4, 3, 5);
  ASSERT_GE(renderer.rendered.size(), 12u);
  EXPECT_EQ(std::vector<uint32_t>(renderer.rendered.begin(), renderer.rendered.begin() + 12),
            spiral);
  EXPECT_EQ(renderer.samples_given, (std::vector<uint32_t>{2, 2, 2, 1}));  // first visits get more
  for (const auto& rule : renderer.step_rules) EXPECT_EQ(rule, DisplayRule::Immediate);
}

TEST(SchedulingInterface, FullShowsWholePassesOnly) {
  FakeRenderer renderer;
  Scheduler scheduler(renderer, Policy::Full, 6);
  scheduler.set_first_visit_spp(4);  // ignored: passes stay whole
  scheduler.on_edit(Scene{}, ChangeSet{});
  const size_t resolves_at_edit = renderer.whole_resolves.size();
  scheduler.step();
  EXPECT_EQ(renderer.whole_resolves.size(), resolves_at_edit);  // half a pass: nothing new shown
  scheduler.step();
  EXPECT_EQ(renderer.whole_resolves.size(), resolves_at_edit + 1);
  for (const auto& rule : renderer.step_rules) EXPECT_FALSE(rule.has_value());
  EXPECT_EQ(renderer.samples_given, (std::vector<uint32_t>{1, 1}));
  EXPECT_DOUBLE_EQ(scheduler.work_since_edit(), 1.0);
}

TEST(SchedulingInterface, HiprRendersItsActiveTilesAsLeadingStepsThenTheSortedRest) {
  FakeRenderer renderer;
  renderer.stages.emplace();
  Scheduler scheduler(renderer, make_hipr_policy(*renderer.stages), 2);
  EXPECT_EQ(renderer.stages->stage1_calls, 1u);  // the G-buffer before any edit
  std::vector<uint32_t> sorted(12);
  std::iota(sorted.rbegin(), sorted.rend(), 0u);
  renderer.set_schedule(sorted);
  scheduler.on_edit(Scene{}, ChangeSet{});
  EXPECT_EQ(renderer.stages->stage1_calls, 2u);
  EXPECT_EQ(renderer.stages->schedule_builds, 1u);
  EXPECT_TRUE(scheduler.leading_steps_pending());
  scheduler.step();
  scheduler.step();
  EXPECT_EQ(renderer.stages->stage2, (std::vector<std::pair<uint32_t, uint32_t>>{{0, 2}, {2, 1}}));
  EXPECT_FALSE(scheduler.leading_steps_pending());
  EXPECT_EQ(renderer.stages->schedule_builds, 2u);  // stage 3 after the last active tile
  scheduler.step();
  EXPECT_EQ(renderer.rendered, (std::vector<uint32_t>{8, 7}));  // entries 3 and 4 of the order
  for (const auto& rule : renderer.step_rules)
    EXPECT_EQ(rule, DisplayRule::Difference);  // hipr's own rule
}

// A focus (docs/method.md#focus) re-plans at once without capturing, restarting or updating
// anything; its stage-2 steps lead; the round under way ends with every tile at one count.
TEST(SchedulingInterface, AFocusReplansWithoutRestartingAndEndsTheRoundEven) {
  FakeRenderer renderer;
  renderer.stages.emplace();
  std::vector<uint32_t> sorted(12);
  std::iota(sorted.begin(), sorted.end(), 0u);
  Scheduler scheduler(renderer, make_hipr_policy(*renderer.stages), 5);
  renderer.set_schedule(sorted);
  scheduler.step();  // 5 tiles of a pass before any focus: no round target yet, 1 sample each
  EXPECT_EQ(renderer.target, 0u);
  const Focus focus{{FocusSeed{.pixel = glm::vec2(3.0f, 4.0f), .radius = 2.0f}}};
  scheduler.set_focus(focus);
  EXPECT_EQ(renderer.stages->focus, focus);
  EXPECT_EQ(renderer.stages->focus_calls, 1u);
  EXPECT_EQ(renderer.stages->schedule_builds, 1u);
  EXPECT_EQ(renderer.captures, 0u);
  EXPECT_EQ(renderer.owed_marks, 0u);
  EXPECT_EQ(renderer.scene_updates, 0u);
  EXPECT_EQ(renderer.target, 1u);  // counts 0 and 1: the round under way is the one to 1
  EXPECT_TRUE(scheduler.leading_steps_pending());
  scheduler.step();  // stage 2 over the focus's two tiles
  EXPECT_EQ(renderer.stages->stage2.back(), (std::pair<uint32_t, uint32_t>{0, 2}));
  EXPECT_FALSE(scheduler.leading_steps_pending());
  EXPECT_EQ(renderer.stages->schedule_builds, 2u);
  for (int s = 0; s < 2; ++s) scheduler.step();  // the rest of the round: tiles 2..11
  for (uint32_t t = 2; t < 12; ++t) EXPECT_EQ(renderer.tile_samples[t], 1u) << t;  // none ran ahead
  EXPECT_EQ(renderer.target, 2u);                                                  // the next round
  // The scheduler keeps the focus; an empty one clears it (and plans again).
  EXPECT_EQ(scheduler.focus(), focus);
  scheduler.set_focus({});
  EXPECT_TRUE(renderer.stages->focus.empty());
  EXPECT_EQ(renderer.stages->focus_calls, 2u);
}

// Knowing the converged count, the focus takes its lead after its first visit: stage 2 visits
// every leading tile at the round target, then lead steps over those entries bring the focus's
// tiles ahead (never past the converged count), then the round goes on.
TEST(SchedulingInterface, TheFocusTakesItsLeadAfterItsFirstVisit) {
  FakeRenderer renderer;
  renderer.stages.emplace();
  renderer.stages->focus_active = 3;
  Scheduler scheduler(renderer, make_hipr_policy(*renderer.stages), 2);
  scheduler.set_converged_spp(4);
  scheduler.set_focus_lead(5);
  scheduler.set_focus({{FocusSeed{.pixel = glm::vec2(3.0f, 4.0f), .radius = 2.0f}}});
  EXPECT_EQ(renderer.target, 1u);
  EXPECT_EQ(renderer.focus_target, 0u) << "no lead before the first visit";
  scheduler.step();  // stage 2: entries 0, 1
  scheduler.step();  // stage 2: entry 2, then the sort
  EXPECT_FALSE(scheduler.leading_steps_pending());
  EXPECT_EQ(renderer.focus_target, 4u) << "1 + 5 visits, held at the converged count";
  EXPECT_TRUE(renderer.lead_calls.empty());
  scheduler.step();
  scheduler.step();
  EXPECT_EQ(renderer.lead_calls, (std::vector<std::pair<uint32_t, uint32_t>>{{0, 2}, {2, 1}}));
  const size_t rendered = renderer.rendered.size();
  scheduler.step();  // the rest of the round, from entry 3
  EXPECT_EQ(renderer.rendered.size(), rendered + 2);
  EXPECT_EQ(renderer.rendered[rendered], renderer.order[3]);
  // Without a lead the focus only orders.
  scheduler.set_focus_lead(0);
  EXPECT_EQ(renderer.focus_target, 0u);
}

// After an edit that activates every tile (a camera move), the focus does not wait for the whole
// stage 2: its lead steps come once the scored entries (the focus's tiles lead the order) have
// had their first visit, then stage 2 goes on.
TEST(SchedulingInterface, AfterACameraEditTheLeadComesOnceTheFocusIsVisited) {
  FakeRenderer renderer;
  renderer.stages.emplace();
  Scheduler scheduler(renderer, make_hipr_policy(*renderer.stages), 2);
  scheduler.set_converged_spp(8);
  scheduler.set_focus({{FocusSeed{.pixel = glm::vec2(3.0f, 4.0f), .radius = 2.0f}}});
  renderer.stages->active = 12;  // every tile
  renderer.stages->seeded = 3;   // the focus's three
  scheduler.on_edit(Scene{}, ChangeSet{});
  renderer.stages->stage2.clear();
  scheduler.step();  // stage 2: entries 0, 1
  scheduler.step();  // stage 2: entry 2 (a step stops at the seeded ones), then the lead begins
  EXPECT_EQ(renderer.stages->stage2, (std::vector<std::pair<uint32_t, uint32_t>>{{0, 2}, {2, 1}}));
  EXPECT_EQ(renderer.focus_target, 1u + kDefaultFocusLead) << "the round's 1 and the lead's visits";
  scheduler.step();
  scheduler.step();
  EXPECT_EQ(renderer.lead_calls, (std::vector<std::pair<uint32_t, uint32_t>>{{0, 2}, {2, 1}}));
  EXPECT_TRUE(scheduler.leading_steps_pending());
  scheduler.step();  // stage 2 goes on from entry 3
  EXPECT_EQ(renderer.stages->stage2.back(), (std::pair<uint32_t, uint32_t>{3, 2}));
}

// After an edit, the pixels stage 1 saw change most lead (docs/method.md#the-edits-lead): once
// the active tiles and the strongly discovered ones had their first visit, lead steps over the
// leading entries bring them to the round target plus the lead (never past the converged
// count), then the round goes on. A new focus plans no edit lead; a lead of 0 is none.
TEST(SchedulingInterface, TheEditsLeadComesAfterTheStronglyDiscoveredTiles) {
  FakeRenderer renderer;
  renderer.stages.emplace();
  renderer.stages->leading = 2;     // tiles with pixels that lead
  renderer.stages->discovered = 4;  // strongly discovered tiles after the 3 active ones
  Scheduler scheduler(renderer, make_hipr_policy(*renderer.stages), 2);
  scheduler.set_first_visit_spp(2);
  scheduler.set_converged_spp(16);
  scheduler.set_edit_lead(3);
  scheduler.on_edit(Scene{}, ChangeSet{});
  scheduler.step();  // stage 2: entries 0, 1
  scheduler.step();  // stage 2: entry 2, then the sort
  EXPECT_EQ(renderer.lead_target, 0u) << "no lead before the discovered tiles' first visit";
  scheduler.step();  // entries 3, 4
  scheduler.step();  // entries 5, 6: the last strongly discovered
  EXPECT_TRUE(renderer.lead_calls.empty());
  scheduler.step();  // the lead begins
  EXPECT_EQ(renderer.lead_target, 2u + 3u) << "the round's 2 and the lead's 3 visits";
  scheduler.step();
  scheduler.step();
  // A lead step holds 2 x 2 / 3 tiles (one): about a first visit's work.
  EXPECT_EQ(renderer.lead_calls,
            (std::vector<std::pair<uint32_t, uint32_t>>{{0, 1}, {1, 1}, {2, 1}}));
  const size_t rendered = renderer.rendered.size();
  scheduler.step();  // the round goes on from entry 7
  ASSERT_EQ(renderer.rendered.size(), rendered + 2);
  EXPECT_EQ(renderer.rendered[rendered], renderer.order[7]);
  for (int s = 0; s < 3; ++s) scheduler.step();  // the round ends: the lead target stays
  EXPECT_EQ(renderer.target, 3u);
  EXPECT_EQ(renderer.lead_target, 5u);

  // Held at the converged count.
  scheduler.set_converged_spp(4);
  scheduler.on_edit(Scene{}, ChangeSet{});
  while (renderer.lead_target == 0 && scheduler.work_since_edit() < 4.0) scheduler.step();
  EXPECT_EQ(renderer.lead_target, 4u);
  // A focus plans no edit lead.
  renderer.lead_calls.clear();
  scheduler.set_focus({{FocusSeed{.pixel = glm::vec2(3.0f, 4.0f), .radius = 2.0f}}});
  EXPECT_EQ(renderer.lead_target, 0u);
  scheduler.set_focus({});
  renderer.lead_calls.clear();
  // Without a lead nothing runs ahead.
  scheduler.set_edit_lead(0);
  scheduler.set_converged_spp(16);
  scheduler.on_edit(Scene{}, ChangeSet{});
  for (int s = 0; s < 8; ++s) scheduler.step();
  EXPECT_EQ(renderer.lead_target, 0u);
  EXPECT_TRUE(renderer.lead_calls.empty());
}

TEST(SchedulingInterface, HiprNeedsARendererWithItsStages) {
  FakeRenderer renderer;
  EXPECT_THROW(Scheduler(renderer, Policy::Hipr, 2), InputError);
  EXPECT_THROW(make_policy(Policy::Oracle), InputError);  // hipr bench makes the oracle
}

TEST(EditPipeline, DiffsLikeAFullCopyAndSkipsEditsThatChangeNothing) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  FakeRenderer renderer;
  Scheduler scheduler(renderer, Policy::Scanline, 4);
  EditPipeline pipeline(scene, scheduler);
  const Scene before = scene;
  const Edit move = TransformEdit{"tall_block", glm::vec3(0.05f, 0.0f, 0.0f), std::nullopt};
  const ChangeSet changes = pipeline.apply(move);
  Scene expected = before;
  apply_edit(expected, move);
  const ChangeSet full = diff_scenes(before, expected);
  EXPECT_EQ(changes.instances, full.instances);
  EXPECT_TRUE(changes.transforms);
  EXPECT_EQ(renderer.scene_updates, 1u);
  EXPECT_TRUE(pipeline.apply(TransformEdit{"tall_block", glm::vec3(0.0f), std::nullopt}).empty());
  EXPECT_EQ(renderer.scene_updates, 1u);  // nothing changed: no re-render
  EXPECT_THROW(pipeline.apply(TransformEdit{"no_such_node", glm::vec3(1.0f), std::nullopt}),
               InputError);
  EXPECT_EQ(renderer.scene_updates, 1u);
}

}  // namespace
}  // namespace hipr
