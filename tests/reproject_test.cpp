// Camera edits reuse the converged image (reproject_display.comp): a pure pan reprojects exactly
// where nothing is disoccluded, rejected pixels are ranked first, a view-dependent value gives
// way to its fresh samples, and the schedule still ends on the full-frame render of the new view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "card_scene.h"
#include "hipr/edits.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "render/render_readback.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

constexpr uint32_t kSize = 64, kTile = 8;

RenderSettings settings() { return test::render_settings(kSize, kSize, kTile, 4, 21); }

// The card camera's card (filling the frame, unless moved by `card`) lit unevenly by a lamp, so
// that pixels differ.
Scene lit_card(const glm::mat4& card = glm::mat4(1.0f)) {
  Scene scene = test::make_card_camera_scene(0.0f);
  MaterialParameters white = default_material_params();
  white.base_color = glm::vec3(0.8f);
  white.specular_weight = 0.0f;
  test::add_card(scene, "card", card, white);
  PunctualLight lamp;
  lamp.intensity = 1.5f;
  scene.lights.push_back(lamp);
  Node node;
  node.name = "lamp";
  node.light = 0;
  node.local = glm::translate(glm::mat4(1.0f), {-0.4f, 0.3f, 0.6f});
  scene.nodes.push_back(node);
  scene.children.push_back({});
  scene.root_nodes.push_back(uint32_t(scene.nodes.size() - 1));
  return scene;
}

void run_to_convergence(Scheduler& scheduler, uint32_t spp) {
  for (int s = 0; s < 10000 && scheduler.work_since_edit() < double(spp); ++s) scheduler.step();
}

float at(const ImageRGB& image, uint32_t x, uint32_t y, int c) {
  return image.rgb[(size_t(y) * image.width + x) * 3 + size_t(c)];
}

TEST(Reproject, APanReprojectsExactlyWhereNothingIsDisoccluded) {
  Scene scene = lit_card();
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 8);
  renderer.add_samples_full_frame(4);
  renderer.resolve_display_all(DisplayRule::Immediate);  // what the capture at the edit takes too
  const ImageRGB before = scheduler.displayed_image();
  // Two pixels to the right (the card spans 2 units over 64 pixels at the camera's distance).
  const Scene old = scene;
  apply_edit(scene, CameraEdit{glm::vec3(2.0f * 2.0f / kSize, 0.0f, 0.0f), std::nullopt});
  const ChangeSet changes = diff_scenes(old, scene);
  ASSERT_TRUE(changes.camera_only());
  scheduler.on_edit(scene, changes);
  const ImageRGB after = scheduler.displayed_image();
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x + 2 < kSize; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(at(after, x, y, c), at(before, x + 2, y, c)) << x << "," << y;
  // The two right columns see past the card's edge: rejected, so their tiles (the right column
  // of tiles) are the ones scored, first in the schedule.
  const std::vector<uint32_t> order = read_schedule(renderer);
  for (uint32_t i = 0; i < kSize / kTile; ++i)
    EXPECT_EQ(order[i] % (kSize / kTile), kSize / kTile - 1) << i;
}

// A silhouette's pixels mix, by their footprint, the card in front and the black behind it; after
// a move the mix moves with the card, whatever the pixel's own surface did. The lit card covers
// x < 32.3 pixels, so pixel 32 is three tenths card but sees the background through its centre;
// a pan of two pixels carries the card to x < 30.3.
TEST(Reproject, ASilhouetteMovesWithTheSurfaceInFront) {
  const float edge = 32.3f / kSize * 2.0f - 1.0f;  // in card units: the frame spans [-1, 1]
  Scene scene = lit_card(glm::translate(glm::mat4(1.0f), {(edge - 1.0f) / 2.0f, 0.0f, 0.0f}) *
                         glm::scale(glm::mat4(1.0f), glm::vec3((edge + 1.0f) / 2.0f, 1.0f, 1.0f)));
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 8);
  renderer.add_samples_full_frame(4);
  renderer.resolve_display_all(DisplayRule::Immediate);
  const ImageRGB before = scheduler.displayed_image();
  ASSERT_GT(at(before, 32, 20, 0), 0.0f) << "the old edge pixel mixes in some card";
  ASSERT_LT(at(before, 32, 20, 0), 0.5f * at(before, 31, 20, 0)) << "mostly black";
  const Scene old = scene;
  apply_edit(scene, CameraEdit{glm::vec3(2.0f * 2.0f / kSize, 0.0f, 0.0f), std::nullopt});
  scheduler.on_edit(scene, diff_scenes(old, scene));
  const ImageRGB after = scheduler.displayed_image();
  // Every pixel shows the old one two to its right: the card, its edge pixels (the mix at x = 30
  // sees the background, as x = 32 did), and the black beyond, but for x = 31, which the card
  // uncovered and nothing old shows. The background does not move (it is reprojected by
  // direction), so only the edge's mix is carried by the card's motion.
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x + 2 < kSize; ++x) {
      if (x == 31) continue;
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(at(after, x, y, c), at(before, x + 2, y, c)) << x << "," << y;
    }
}

// Beside an emitter a mix read a fraction of a pixel off is far off: an emitting card in front of
// the lit card (its edge three tenths into a pixel column, as above) moves two pixels with a
// pan, and no pixel that sees the lit card shows the emitter's light carried over, where the
// silhouette rule would carry the mixes of its edge.
TEST(Reproject, AnEmittersEdgeIsNeverCarriedOntoWhatLiesBehind) {
  const float edge = 32.3f / kSize * 2.0f - 1.0f;
  Scene scene = lit_card();
  MaterialParameters glow = test::black_material();
  glow.emission_color = glm::vec3(1.0f);
  glow.emission_luminance = 20.0f;
  // Just in front of the lit card: both move by about the same two pixels.
  test::add_card(scene, "glow",
                 glm::translate(glm::mat4(1.0f), {(edge - 1.0f) / 2.0f, 0.0f, 0.01f}) *
                     glm::scale(glm::mat4(1.0f), glm::vec3((edge + 1.0f) / 2.0f, 1.0f, 1.0f)),
                 glow);
  // Lights picked by power: the glowing card lies against the lit one, which it lights only at
  // grazing angles; the light tree cannot bound that from the card's box (the point is inside
  // it), sends most shadow rays there and leaves the lamp's light noisy at 4 spp, while this
  // test needs the lit card's pixels far below the glowing edge's.
  RenderSettings power = settings();
  power.light_selection = LightSelection::Power;
  Renderer renderer(test::context(), scene, power);
  Scheduler scheduler(renderer, Policy::Hipr, 8);
  renderer.add_samples_full_frame(4);
  renderer.resolve_display_all(DisplayRule::Immediate);
  const ImageRGB before = scheduler.displayed_image();
  float lit = 0.0f;  // the brightest pixel of the lit card away from the emitter
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 36; x < kSize; ++x) lit = std::max(lit, at(before, x, y, 0));
  ASSERT_GT(at(before, 32, 20, 0), 4.0f * lit) << "the old edge pixel mixes in much light";
  const Scene old = scene;
  apply_edit(scene, CameraEdit{glm::vec3(2.0f * 2.0f / kSize, 0.0f, 0.0f), std::nullopt});
  scheduler.on_edit(scene, diff_scenes(old, scene));
  const ImageRGB after = scheduler.displayed_image();
  // x = 30 now mixes as x = 32 did, but its centre sees the lit card: it is kept at the lit
  // card's value (too dark, which is bounded) until it is rendered.
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 30; x < kSize; ++x)
      ASSERT_LE(at(after, x, y, 0), 1.5f * lit) << x << "," << y;
}

// A smooth mirror filling the frame, reflecting a bright panel behind the camera over half of
// it: the reflection's edge moves on screen otherwise than the mirror's surface does.
Scene mirror_card() {
  Scene scene = test::make_card_camera_scene(0.0f);
  MaterialParameters mirror = default_material_params();
  mirror.base_color = glm::vec3(0.9f);
  mirror.base_metalness = 1.0f;
  mirror.specular_roughness = 0.0f;
  test::add_card(scene, "mirror", glm::mat4(1.0f), mirror);
  MaterialParameters glow = test::black_material();
  glow.emission_color = glm::vec3(1.0f);
  glow.emission_luminance = 2.0f;
  glm::mat4 panel = glm::translate(glm::mat4(1.0f), {2.0f, 0.0f, 5.0f});
  panel = glm::rotate(panel, glm::radians(180.0f), glm::vec3(0, 1, 0));  // facing the mirror
  test::add_card(scene, "panel", glm::scale(panel, glm::vec3(2.0f, 4.0f, 1.0f)), glow);
  return scene;
}

TEST(Reproject, AReflectionThatMovedGivesWayToItsFreshSamples) {
  Scene scene = mirror_card();
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, kSize * kSize / (kTile * kTile));
  scheduler.set_display_rule(DisplayRule::Blend);
  renderer.add_samples_full_frame(16);
  const Scene old = scene;
  apply_edit(scene, CameraEdit{glm::vec3(0.25f, 0.0f, 0.0f), std::nullopt});  // 8 pixels right
  scheduler.on_edit(scene, diff_scenes(old, scene));
  const ImageRGB stale = scheduler.displayed_image();
  Renderer full(test::context(), scene, settings());
  full.add_samples_full_frame(16);
  full.resolve_display_all(DisplayRule::Immediate);
  const ImageRGB truth = full.displayed_image();
  run_to_convergence(scheduler, 4);  // a quarter of the samples the reprojected values have
  const ImageRGB shown = scheduler.displayed_image();
  // Where the reprojected reflection is wrong (the panel's edge moved 3/8 as far as the mirror):
  double stale_error = 0.0, shown_error = 0.0;
  size_t wrong = 0;
  for (size_t i = 0; i < truth.rgb.size(); ++i) {
    if (std::abs(stale.rgb[i] - truth.rgb[i]) < 0.5f) continue;
    ++wrong;
    stale_error += std::abs(stale.rgb[i] - truth.rgb[i]);
    shown_error += std::abs(shown.rgb[i] - truth.rgb[i]);
  }
  ASSERT_GT(wrong, size_t(3 * kSize)) << "the reflection's edge moved across a few columns";
  EXPECT_LT(shown_error, 0.2 * stale_error) << "the fresh samples took over where they disagree";
}

// HiPR's schedule after `scene`, converged at 4 spp, is seen from `dx` further right.
std::vector<uint32_t> schedule_after_pan(Scene scene, float dx) {
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 8);
  renderer.add_samples_full_frame(4);
  renderer.resolve_display_all(DisplayRule::Immediate);
  const Scene old = scene;
  apply_edit(scene, CameraEdit{glm::vec3(dx, 0.0f, 0.0f), std::nullopt});
  scheduler.on_edit(scene, diff_scenes(old, scene));
  return read_schedule(renderer);
}

// Where each tile of `tiles` stands in the schedule.
std::vector<size_t> positions(const std::vector<uint32_t>& order,
                              const std::vector<uint32_t>& tiles) {
  std::vector<size_t> at;
  for (uint32_t tile : tiles)
    at.push_back(size_t(std::find(order.begin(), order.end(), tile) - order.begin()));
  return at;
}

// The tiles of columns [first, last] of tiles.
std::vector<uint32_t> tile_columns(uint32_t first, uint32_t last) {
  std::vector<uint32_t> tiles;
  for (uint32_t y = 0; y < kSize / kTile; ++y)
    for (uint32_t x = first; x <= last; ++x) tiles.push_back(y * (kSize / kTile) + x);
  return tiles;
}

// A reflection kept from another view is wrong wherever the mirror is: after a camera move the
// tiles of view-dependent surfaces rank with the rejected ones, before the diffuse rest.
TEST(Reproject, ViewDependentSurfacesRankWithTheRejectedOnes) {
  Scene scene = test::make_card_camera_scene(0.5f);
  MaterialParameters mirror = default_material_params();
  mirror.base_metalness = 1.0f;
  mirror.specular_roughness = 0.05f;
  MaterialParameters matte = default_material_params();
  matte.specular_weight = 0.0f;
  ASSERT_TRUE(material_is_view_dependent(mirror));
  ASSERT_FALSE(material_is_view_dependent(matte));
  // The mirror on the left half of the view, the matte card on the right half.
  const glm::mat4 half = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 1.0f, 1.0f));
  test::add_card(scene, "mirror", glm::translate(glm::mat4(1.0f), {-0.5f, 0.0f, 0.0f}) * half,
                 mirror);
  test::add_card(scene, "matte", glm::translate(glm::mat4(1.0f), {0.5f, 0.0f, 0.0f}) * half, matte);
  const std::vector<uint32_t> order = schedule_after_pan(scene, 2.0f * 2.0f / kSize);  // two pixels
  // The mirror covers tile columns 0-3 (it moved two pixels left; column 3 also shows matte),
  // the right column saw past the cards' edge (rejected); columns 4-6 are matte and kept.
  const std::vector<size_t> mirror_at = positions(order, tile_columns(0, 2));
  const std::vector<size_t> matte_at = positions(order, tile_columns(5, 6));
  EXPECT_LT(*std::max_element(mirror_at.begin(), mirror_at.end()),
            *std::min_element(matte_at.begin(), matte_at.end()))
      << "every mirror tile before every kept matte tile";
  for (uint32_t tile : tile_columns(kSize / kTile - 1, kSize / kTile - 1))
    EXPECT_LT(positions(order, {tile})[0], 5u * (kSize / kTile))
        << "rejected tile " << tile << " among the first";
}

// The per-object "barely moved" rule: a surface whose pixels moved less than a quarter pixel
// shows nearly its own value already, so its tiles are rendered after every other.
TEST(Reproject, TilesThatBarelyMovedComeLast) {
  Scene scene = test::make_card_camera_scene(0.5f);
  MaterialParameters matte = default_material_params();
  matte.specular_weight = 0.0f;
  // A far card filling the view (z = 0, 3 from the camera) and a near one (z = 1.5, half as far)
  // over the left half of the view, taller than it: a sideways move shifts it twice as far.
  test::add_card(scene, "far", glm::mat4(1.0f), matte);
  test::add_card(scene, "near",
                 glm::translate(glm::mat4(1.0f), {-0.5f, 0.0f, 1.5f}) *
                     glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 1.0f, 1.0f)),
                 matte);
  // 32 pixels per unit at the far card: 0.005 moves it 0.16 pixels, the near card 0.32.
  const std::vector<uint32_t> order = schedule_after_pan(scene, 0.005f);
  // Columns 0-2: the near card, moved; 5-6: the far card, still (columns 3-4 hold the near card's
  // edge and 7 the frame's, where pixels are rejected: they rank first).
  const std::vector<size_t> moved_at = positions(order, tile_columns(0, 2));
  const std::vector<size_t> still_at = positions(order, tile_columns(5, 6));
  EXPECT_LT(*std::max_element(moved_at.begin(), moved_at.end()),
            *std::min_element(still_at.begin(), still_at.end()))
      << "the far card's tiles last, though they lie nearer the rejected columns";
  EXPECT_EQ(*std::max_element(still_at.begin(), still_at.end()), order.size() - 1);
}

TEST(Reproject, AnOrbitEndsOnTheFullFrameImageOfTheNewView) {
  for (const DisplayRule rule :
       {DisplayRule::Blend, DisplayRule::Difference, DisplayRule::Switch}) {
    Scene scene = load_scene(test::asset("cornell_box.gltf"));
    Renderer renderer(test::context(), scene, settings());
    Scheduler scheduler(renderer, Policy::Hipr, 5);
    scheduler.set_display_rule(rule);
    renderer.add_samples_full_frame(3);
    const Scene old = scene;
    // Two degrees about the box's vertical axis through its centre.
    const int node = scene.camera_node();
    ASSERT_GE(node, 0);
    ASSERT_LT(scene.nodes[size_t(node)].parent, 0)
        << "the camera's local transform is its world transform";
    const glm::mat4 world = scene.nodes[size_t(node)].local;
    const glm::vec3 centre(0.28f, 0.27f, 0.28f);
    const glm::mat4 orbit = glm::translate(glm::mat4(1.0f), centre) *
                            glm::rotate(glm::mat4(1.0f), glm::radians(2.0f), glm::vec3(0, 1, 0)) *
                            glm::translate(glm::mat4(1.0f), -centre);
    apply_edit(scene, CameraEdit{std::nullopt, orbit * world});
    ASSERT_TRUE(diff_scenes(old, scene).camera_only());
    scheduler.on_edit(scene, diff_scenes(old, scene));
    run_to_convergence(scheduler, 3);
    Renderer full(test::context(), scene, settings());
    full.add_samples_full_frame(3);
    full.resolve_display_all(DisplayRule::Immediate);
    EXPECT_EQ(scheduler.displayed_image().rgb, full.displayed_image().rgb);
  }
}

}  // namespace
}  // namespace hipr
