// Stage 1 for punctual-light edits (light_reach.comp): a changed light activates the tiles whose
// visible surfaces it reaches before or after the edit (range, cone and shadows respected), the
// tiles whose direct light changed the most come first, and the schedule still ends on the
// full-frame image of the edited scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "card_scene.h"
#include "hipr/edits.h"
#include "hipr/hipr_stages.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "render/render_readback.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

constexpr uint32_t kSize = 64, kTile = 8, kTilesX = kSize / kTile;

RenderSettings settings() { return test::render_settings(kSize, kSize, kTile, 4, 5); }

MaterialParameters white() {
  MaterialParameters m = default_material_params();
  m.base_color = glm::vec3(0.8f);
  m.specular_weight = 0.0f;
  return m;
}

// Adds a light on its own root node (which travels down the node's -Z); returns the node.
uint32_t add_light(Scene& scene, const std::string& name, const PunctualLight& light,
                   const glm::mat4& local) {
  scene.lights.push_back(light);
  scene.lights.back().name = name;
  Node node;
  node.name = name;
  node.light = int(scene.lights.size() - 1);
  node.local = local;
  scene.nodes.push_back(node);
  scene.children.push_back({});
  scene.root_nodes.push_back(uint32_t(scene.nodes.size() - 1));
  return uint32_t(scene.nodes.size() - 1);
}

// The card camera's floor ([-1,1]^2 at z = 0 fills the frame) lit by a point lamp of range 1.1,
// 0.2 above the floor's left edge.
Scene lamp_floor() {
  Scene scene = test::make_card_camera_scene(0.0f);
  test::add_card(scene, "floor", glm::mat4(1.0f), white());
  PunctualLight lamp;
  lamp.intensity = 2.0f;
  lamp.range = 1.1f;
  add_light(scene, "lamp", lamp, glm::translate(glm::mat4(1.0f), {-1.0f, 0.0f, 0.2f}));
  return scene;
}

// The floor point pixel (x, y) shows (pixel centres, rows from the top).
glm::vec2 floor_point(uint32_t x, uint32_t y) {
  return {-1.0f + (float(x) + 0.5f) * 2.0f / kSize, 1.0f - (float(y) + 0.5f) * 2.0f / kSize};
}

// Tiles with a pixel whose floor point lies within `range` of the lamp at any of `lamps`.
std::vector<bool> tiles_in_range(const std::vector<glm::vec3>& lamps, float range) {
  std::vector<bool> tiles(kTilesX * kTilesX, false);
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x)
      for (const glm::vec3& lamp : lamps)
        if (glm::length(glm::vec3(floor_point(x, y), 0.0f) - lamp) < range)
          tiles[(y / kTile) * kTilesX + x / kTile] = true;
  return tiles;
}

struct Staged {
  std::unique_ptr<Renderer> renderer;
  uint32_t active = 0;
  std::vector<uint32_t> flags;
};

// A renderer converged a little on `before`, its display resolved, then stage 1 for the edit.
Staged stage_one(const Scene& before, const Scene& after, uint32_t spp = 2) {
  Staged s;
  s.renderer = std::make_unique<Renderer>(test::context(), before, settings());
  s.renderer->add_samples_full_frame(spp);
  s.renderer->resolve_display_all(DisplayRule::Immediate);
  hipr_stages(*s.renderer).stage1_visibility({});  // the G-buffer of the scene as it was
  const ChangeSet changes = diff_scenes(before, after);
  s.renderer->update_scene(after, changes);
  s.renderer->mark_all_owed();
  s.active = hipr_stages(*s.renderer).stage1_visibility(changes);
  s.flags = read_tile_flags(*s.renderer);
  return s;
}

bool active(const std::vector<uint32_t>& flags, uint32_t tile) {
  return (flags[tile] & abi::kTileActive) != 0;
}

TEST(LightReach, ChangeSetKeepsTheLightBeforeAndAfter) {
  const Scene before = lamp_floor();
  Scene after = before;
  apply_edit(after, TransformEdit{"lamp", glm::vec3(0.1f, 0.0f, 0.0f), std::nullopt});
  const ChangeSet changes = diff_scenes(before, after);
  ASSERT_EQ(changes.lights.size(), 1u);
  EXPECT_EQ(glm::vec3(changes.lights[0].before.world[3]), glm::vec3(-1.0f, 0.0f, 0.2f));
  EXPECT_NEAR(changes.lights[0].after.world[3].x, -0.9f, 1e-6f);
  EXPECT_EQ(changes.lights[0].before.light.range, 1.1f);
}

TEST(LightReach, ALampWhoseRangeCoversHalfTheFrameActivatesThoseTiles) {
  const Scene before = lamp_floor();
  Scene after = before;
  apply_edit(after, TransformEdit{"lamp", glm::vec3(0.05f, 0.0f, 0.0f), std::nullopt});
  const std::vector<bool> expected =
      tiles_in_range({{-1.0f, 0.0f, 0.2f}, {-0.95f, 0.0f, 0.2f}}, 1.1f);
  const size_t in_range = size_t(std::count(expected.begin(), expected.end(), true));
  ASSERT_GT(in_range, expected.size() * 4 / 10);  // the scene is what the test says: about half
  ASSERT_LT(in_range, expected.size() * 6 / 10);
  const Staged s = stage_one(before, after);
  EXPECT_EQ(s.active, in_range);
  // Tile by tile, allowing for pixel centres within a float's rounding of the range.
  size_t differing = 0;
  for (uint32_t t = 0; t < expected.size(); ++t) differing += active(s.flags, t) != expected[t];
  EXPECT_LE(differing, 1u);
}

TEST(LightReach, ARangeChangeActivatesWhereEitherRangeReaches) {
  const Scene before = lamp_floor();
  Scene after = before;
  apply_edit(after, LightEdit{.node = "lamp", .range = 0.5f});
  const std::vector<bool> expected = tiles_in_range({{-1.0f, 0.0f, 0.2f}}, 1.1f);
  const Staged s = stage_one(before, after);
  EXPECT_EQ(s.active, size_t(std::count(expected.begin(), expected.end(), true)));
  EXPECT_LT(s.active, s.flags.size());
}

// A sun straight down (a directional light, down its node's -Z) over the floor, its right half
// (x > 0) shadowed by a card behind the camera that the camera does not see.
Scene half_shadowed_floor() {
  Scene scene = test::make_card_camera_scene(0.0f);
  test::add_card(scene, "floor", glm::mat4(1.0f), white());
  test::add_card(
      scene, "blocker",
      glm::scale(glm::translate(glm::mat4(1.0f), {2.0f, 0.0f, 5.0f}), glm::vec3(2.0f, 3.0f, 1.0f)),
      test::black_material());
  PunctualLight sun;
  sun.type = LightType::Directional;
  add_light(scene, "sun", sun, glm::mat4(1.0f));
  return scene;
}

TEST(LightReach, ShadowedSurfacesAreNotReached) {
  const Scene before = half_shadowed_floor();
  Scene after = before;
  apply_edit(after, LightEdit{.node = "sun", .color = glm::vec3(1.0f, 0.5f, 0.2f)});
  const Staged s = stage_one(before, after);
  // Left half lit (columns 0-3 of 8), right half in the blocker's shadow in both states.
  for (uint32_t t = 0; t < s.flags.size(); ++t)
    EXPECT_EQ(active(s.flags, t), t % kTilesX < kTilesX / 2) << t;
}

TEST(LightReach, TilesWhereTheShadowMovedComeFirst) {
  const Scene before = half_shadowed_floor();
  Scene after = before;
  // Tilted about Y: the light now travels toward -X a little, the shadow's edge moves left by
  // 5 tan(4 deg) = 0.35, across a strip of tile columns 2 and 3 (x in [-0.5, 0)).
  apply_edit(after,
             TransformEdit{"sun", std::nullopt,
                           glm::rotate(glm::mat4(1.0f), glm::radians(4.0f), glm::vec3(0, 1, 0))});
  Staged s = stage_one(before, after);
  for (uint32_t t = 0; t < s.flags.size(); ++t)
    EXPECT_EQ(active(s.flags, t), t % kTilesX < kTilesX / 2) << t;
  test::discover_all(*s.renderer, 1);
  hipr_stages(*s.renderer).build_schedule();
  const std::vector<uint32_t> order = read_schedule(*s.renderer);
  // The 8 tiles of column 3 are wholly in the moved shadow's strip: they lead.
  for (uint32_t i = 0; i < kTilesX; ++i) EXPECT_EQ(order[i] % kTilesX, 3u) << i;
}

TEST(LightReach, MovedLightScheduleEndsOnTheFullFrameImage) {
  const Scene before = lamp_floor();
  Scene after = before;
  apply_edit(after, TransformEdit{"lamp", glm::vec3(0.3f, 0.2f, 0.0f), std::nullopt});
  Staged s = stage_one(before, after, 3);
  Renderer& renderer = *s.renderer;
  test::discover_all(renderer, 1);
  hipr_stages(renderer).build_schedule();
  for (uint32_t offset = 0; offset < renderer.tile_count(); offset += 7)
    renderer.render_schedule(offset, 7, 1, true);
  renderer.render_schedule(0, renderer.tile_count(), 2, false);
  Renderer full(test::context(), after, settings());
  full.add_samples_full_frame(3);
  EXPECT_EQ(renderer.image().rgb, full.image().rgb);
}

// The light tree is built again at a light edit (docs/method.md#many-light-sampling): a lamp of
// lamp_hall moved and another recoloured, the schedule still ends on the full-frame render of the
// edited hall, whose tree sends each point's shadow rays elsewhere than the old one did.
TEST(LightReach, LampHallEditsEndOnTheFullFrameImageWithTheLightTree) {
  const Scene before = load_scene(test::asset("lamp_hall.glb"));
  Scene after = before;
  apply_edit(after, TransformEdit{"lamp_1_1_1", glm::vec3(0.0f, 0.0f, 0.6f), std::nullopt});
  apply_edit(after, LightEdit{.node = "lamp_2_1_0", .color = glm::vec3(0.2f, 0.5f, 1.0f)});
  Staged s = stage_one(before, after, 3);
  Renderer& renderer = *s.renderer;
  test::discover_all(renderer, 1);
  hipr_stages(renderer).build_schedule();
  for (uint32_t offset = 0; offset < renderer.tile_count(); offset += 5)
    renderer.render_schedule(offset, 5, 1, true);
  renderer.render_schedule(0, renderer.tile_count(), 2, false);
  Renderer full(test::context(), after, settings());
  full.add_samples_full_frame(3);
  EXPECT_EQ(renderer.image().rgb, full.image().rgb);
  Renderer stale(test::context(), before, settings());
  stale.add_samples_full_frame(3);
  EXPECT_NE(stale.image().rgb, full.image().rgb);
}

TEST(LightReach, MoreChangedLightsThanItFollowsActivateEveryTile) {
  Scene before = lamp_floor();
  // kMaxReachLights + 1 lamps under one parent, far out of the floor's reach: moving the parent
  // changes them all.
  Node parent;
  parent.name = "rig";
  before.nodes.push_back(parent);
  before.children.push_back({});
  const uint32_t rig = uint32_t(before.nodes.size() - 1);
  before.root_nodes.push_back(rig);
  PunctualLight lamp;
  lamp.range = 0.1f;
  for (uint32_t i = 0; i <= abi::kMaxReachLights; ++i) {
    const uint32_t node = add_light(before, "far" + std::to_string(i), lamp,
                                    glm::translate(glm::mat4(1.0f), {50.0f, 0, 0}));
    before.root_nodes.pop_back();
    before.nodes[node].parent = int(rig);
    before.children[rig].push_back(node);
  }
  Scene after = before;
  apply_edit(after, TransformEdit{"rig", glm::vec3(1.0f, 0.0f, 0.0f), std::nullopt});
  ASSERT_EQ(diff_scenes(before, after).lights.size(), abi::kMaxReachLights + 1);
  EXPECT_EQ(stage_one(before, after).active, kTilesX * kTilesX);
  // One of them moved: out of reach before and after, nothing to re-render first.
  Scene one = before;
  apply_edit(one, TransformEdit{"far0", glm::vec3(1.0f, 0.0f, 0.0f), std::nullopt});
  EXPECT_EQ(stage_one(before, one).active, 0u);
}

}  // namespace
}  // namespace hipr
