// The viewer's window-free parts: undo/redo history, camera controller, view layout, overlays,
// the edit path of a session (headless GPU) and the display pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>

#include "app/viewer/camera_controller.h"
#include "app/viewer/edit_history.h"
#include "app/viewer/overlays.h"
#include "app/viewer/scene_edits.h"
#include "app/viewer/session.h"
#include "app/viewer/view_layout.h"
#include "app/viewer/viewer_state.h"
#include "core/error.h"
#include "hipr/hipr_stages.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "image/auto_exposure.h"
#include "image/debug_images.h"
#include "image/tonemap.h"
#include "render/display_pass.h"
#include "render/light_tables.h"
#include "render/render_readback.h"
#include "shaders/shared/bindings/exposure.h"
#include "test_support.h"
#include "vk/context.h"

namespace hipr::viewer {
namespace {

Scene cornell() { return load_scene(test::asset("cornell_box.gltf")); }

size_t node_index(const Scene& scene, const std::string& name) {
  for (size_t n = 0; n < scene.nodes.size(); ++n)
    if (scene.nodes[n].name == name) return n;
  return SIZE_MAX;
}

uint32_t instance_of(const Scene& scene, const std::string& name) {
  const auto instances = scene.instances();
  for (uint32_t i = 0; i < instances.size(); ++i)
    if (scene.nodes[instances[i].node].name == name) return i;
  return UINT32_MAX;
}

bool same_material(const Scene& a, const Scene& b, size_t m) {
  return std::memcmp(&a.materials[m].params, &b.materials[m].params, sizeof(MaterialParameters)) ==
         0;
}

// ---- EditHistory (no GPU)

TEST(EditHistory, UndoAndRedoRestoreEachStateExactly) {
  const Scene original = cornell();
  Scene scene = original;
  EditHistory history;
  history.apply(scene, TransformEdit{"tall_block", glm::vec3(0.1f, 0.0f, -0.05f), std::nullopt});
  history.apply(scene, MaterialEdit{"red", {{"base_color", {0.1f, 0.2f, 0.7f}}}});
  const Scene edited = scene;
  EXPECT_EQ(history.undo_count(), 2u);
  EXPECT_EQ(history.undo_label(), "material red");

  ASSERT_TRUE(history.undo(scene));
  EXPECT_TRUE(same_material(scene, original, 1));
  EXPECT_EQ(history.redo_label(), "material red");
  ASSERT_TRUE(history.undo(scene));
  EXPECT_TRUE(diff_scenes(original, scene).empty());
  EXPECT_FALSE(history.undo(scene)) << "nothing left to undo";

  ASSERT_TRUE(history.redo(scene));
  ASSERT_TRUE(history.redo(scene));
  EXPECT_FALSE(history.redo(scene));
  EXPECT_TRUE(diff_scenes(edited, scene).empty());
  EXPECT_EQ(scene.nodes[node_index(scene, "tall_block")].local,
            edited.nodes[node_index(edited, "tall_block")].local);
}

TEST(EditHistory, AGroupIsOneStepAndANewEditDropsTheRedoList) {
  const Scene original = cornell();
  Scene scene = original;
  EditHistory history;
  history.begin_group();  // a drag: many small moves
  for (int i = 1; i <= 20; ++i) {
    glm::mat4 local = original.nodes[node_index(original, "short_block")].local;
    local[3].x += 0.01f * float(i);
    history.apply(scene, TransformEdit{"short_block", std::nullopt, local});
  }
  history.end_group();
  history.apply(scene, VisibilityEdit{"tall_block", false});
  EXPECT_EQ(history.undo_count(), 2u);
  ASSERT_TRUE(history.undo(scene));
  ASSERT_TRUE(history.undo(scene));
  EXPECT_TRUE(diff_scenes(original, scene).empty()) << "one undo reverts the whole drag";
  EXPECT_EQ(history.redo_count(), 2u);
  history.apply(scene, CameraEdit{glm::vec3(0.0f, 0.0f, -0.1f), std::nullopt});
  EXPECT_FALSE(history.can_redo()) << "a new edit forks the history";
}

TEST(EditHistory, ARefusedEditChangesNothingAndRecordsNothing) {
  const Scene original = cornell();
  Scene scene = original;
  EditHistory history;
  // The second key is unknown: the first must not be applied half-way.
  EXPECT_THROW(
      history.apply(scene,
                    MaterialEdit{"red", {{"base_color", {0.0f, 0.0f, 1.0f}}, {"colour", {1.0f}}}}),
      InputError);
  EXPECT_THROW(history.apply(scene, TransformEdit{"teapot", glm::vec3(1.0f), std::nullopt}),
               InputError);
  EXPECT_TRUE(same_material(scene, original, 1));
  EXPECT_FALSE(history.can_undo());
}

TEST(EditHistory, UnsavedFollowsTheSavedState) {
  Scene scene = cornell();
  EditHistory history;
  EXPECT_FALSE(history.unsaved());
  history.apply(scene, VisibilityEdit{"tall_block", false});
  EXPECT_TRUE(history.unsaved());
  history.mark_saved();
  EXPECT_FALSE(history.unsaved());
  history.undo(scene);
  EXPECT_TRUE(history.unsaved());
  history.redo(scene);
  EXPECT_FALSE(history.unsaved()) << "redo returns to the saved state";
  // Growing the saved step (a drag that continues) makes it unsaved again.
  history.begin_group();
  history.apply(scene, VisibilityEdit{"short_block", false});
  history.mark_saved();
  history.apply(scene, VisibilityEdit{"short_block", true});
  history.end_group();
  EXPECT_TRUE(history.unsaved());
}

// ---- CameraController (no GPU)

TEST(CameraController, TakesOverARollFreeCameraWithoutAJump) {
  const glm::vec3 eye(1.0f, 2.0f, 5.0f), target(0.0f, 0.5f, 0.0f);
  const glm::mat4 camera = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
  CameraController controller;
  controller.reset(camera, glm::length(target - eye));
  const glm::mat4 back = controller.camera_to_world();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(back[c][r], camera[c][r], 1e-5f) << c << "," << r;
  EXPECT_NEAR(glm::length(controller.pivot() - target), 0.0f, 1e-5f);
}

TEST(CameraController, OrbitKeepsThePivotPanMovesItZoomApproaches) {
  const glm::mat4 camera =
      glm::inverse(glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0), glm::vec3(0, 1, 0)));
  CameraController controller;
  controller.reset(camera, 4.0f);
  controller.orbit(glm::vec2(50.0f, -30.0f), 512.0f);
  const glm::mat4 orbited = controller.camera_to_world();
  EXPECT_NEAR(glm::length(glm::vec3(orbited[3])), 4.0f, 1e-4f)
      << "the eye stays at the pivot distance";
  EXPECT_NEAR(glm::dot(-glm::vec3(orbited[2]), glm::normalize(-glm::vec3(orbited[3]))), 1.0f, 1e-5f)
      << "still looking at the pivot";
  EXPECT_GT(std::abs(orbited[3].x), 0.1f) << "a horizontal drag turns the view";
  EXPECT_NEAR(orbited[0].y, 0.0f, 1e-5f) << "no roll";

  // Panning by half the view's height moves the pivot by half the visible height at its depth.
  controller.reset(camera, 4.0f);
  const float tan_half = std::tan(glm::radians(20.0f));
  controller.pan(glm::vec2(0.0f, 256.0f), 512.0f, tan_half);
  EXPECT_NEAR(controller.pivot().y, 4.0f * tan_half, 1e-4f);
  EXPECT_NEAR(controller.pivot().x, 0.0f, 1e-5f);

  controller.zoom(2.0f);
  EXPECT_LT(controller.distance(), 4.0f);
  controller.zoom(-1000.0f);
  EXPECT_TRUE(std::isfinite(controller.distance()));
  controller.zoom(1000.0f);
  EXPECT_GT(controller.distance(), 0.0f) << "zoom never passes the pivot";
}

// ---- ViewLayout (no GPU)

TEST(ViewLayout, CentresAtIntegerZoomAndMapsBack) {
  const ViewLayout same = fit_view(128, 128, 128, 128);
  EXPECT_EQ(same.x, 0);
  EXPECT_EQ(same.y, 0);
  EXPECT_EQ(same.scale, 1.0f);
  EXPECT_EQ(*same.to_render({0.5f, 127.5f}), glm::uvec2(0, 127));
  EXPECT_FALSE(same.to_render({128.5f, 3.0f}).has_value());

  const ViewLayout tall = fit_view(256, 256, 300, 700);  // a crisp 1:1, centred
  EXPECT_EQ(tall.scale, 1.0f);
  EXPECT_EQ(tall.x, 22);
  EXPECT_EQ(tall.y, 222);
  EXPECT_FALSE(tall.to_render({10.0f, 300.0f}).has_value());
  EXPECT_EQ(*tall.to_render({22.0f, 222.0f}), glm::uvec2(0, 0));

  const ViewLayout big = fit_view(100, 50, 450, 300);  // integer zoom 4
  EXPECT_EQ(big.scale, 4.0f);
  EXPECT_EQ(*big.to_render({float(big.x) + 9.0f, float(big.y) + 5.0f}), glm::uvec2(2, 1));

  const ViewLayout small = fit_view(512, 512, 256, 400);  // shrinks to fit
  EXPECT_EQ(small.scale, 0.5f);
}

// ---- Overlays (no GPU)

TEST(Overlays, IdsAreTheDebugImageInDisplayBytes) {
  const std::vector<uint32_t> ids = {0, 1, UINT32_MAX, 7, 7, 3};
  const OverlayGrid grid{3, 2, 2, 2};
  const std::vector<uint32_t> overlay = id_overlay(ids, grid);
  const std::vector<uint8_t> expected = tonemap_srgb8(object_id_image(ids, 3, 2).rgb, 0.0f);
  ASSERT_EQ(overlay.size(), 6u);
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(overlay[i] & 0xff, expected[3 * i]);
    EXPECT_EQ((overlay[i] >> 8) & 0xff, expected[3 * i + 1]);
    EXPECT_EQ((overlay[i] >> 16) & 0xff, expected[3 * i + 2]);
    EXPECT_EQ(overlay[i] >> 24, 255u) << "ids cover the image";
  }
  EXPECT_EQ(overlay[3], overlay[4]) << "one flat colour per object";
  EXPECT_NE(overlay[0], overlay[1]);
}

TEST(Overlays, OwedTintsOnlyOwedTilesAndOutlinesFollowTheObject) {
  const OverlayGrid grid{4, 4, 2, 2};
  const std::vector<uint32_t> owed = owed_overlay({0, 3, 0, 0}, grid);  // tile 1: top right
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x)
      EXPECT_EQ(owed[y * 4 + x] != 0u, x >= 2 && y < 2) << x << "," << y;

  // A 3x3 object in a 4x4 image: its 8 border pixels are outlined, its centre is not.
  std::vector<uint32_t> ids(16, UINT32_MAX);
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 3; ++x) ids[y * 4 + x] = 5;
  std::vector<uint32_t> overlay(16, 0u);
  outline_instance(overlay, ids, 5, grid);
  size_t outlined = 0;
  for (uint32_t v : overlay) outlined += v != 0u;
  EXPECT_EQ(outlined, 8u);
  EXPECT_EQ(overlay[1 * 4 + 1], 0u);
  EXPECT_EQ(parse_overlay("weights"), Overlay::Weights);
  EXPECT_THROW(parse_overlay("normals"), InputError);
}

// ---- diff_snapshot (no GPU)

// The viewer diffs against a stripped copy of the scene: it must report exactly what a diff
// against the full scene reports, for every kind of edit.
TEST(DiffSnapshot, ReportsWhatAFullDiffReports) {
  Scene base = load_scene(test::asset("cornell_sphere.glb"));
  base.environment = test::uniform_environment(1.0f);
  const Edit edits[] = {
      TransformEdit{"sphere", glm::vec3(0.1f, 0.0f, 0.0f), std::nullopt},
      MaterialEdit{"light", {{"emission_luminance", {3.0f}}}},
      LightEdit{"lamp", 9.0f, std::nullopt, std::nullopt},
      VisibilityEdit{"tall_block", false},
      CameraEdit{glm::vec3(0.0f, 0.1f, 0.0f), std::nullopt},
      EnvironmentEdit{.intensity = 2.0f},
      EnvironmentEdit{.source = std::filesystem::path("studio")},
      EnvironmentEdit{.source = std::filesystem::path("sky"), .sun_elevation_degrees = 10.0f},
      EnvironmentEdit{.source = std::filesystem::path("none")},
  };
  for (const Edit& edit : edits) {
    Scene after = base;
    apply_edit(after, edit);
    const ChangeSet full = diff_scenes(base, after), lean = diff_scenes(diff_snapshot(base), after);
    EXPECT_EQ(lean.instances, full.instances) << describe(edit);
    EXPECT_EQ(lean.lights, full.lights) << describe(edit);
    EXPECT_EQ(lean.materials, full.materials) << describe(edit);
    EXPECT_EQ(lean.transforms, full.transforms) << describe(edit);
    EXPECT_EQ(lean.light_tables, full.light_tables) << describe(edit);
    EXPECT_EQ(lean.camera, full.camera) << describe(edit);
    EXPECT_EQ(lean.environment, full.environment) << describe(edit);
    EXPECT_EQ(lean.environment_map, full.environment_map) << describe(edit);
  }
  base.images.push_back(
      {"texels", 2, 2, std::vector<uint8_t>(16, 200)});  // the sphere scene has none
  const Scene snapshot = diff_snapshot(base);
  EXPECT_TRUE(snapshot.images.empty());
  EXPECT_TRUE(snapshot.environment->texels.empty());
}

// ---- follow_environment (no GPU)

// A switch to another map moves the exposure by the change of mean radiance (studio <-> sky is
// about 14 stops); the sun, the intensity and a detour through "none" leave it alone.
TEST(FollowEnvironment, ExposureFollowsASwitchOfMap) {
  Scene scene = load_scene(test::asset("furnace_sphere.gltf"), {.environment = "studio"});
  const float studio = environment_mean_luminance(*scene.environment);
  ViewerState state;
  state.exposure_ev = 1.0f;
  follow_environment(scene, state);
  EXPECT_EQ(state.exposure_ev, 1.0f) << "the first environment is taken as it is";
  apply_edit(scene, EnvironmentEdit{.source = std::filesystem::path("sky")});
  const float sky = environment_mean_luminance(*scene.environment);
  follow_environment(scene, state);
  EXPECT_NEAR(state.exposure_ev, 1.0f - std::log2(sky / studio), 1e-4f);
  EXPECT_LT(state.exposure_ev, -10.0f);
  const float at_noon = state.exposure_ev;
  apply_edit(scene, EnvironmentEdit{.sun_elevation_degrees = 5.0f, .intensity = 3.0f});
  follow_environment(scene, state);
  EXPECT_EQ(state.exposure_ev, at_noon);
  apply_edit(scene, EnvironmentEdit{.source = std::filesystem::path("none")});
  follow_environment(scene, state);
  EXPECT_EQ(state.exposure_ev, at_noon);
  // Back to the studio: the exposure it had (the sun moved within the same map).
  apply_edit(scene, EnvironmentEdit{.source = std::filesystem::path("studio")});
  follow_environment(scene, state);
  EXPECT_NEAR(state.exposure_ev, 1.0f, 1e-4f);
}

// With auto exposure on, the metering moves the exposure (the environment rule steps aside);
// small changes (a converging image's noise) do not; a hand-set exposure (auto off) stays.
TEST(FollowMetering, AutoExposureFollowsTheMeterUntilLocked) {
  Scene scene = load_scene(test::asset("furnace_sphere.gltf"), {.environment = "studio"});
  ViewerState state;
  state.auto_exposure = true;
  follow_environment(scene, state);
  follow_metering(state, 2.0f);
  EXPECT_EQ(state.exposure_ev, 2.0f);
  follow_metering(state, 2.0f + 0.5f * kMeteringDeadbandEv);
  EXPECT_EQ(state.exposure_ev, 2.0f) << "within the dead band: no pulsing";
  apply_edit(scene, EnvironmentEdit{.source = std::filesystem::path("sky")});
  follow_environment(scene, state);
  EXPECT_EQ(state.exposure_ev, 2.0f) << "the meter, not the map's mean, follows the light";
  follow_metering(state, -11.0f);
  EXPECT_EQ(state.exposure_ev, -11.0f);
  state.auto_exposure = false;  // what moving the slider does
  follow_metering(state, 3.0f);
  EXPECT_EQ(state.exposure_ev, -11.0f);
}

// ---- Session (headless GPU)

// The session's scheduling settings with one change (Session::set_schedule takes them whole).
template <typename Change>
void change_schedule(Session& session, Change change) {
  ScheduleSettings schedule = session.settings().schedule;
  change(schedule);
  session.set_schedule(schedule);
}

SessionSettings small_settings(Policy policy = Policy::Hipr) {
  SessionSettings s;
  s.render.width = 32;
  s.render.height = 32;
  s.render.tile_size = 8;
  s.render.max_depth = 4;
  s.schedule.policy = policy;
  s.schedule.tiles_per_step = 4;
  s.spp = 2;
  return s;
}

ImageRGB fresh_render(const Scene& scene, const SessionSettings& s) {
  Renderer renderer(test::context(), scene, s.render);
  renderer.add_samples_full_frame(s.spp);
  return renderer.image();
}

void converge(Session& session) {
  for (int i = 0; i < 10000 && !session.converged(); ++i) session.render(1e9, 1);
  ASSERT_TRUE(session.converged());
}

// The overlays the viewer shows are made on the GPU (overlay.comp) from the renderer's buffers;
// they are the CPU overlays of the same data (app/viewer/overlays.cpp, image/debug_images.cpp):
// the ids, owed tint and outline exactly, the weight heat map within a byte (log10 in float).
TEST(Session, GpuOverlaysAreTheCpuOverlaysOfTheSameData) {
  SessionSettings settings = small_settings();
  settings.render.width = 44;  // a column of tiles cut short by the image edge
  Session session(test::context(), cornell(), settings);
  converge(session);
  session.edit(TransformEdit{"tall_block", glm::vec3(0.1f, 0.0f, 0.0f), std::nullopt});
  session.render(1e9, 1);  // stage 2's weights, some tiles re-rendered, the rest owed
  const Renderer& renderer = session.renderer();
  const OverlayGrid grid{settings.render.width, settings.render.height, settings.render.tile_size,
                         renderer.tiles_x()};
  DisplayPass display(test::context(), grid.width, grid.height);
  const auto gpu_overlay = [&](DebugOverlay kind, uint32_t node) {
    session.render_overlay(kind, node, display.overlay_buffer());
    return display.overlay_buffer().download_all<uint32_t>();
  };
  const std::vector<uint32_t> ids = session.instance_ids();
  EXPECT_EQ(gpu_overlay(DebugOverlay::Ids, UINT32_MAX), id_overlay(ids, grid));
  EXPECT_EQ(gpu_overlay(DebugOverlay::OwedTiles, UINT32_MAX),
            owed_overlay(read_owed_tiles(renderer), grid));

  const std::vector<uint32_t> weights = gpu_overlay(DebugOverlay::TileWeights, UINT32_MAX);
  const std::vector<uint32_t> expected =
      weight_overlay(read_tile_weights(renderer), read_tile_flags(renderer), grid);
  ASSERT_EQ(weights.size(), expected.size());
  size_t coloured = 0;
  for (size_t i = 0; i < weights.size(); ++i) {
    for (uint32_t shift : {0u, 8u, 16u, 24u})
      ASSERT_LE(std::abs(int((weights[i] >> shift) & 0xff) - int((expected[i] >> shift) & 0xff)), 1)
          << i;
    coloured += (expected[i] & 0xffffffu) != 0u;
  }
  EXPECT_GT(coloured, 0u) << "a heat map of nothing would prove nothing";

  // The selected node's outline on top of no overlay.
  const Scene& scene = session.scene();
  uint32_t node = 0;
  while (scene.nodes[node].name != "tall_block") ++node;
  std::vector<uint32_t> outline(ids.size(), 0u);
  const auto instances = scene.instances();
  for (uint32_t i = 0; i < instances.size(); ++i)
    if (instances[i].node == node) outline_instance(outline, ids, i, grid);
  EXPECT_EQ(gpu_overlay(DebugOverlay::None, node), outline);
  EXPECT_GT(std::count_if(outline.begin(), outline.end(), [](uint32_t v) { return v != 0u; }), 8);
}

// Undo is a change like any other: it goes through on_edit, and the re-render ends exactly
// where a fresh render of the restored scene is (samples depend only on pixel, index, seed).
TEST(Session, UndoReRendersToTheOriginalImageBitForBit) {
  const SessionSettings s = small_settings();
  Session session(test::context(), cornell(), s);
  converge(session);
  const ImageRGB original = session.displayed();
  EXPECT_EQ(original.rgb, fresh_render(session.scene(), s).rgb);

  session.edit(MaterialEdit{"red", {{"base_color", {0.05f, 0.1f, 0.65f}}}});
  EXPECT_FALSE(session.converged()) << "the edit restarts the render";
  converge(session);
  EXPECT_NE(session.displayed().rgb, original.rgb);
  EXPECT_EQ(session.displayed().rgb, fresh_render(session.scene(), s).rgb);

  ASSERT_TRUE(session.undo());
  EXPECT_FALSE(session.converged()) << "undo restarts what it changed";
  converge(session);
  EXPECT_EQ(session.displayed().rgb, original.rgb);
  ASSERT_TRUE(session.redo());
  converge(session);
  EXPECT_EQ(session.displayed().rgb, fresh_render(session.scene(), s).rgb);
  EXPECT_EQ(session.edit_records().size(), 3u);
  EXPECT_EQ(session.edit_records()[1].what, "undo material red");
}

// A noise target pauses rendering long before --spp once the image is clean: at a round's end
// (every pixel the same samples), where the film's own estimate meets it, on the image a full
// frame render of those samples makes. An edit resumes; a stricter target resumes too.
TEST(Session, ANoiseTargetPausesAtAnImageThatClean) {
  SessionSettings s = small_settings();
  s.spp = 4096;
  s.converge.relmse = 0.01;
  Session session(test::context(), cornell(), s);
  converge(session);
  ASSERT_TRUE(session.noise());
  EXPECT_TRUE(session.noise()->within(0.01)) << session.noise()->relmse;
  const auto [fewest, most] = session.renderer().sample_count_range();
  EXPECT_EQ(fewest, most) << "paused between rounds";
  EXPECT_LT(most, 256u);
  EXPECT_GE(most, 2u);
  EXPECT_EQ(session.displayed().rgb, test::full_frame_display(session.scene(), s.render, most).rgb);

  session.edit(MaterialEdit{"red", {{"base_color", {0.05f, 0.1f, 0.65f}}}});
  EXPECT_FALSE(session.converged());
  EXPECT_FALSE(session.noise()) << "an estimate of the scene before";
  converge(session);
  EXPECT_TRUE(session.noise()->within(0.01));
  EXPECT_LT(session.work_since_edit(), 256.0);

  const double paused_at = session.work_since_edit();
  session.set_convergence(4096, ConvergenceTarget{0.0, 0.0025});
  EXPECT_FALSE(session.converged()) << "a stricter target resumes";
  converge(session);
  EXPECT_TRUE(session.noise()->within(0.0025));
  EXPECT_GT(session.work_since_edit(), 2.0 * paused_at) << "relMSE falls as 1/samples";
}

// The viewer's automatic exposure is metered on the device from a histogram (4 KB read back):
// the exposure the host meters from the whole display, within half a bin (1/32 of a stop).
TEST(Session, TheDevicesExposureMeterIsTheHostsMeterOfTheDisplay) {
  Session session(test::context(), cornell(), small_settings());
  session.render(1e9, 6);
  const float host = metered_exposure_ev(session.displayed().rgb);
  EXPECT_NEAR(session.metered_exposure(), host, 0.5f / float(abi::kMeterBinsPerStop) + 1e-5f);
  EXPECT_NE(host, 0.0f) << "a lit image";
  // Metered once per display version: an idle viewer submits nothing for it.
  const uint64_t submissions = vk::queue_submissions();
  EXPECT_EQ(session.metered_exposure(), session.metered_exposure());
  EXPECT_EQ(vk::queue_submissions(), submissions);
  session.render(1e9, 1);
  const uint64_t after_step = vk::queue_submissions();
  session.metered_exposure();
  EXPECT_GT(vk::queue_submissions(), after_step) << "a new display is metered again";
}

// A new renderer (light selection, guiding) gets the denoiser and the exposure meter the window
// had made on the old one at once, not inside its first frame (which then allocated them).
TEST(Session, ARebuiltRendererHasTheWindowsPassesBeforeItsFirstFrame) {
  Session session(test::context(), cornell(), small_settings());
  session.denoised_display();
  session.metered_exposure();
  const uint64_t before = session.renderer_id();
  session.set_light_selection(LightSelection::Power);
  ASSERT_NE(session.renderer_id(), before);
  EXPECT_TRUE(has_denoiser(session.renderer()));
  EXPECT_TRUE(has_exposure_meter(session.renderer()));
}

// The denoiser hides noise while the image converges; once a noise target of
// kRawIsCleanerRelmse or less is met the window shows the raw image, the full-frame render of its
// samples bit for bit, unless the target keeps it denoised. Met at a looser target, or paused at
// the sample limit, noise is left: it stays denoised.
TEST(Session, OnceTheImageIsCleanTheWindowShowsTheRawImage) {
  DenoiseSettings denoise;
  denoise.enabled = true;
  SessionSettings s = small_settings();
  s.spp = 4096;
  s.converge.relmse = 0.01;
  Session session(test::context(), cornell(), s);
  session.render(1e9, 4);
  EXPECT_TRUE(session.shows_denoised(denoise));
  EXPECT_NE(session.shown(denoise).rgb, session.displayed().rgb);
  converge(session);
  EXPECT_TRUE(session.shows_denoised(denoise)) << "a loose target leaves noise";

  ConvergenceTarget clean = s.converge;
  clean.relmse = kRawIsCleanerRelmse;
  session.set_convergence(s.spp, clean);
  converge(session);
  EXPECT_FALSE(session.shows_denoised(denoise));
  const uint32_t samples = session.renderer().sample_count_range().second;
  EXPECT_EQ(session.shown(denoise).rgb,
            test::full_frame_display(session.scene(), s.render, samples).rgb);

  ConvergenceTarget keep = clean;
  keep.keep_denoised = true;
  session.set_convergence(s.spp, keep);
  EXPECT_TRUE(session.converged()) << "no target changed: the met one stays met";
  EXPECT_TRUE(session.shows_denoised(denoise));
  EXPECT_NE(session.shown(denoise).rgb, session.displayed().rgb);

  session.set_convergence(s.spp, clean);
  session.edit(MaterialEdit{"red", {{"base_color", {0.05f, 0.1f, 0.65f}}}});
  EXPECT_TRUE(session.shows_denoised(denoise)) << "an edit is noisy again";

  SessionSettings limited = small_settings();
  limited.spp = 4;
  limited.converge.relmse = 1e-6;
  Session at_limit(test::context(), cornell(), limited);
  converge(at_limit);
  EXPECT_TRUE(at_limit.shows_denoised(denoise)) << "paused by --spp, not clean";
}

// A time target pauses at the first round's end after it has passed, never before every pixel
// shows the scene as it is now: an edit is never left half rendered.
TEST(Session, ATimeTargetWaitsForEveryPixelToShowTheScene) {
  SessionSettings s = small_settings();
  s.spp = 4096;
  s.converge.seconds = 1e-6;
  Session session(test::context(), cornell(), s);
  converge(session);
  EXPECT_EQ(session.scheduler().rounds_since_edit(), 1u);
  session.edit(TransformEdit{"tall_block", glm::vec3(0.1f, 0.0f, 0.0f), std::nullopt});
  EXPECT_FALSE(session.converged()) << "the time is up, the edit not yet shown everywhere";
  converge(session);
  EXPECT_EQ(session.scheduler().rounds_since_edit(), 1u);
  for (uint32_t owed : read_owed_tiles(session.renderer())) EXPECT_EQ(owed, 0u);
}

// The Environment panel's switch and sun sliders are session edits: re-rendered to the image of
// the new light, a slider drag is one undo step, and undo comes back to the studio bit for bit.
TEST(Session, EnvironmentSwitchAndSunDragUndo) {
  const SessionSettings s = small_settings();
  Session session(test::context(),
                  load_scene(test::asset("furnace_sphere.gltf"), {.environment = "studio"}), s);
  converge(session);
  const ImageRGB studio = session.displayed();
  session.edit(EnvironmentEdit{.source = std::filesystem::path("sky"), .intensity = 0.0005f});
  converge(session);
  const ImageRGB sky = session.displayed();
  EXPECT_NE(sky.rgb, studio.rgb);
  EXPECT_EQ(sky.rgb, fresh_render(session.scene(), s).rgb);
  session.begin_group();
  for (int i = 1; i <= 4; ++i) {
    session.edit(EnvironmentEdit{.sun_azimuth_degrees = 30.0f + 20.0f * float(i)});
    session.render(1e9, 1);
  }
  session.end_group();
  converge(session);
  EXPECT_EQ(session.scene().environment->sky.sun_azimuth_degrees, 110.0f);
  EXPECT_EQ(session.displayed().rgb, fresh_render(session.scene(), s).rgb);
  ASSERT_TRUE(session.undo());  // the whole drag
  converge(session);
  EXPECT_EQ(session.displayed().rgb, sky.rgb);
  ASSERT_TRUE(session.undo());
  converge(session);
  EXPECT_EQ(session.scene().environment->path, "studio");
  EXPECT_EQ(session.displayed().rgb, studio.rgb);
}

TEST(Session, ARefusedEditKeepsTheSceneAndItsRender) {
  Session session(test::context(), cornell(), small_settings());
  converge(session);
  const double work = session.work_since_edit();
  EXPECT_THROW(session.edit(TransformEdit{"teapot", glm::vec3(1.0f), std::nullopt}), InputError);
  EXPECT_FALSE(session.history().can_undo());
  EXPECT_TRUE(session.converged());
  EXPECT_EQ(session.work_since_edit(), work) << "no restart";
}

// With the immediate display rule, the first step after an edit (HiPR's stage 2 on the most
// changed active tiles) shows the edit, long before a whole frame's work; the latency of the
// change is recorded when that frame is presented. (Under the blend and switch rules a fresh
// estimate may wait until it is worth showing: the scheduler's choice, not the viewer's.)
TEST(Session, TheFirstStepShowsTheEditAndRecordsItsLatency) {
  SessionSettings settings = small_settings();
  settings.schedule.display = DisplayRule::Immediate;
  Session session(test::context(), cornell(), settings);
  converge(session);
  const ImageRGB before = session.displayed();
  session.edit(TransformEdit{"tall_block", glm::vec3(0.1f, 0.0f, 0.0f), std::nullopt});
  session.on_presented();  // the frame of the edit itself shows the old image
  EXPECT_LT(session.edit_records().back().latency_seconds, 0.0);
  session.render(1e9, 1);
  EXPECT_NE(session.displayed().rgb, before.rgb);
  session.on_presented();
  EXPECT_GE(session.edit_records().back().latency_seconds, 0.0);
  EXPECT_GT(session.edit_records().back().work_at_first_change, 0.0);
  EXPECT_LE(session.edit_records().back().work_at_first_change,
            0.25 * default_first_visit_spp(settings))
      << "one step: 4 of the 16 tiles at the first visit's spp";
}

// Picking reads the G-buffer of the scene as it is now, also under policies without stage 1.
TEST(Session, PickingFollowsAMovedObjectUnderEveryPolicy) {
  for (Policy policy : {Policy::Hipr, Policy::Scanline}) {
    Session session(test::context(), cornell(), small_settings(policy));
    const uint32_t block = instance_of(session.scene(), "tall_block");
    // Find a pixel of the tall block, then move the block out of it.
    const std::vector<uint32_t> ids = session.instance_ids();
    const auto at = std::find(ids.begin(), ids.end(), block);
    ASSERT_NE(at, ids.end());
    const uint32_t pixel = uint32_t(at - ids.begin());
    EXPECT_EQ(session.pick(pixel % 32, pixel / 32).instance, block);
    session.edit(TransformEdit{"tall_block", glm::vec3(0.0f, 5.0f, 0.0f), std::nullopt});
    EXPECT_NE(session.pick(pixel % 32, pixel / 32).instance, block) << policy_name(policy);
    EXPECT_EQ(std::count(session.instance_ids().begin(), session.instance_ids().end(), block), 0)
        << policy_name(policy);
  }
}

TEST(Session, ViewerSettingsKeepTheScene) {
  Session session(test::context(), cornell(), small_settings());
  session.edit(VisibilityEdit{"short_block", false});
  session.set_tile_size(4);
  EXPECT_EQ(session.renderer().tile_count(), 64u);
  EXPECT_FALSE(session.scene().nodes[node_index(session.scene(), "short_block")].visible);
  EXPECT_TRUE(session.history().can_undo());
  EXPECT_THROW(session.set_tile_size(0), InputError);
  EXPECT_EQ(session.settings().render.tile_size, 4u);
  change_schedule(session, [](ScheduleSettings& s) { s.policy = Policy::Full; });
  EXPECT_EQ(session.scheduler().policy(), Policy::Full);
  EXPECT_THROW(change_schedule(session, [](ScheduleSettings& s) { s.policy = Policy::Oracle; }),
               InputError)
      << "the oracle needs a reference render";
  EXPECT_EQ(session.scheduler().policy(), Policy::Full);
  EXPECT_EQ(session.settings().schedule.policy, Policy::Full)
      << "a refused policy leaves the settings alone";
  change_schedule(session, [](ScheduleSettings& s) { s.display = DisplayRule::Switch; });
  EXPECT_EQ(session.scheduler().display_rule(), DisplayRule::Switch);
  change_schedule(session, [](ScheduleSettings& s) { s.display.reset(); });
  EXPECT_EQ(session.scheduler().display_rule(), default_display_rule(Policy::Full));
  change_schedule(session, [](ScheduleSettings& s) { s.edit_lead = 2; });
  EXPECT_EQ(session.scheduler().edit_lead(), 2u);
  change_schedule(session, [](ScheduleSettings& s) { s.visit_spp = 2; });  // a new scheduler
  EXPECT_EQ(session.scheduler().edit_lead(), 2u) << "a new scheduler takes every setting";
  change_schedule(session, [](ScheduleSettings& s) { s.visit_spp = 1; });
  HiprParameters h;
  h.depth_epsilon = 0.05f;
  session.set_hipr_parameters(h);
  EXPECT_EQ(session.renderer().settings().hipr.depth_epsilon, 0.05f);
  session.set_sampler(Sampler::Random);
  EXPECT_EQ(session.renderer().settings().sampler, Sampler::Random);
  session.set_light_selection(LightSelection::Power);
  EXPECT_EQ(session.renderer().settings().light_selection, LightSelection::Power);
  session.set_guiding(true);
  EXPECT_TRUE(session.renderer().settings().guiding);
  EXPECT_FALSE(session.scene().nodes[node_index(session.scene(), "short_block")].visible);
  // Ends on the fresh render with the random sampler, lights picked by power and path guiding
  // (fresh_render takes the session's settings).
  converge(session);
  EXPECT_EQ(session.displayed().rgb, fresh_render(session.scene(), session.settings()).rgb);
}

// The selected object is the focus by default (docs/method.md#focus): the scheduler follows
// the view's seeds and a script's focus ops, a new focus restarts nothing and is not an undo
// step, and the render still ends on the full-frame image.
TEST(Session, FollowsTheSelectionAsItsFocus) {
  const SessionSettings s = small_settings();
  Session session(test::context(), cornell(), s);
  session.render(1e9, 3);  // part of the first pass, from nothing
  ViewerState state;
  state.selected_node = int(node_index(session.scene(), "tall_block"));
  session.set_view_focus(view_focus(session.scene(), state, std::nullopt));
  ASSERT_EQ(session.focus().seeds.size(), 1u);
  EXPECT_FALSE(session.focus().seeds[0].instances.empty());
  state.focus_cursor = true;
  state.focus_radius = 5.0f;
  session.set_view_focus(view_focus(session.scene(), state, glm::vec2(10.5f, 12.5f)));
  ASSERT_EQ(session.focus().seeds.size(), 2u);
  EXPECT_EQ(session.focus().seeds[1].pixel, glm::vec2(10.5f, 12.5f));
  state.focus_selection = false;
  EXPECT_EQ(view_focus(session.scene(), state, std::nullopt).seeds.size(), 0u);
  session.edit(FocusEdit{.node = "short_block"});  // a script's op: kept beside the view's seeds
  EXPECT_EQ(session.focus().seeds.size(), 3u);
  EXPECT_FALSE(session.history().can_undo()) << "a focus is not an edit of the scene";
  EXPECT_TRUE(session.edit_records().empty());
  converge(session);
  EXPECT_EQ(session.displayed().rgb, fresh_render(session.scene(), s).rgb);
  // A new policy keeps the focus and its lead; an edit re-renders with them and still ends exactly.
  change_schedule(session, [](ScheduleSettings& schedule) { schedule.focus_lead = 5; });
  change_schedule(session, [](ScheduleSettings& schedule) { schedule.policy = Policy::Full; });
  change_schedule(session, [](ScheduleSettings& schedule) { schedule.policy = Policy::Hipr; });
  EXPECT_EQ(session.focus().seeds.size(), 3u);
  EXPECT_EQ(session.scheduler().focus_lead(), 5u);
  session.edit(TransformEdit{"short_block", glm::vec3(0.04f, 0.0f, 0.0f), std::nullopt});
  converge(session);
  EXPECT_EQ(session.displayed().rgb, fresh_render(session.scene(), s).rgb);
}

// An edit beyond the scene's limits (a move to 3e38 m) is refused with one line, which the viewer
// shows: the scene, the picture and the undo history stay as they were, and undo still undoes
// the edit before it.
TEST(Session, AnEditBeyondTheLimitsLeavesTheSceneAndTheHistory) {
  Session session(test::context(), cornell(), small_settings());
  const Scene loaded = session.scene();
  session.edit(TransformEdit{"short_block", glm::vec3(0.04f, 0.0f, 0.0f), std::nullopt});
  const Scene moved = session.scene();
  const std::string label = session.history().undo_label();
  EXPECT_THROW(
      session.edit(TransformEdit{"short_block", glm::vec3(3e38f, 0.0f, 0.0f), std::nullopt}),
      InputError);
  EXPECT_TRUE(diff_scenes(moved, session.scene()).empty());
  EXPECT_EQ(session.history().undo_label(), label);
  ASSERT_TRUE(session.undo());
  EXPECT_TRUE(diff_scenes(loaded, session.scene()).empty());
}

// A scene without a camera gets one, so moving an object does not move the framing camera.
TEST(Session, ASceneWithoutACameraGetsItsDefaultCamera) {
  Session session(test::context(), test::make_furnace_scene(0.5f, glm::vec3(0.0f), 0.8f, 1.0f),
                  small_settings());
  ASSERT_GE(session.scene().camera_node(), 0);
  Scene before = session.scene();
  session.edit(TransformEdit{"#0", glm::vec3(0.3f, 0.0f, 0.0f), std::nullopt});
  EXPECT_FALSE(diff_scenes(before, session.scene()).camera);
}

// ---- Renderer methods the viewer added (headless GPU)

RenderSettings tiny(uint32_t size = 32) { return test::render_settings(size, size, 8, 4, 0); }

// Early compilation dispatches every kernel over no tile: nothing is rendered or reordered.
TEST(RendererForViewer, EarlyCompilationRendersNothing) {
  const Scene scene = cornell();
  RenderSettings early = tiny();
  early.compile_kernels_early = true;
  Renderer renderer(test::context(), scene, early);
  renderer.set_schedule(tile_order(Policy::Random, renderer.tiles_x(), renderer.tiles_y(), 7));
  const std::vector<uint32_t> schedule = read_schedule(renderer);
  hipr_stages(renderer);  // makes (and so compiles) stage 2's and stage 3's kernels
  EXPECT_EQ(renderer.counters().samples, 0u);
  EXPECT_EQ(renderer.counters().rays, 0u);
  for (float v : renderer.image().rgb) ASSERT_EQ(v, 0.0f);
  EXPECT_EQ(read_schedule(renderer), schedule);
  renderer.add_samples_full_frame(2);
  Renderer fresh(test::context(), scene, tiny());
  fresh.add_samples_full_frame(2);
  EXPECT_EQ(renderer.image().rgb, fresh.image().rgb);
}

TEST(RendererForViewer, OwedTilesCountPixelsStillOwingARestart) {
  Renderer renderer(test::context(), cornell(),
                    tiny(20));  // 3 x 3 tiles, the last row and column 4 px wide
  renderer.add_samples_full_frame(1);
  for (uint32_t owed : read_owed_tiles(renderer)) EXPECT_EQ(owed, 0u);
  renderer.mark_all_owed();
  const std::vector<uint32_t> owed = read_owed_tiles(renderer);
  ASSERT_EQ(owed.size(), 9u);
  EXPECT_EQ(owed[0], 64u);
  EXPECT_EQ(owed[2], 32u);
  EXPECT_EQ(owed[8], 16u);
  const uint32_t tile = 4;
  renderer.add_samples(std::span<const uint32_t>(&tile, 1), 1);
  EXPECT_EQ(read_owed_tiles(renderer)[4], 0u);
  EXPECT_EQ(read_owed_tiles(renderer)[3], 64u);
}

TEST(RendererForViewer, GBufferHitsAgreeWithTheInstanceImage) {
  Scene scene = cornell();
  Renderer renderer(test::context(), scene, tiny());
  hipr_stages(renderer).stage1_visibility({});
  const std::vector<uint32_t> ids = renderer.gbuffer_instances();
  for (uint32_t y = 0; y < 32; y += 5)
    for (uint32_t x = 0; x < 32; x += 3) {
      const Renderer::PixelHit hit = renderer.gbuffer_at(x, y);
      EXPECT_EQ(hit.instance, ids[y * 32 + x]);
      if (hit.instance != UINT32_MAX) {
        EXPECT_GT(hit.depth, 0.0f);
      }
    }
  EXPECT_EQ(renderer.gbuffer_at(32, 0).instance, UINT32_MAX) << "outside the image";
  // refresh_gbuffer follows an edit without touching the tile flags.
  const Scene before = scene;
  apply_edit(scene, VisibilityEdit{"tall_block", false});
  renderer.update_scene(scene, diff_scenes(before, scene));
  renderer.refresh_gbuffer();
  const uint32_t block = instance_of(scene, "tall_block");
  for (uint32_t id : renderer.gbuffer_instances()) EXPECT_NE(id, block);
  for (uint32_t flags : read_tile_flags(renderer)) EXPECT_EQ(flags, 0u);
}

TEST(RendererForViewer, HiprParametersSteerTheNextStage2) {
  const auto weights_after_move = [](const HiprParameters& h) {
    Scene scene = cornell();
    Renderer renderer(test::context(), scene, tiny());
    hipr_stages(renderer).stage1_visibility({});
    renderer.set_hipr_parameters(h);
    const Scene before = scene;
    apply_edit(scene, TransformEdit{"tall_block", glm::vec3(0.05f, 0.0f, 0.0f), std::nullopt});
    const ChangeSet changes = diff_scenes(before, scene);
    renderer.update_scene(scene, changes);
    renderer.mark_all_owed();
    hipr_stages(renderer).stage1_visibility(changes);
    test::discover_all(renderer, 1);
    EXPECT_EQ(renderer.settings().hipr.depth_epsilon, h.depth_epsilon);
    return read_tile_weights(renderer);
  };
  HiprParameters direct, caustic;
  direct.w_path[0] = 1.0f;
  direct.w_path[1] = direct.w_path[2] = 0.0f;
  caustic.w_path[2] = 1.0f;
  caustic.w_path[0] = caustic.w_path[1] = 0.0f;
  caustic.depth_epsilon = 0.02f;
  EXPECT_NE(weights_after_move(direct), weights_after_move(caustic));
}

// ---- DisplayPass (headless GPU)

TEST(DisplayPass, ToneMapsLikeTheCpuAndPlacesTheImage) {
  ImageRGB image{4, 2, {}};
  const float values[] = {0.0f, 0.002f, 0.01f, 0.2f, 0.5f, 0.99f, 1.5f, 40.0f};
  for (size_t i = 0; i < 8; ++i)
    image.rgb.insert(image.rgb.end(), {values[i], values[7 - i], 0.3f * values[i]});
  DisplayPass pass(test::context(), 4, 2);
  pass.set_image(image);
  DisplayView view;
  view.output_width = 4;
  view.output_height = 2;
  for (ToneMapper mapper : tone_mappers())
    for (float ev : {0.0f, -1.5f}) {
      view.exposure_ev = ev;
      view.tone_mapper = mapper;
      const std::vector<uint32_t> out = pass.run(view);
      const std::vector<uint8_t> expected = tonemap_srgb8(image.rgb, DisplayTransform{ev, mapper});
      ASSERT_EQ(out.size(), 8u);
      for (size_t i = 0; i < 8; ++i)
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(int((out[i] >> (8 * c)) & 0xff), int(expected[3 * i + size_t(c)]), 1)
              << i << " " << c << " ev " << ev << " " << tone_mapper_name(mapper);
    }

  // Scaled 2x at (1, 1) in a 10 x 6 window: nearest texels, background around.
  view = DisplayView{};
  view.output_width = 10;
  view.output_height = 6;
  view.x = 1;
  view.y = 1;
  view.scale = 2.0f;
  view.background = 0xff123456u;
  const std::vector<uint32_t> out = pass.run(view);
  const std::vector<uint32_t> one = [&] {
    DisplayView v;
    v.output_width = 4;
    v.output_height = 2;
    return pass.run(v);
  }();
  EXPECT_EQ(out[0], 0xff123456u);
  EXPECT_EQ(out[9], 0xff123456u);
  EXPECT_EQ(out[5 * 10 + 4], 0xff123456u);
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 8; ++x)
      EXPECT_EQ(out[(y + 1) * 10 + x + 1], one[(y / 2) * 4 + x / 2]) << x << "," << y;
}

TEST(DisplayPass, BlendsTheOverlayByItsCoverage) {
  ImageRGB image{2, 1, {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f}};
  DisplayPass pass(test::context(), 2, 1);
  pass.set_image(image);
  pass.set_overlay({pack_rgba8(1.0f, 0.5f, 0.0f, 1.0f), pack_rgba8(1.0f, 1.0f, 1.0f, 0.5f)});
  DisplayView view;
  view.output_width = 2;
  view.output_height = 1;
  view.overlay = true;
  const std::vector<uint32_t> out = pass.run(view);
  EXPECT_EQ(out[0], pack_rgba8(1.0f, 0.5f, 0.0f, 1.0f)) << "full coverage replaces the image";
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(int((out[1] >> (8 * c)) & 0xff), 128, 1) << "half coverage mixes";
  view.overlay = false;
  EXPECT_EQ(pass.run(view)[0], 0xff000000u) << "off: the image alone";
}

// ---- Dragging: a drag is many edits in a row

// Per tile of `size` pixels: the mean over its pixels and channels of |a - b| (b empty: |a|).
std::vector<double> tile_mean_abs(const ImageRGB& a, const ImageRGB* b, uint32_t size) {
  const uint32_t tiles_x = (a.width + size - 1) / size, tiles_y = (a.height + size - 1) / size;
  std::vector<double> sum(size_t(tiles_x) * tiles_y, 0.0), count(sum.size(), 0.0);
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) {
      const size_t t = size_t(y / size) * tiles_x + x / size, i = (size_t(y) * a.width + x) * 3;
      for (int c = 0; c < 3; ++c) sum[t] += std::abs(a.rgb[i + c] - (b ? b->rgb[i + c] : 0.0f));
      count[t] += 3.0;
    }
  for (size_t t = 0; t < sum.size(); ++t) sum[t] /= count[t];
  return sum;
}

// The drag of the viewer, scripted: 20 small moves of the tall block, one per frame, then a
// quarter of a full-frame pass of work. Of the tiles whose converged radiance the drag changed
// by more than half, at most a tenth may still look more like the scene before the drag than
// after it: the tiles the block left in earlier frames of the drag stay first in line. (Ranked
// as before, by the last two G-buffers alone, 20 of these 39 tiles were ghosts.)
TEST(Session, ADragLeavesNoGhostWhereTheObjectWas) {
  SessionSettings s;
  s.render = test::render_settings(128, 128, 8, 6, 0);
  s.spp = 16;
  Session session(test::context(), cornell(), s);
  for (int i = 0; i < 100 && !session.converged(); ++i) session.render(1e9, 1000);
  ASSERT_TRUE(session.converged());
  const Scene before = session.scene();
  // A frame's budget: 2 steps of 1/64 of the image (the viewer's share of a 30 ms frame at
  // 512x512 on lavapipe), so a drag outpaces the re-render as it does in the viewer.
  for (int i = 0; i < 20; ++i) {
    session.edit(TransformEdit{"tall_block", glm::vec3(0.009f, 0.0f, 0.0f), std::nullopt});
    session.render(1e9, 2);
  }
  session.render(1e9, 16);  // a quarter of a full-frame pass of work after the last move
  const ImageRGB shown = session.displayed();
  SessionSettings reference = s;
  reference.spp = 16;
  const ImageRGB pre = fresh_render(before, reference),
                 post = fresh_render(session.scene(), reference);
  const std::vector<double> change = tile_mean_abs(post, &pre, 8),
                            level = tile_mean_abs(pre, nullptr, 8);
  const std::vector<double> to_pre = tile_mean_abs(shown, &pre, 8),
                            to_post = tile_mean_abs(shown, &post, 8);
  size_t strong = 0, ghosts = 0;
  for (size_t t = 0; t < change.size(); ++t) {
    if (change[t] <= 0.5 * (level[t] + 1e-3)) continue;
    ++strong;
    if (to_pre[t] < to_post[t]) ++ghosts;
  }
  ASSERT_GT(strong, 10u);
  EXPECT_LE(double(ghosts), 0.1 * double(strong))
      << ghosts << " of " << strong << " strongly changed tiles";
}

// Ctrl+D, Delete and Import are session edits like any other: the copy becomes the selection,
// a delete clears it, each re-renders to the fresh image of the edited scene, and undoing all
// three comes back to the original image bit for bit.
TEST(Session, DuplicateDeleteAndImportReRenderAndUndo) {
  const SessionSettings s = small_settings();
  Session session(test::context(), cornell(), s);
  ViewerState state;
  converge(session);
  const ImageRGB original = session.displayed();

  state.selected_node = int(node_index(session.scene(), "short_block"));
  duplicate_selection(session, state);
  ASSERT_GE(state.selected_node, 0);
  EXPECT_EQ(session.scene().nodes[size_t(state.selected_node)].name, "short_block.1");
  converge(session);
  EXPECT_EQ(session.displayed().rgb, fresh_render(session.scene(), s).rgb);
  EXPECT_NE(session.displayed().rgb, original.rgb);

  state.selected_node = int(node_index(session.scene(), "tall_block"));
  delete_selection(session, state);
  EXPECT_EQ(state.selected_node, -1);
  ASSERT_TRUE(state.messages.empty()) << state.messages.back().text;
  converge(session);
  EXPECT_EQ(session.displayed().rgb, fresh_render(session.scene(), s).rgb);

  ASSERT_TRUE(
      try_edit(session, state,
               ImportEdit{test::asset("cornell_sphere.glb"), "", glm::vec3(0.0f, 0.1f, 0.0f)}));
  converge(session);
  EXPECT_EQ(session.displayed().rgb, fresh_render(session.scene(), s).rgb);
  EXPECT_FALSE(
      try_edit(session, state, ImportEdit{test::asset("missing.glb"), "", glm::vec3(0.0f)}));
  EXPECT_EQ(state.messages.size(), 1u) << "a bad file is a message, the scene unchanged";

  for (int i = 0; i < 3; ++i) ASSERT_TRUE(session.undo());
  converge(session);
  EXPECT_EQ(session.displayed().rgb, original.rgb);
  // The copy the undo took away is no selection.
  state.selected_node = int(session.scene().nodes.size()) + 3;
  EXPECT_FALSE(selected_node(session, state).has_value());
  EXPECT_EQ(state.selected_node, -1);
}

// Files dropped on the window: a scene opens (asking first when edits are unsaved), with Shift
// each is imported as an undoable edit; anything else is a message.
TEST(Session, DroppedFilesOpenOrImport) {
  Session session(test::context(), cornell(), small_settings());
  ViewerState state;
  const size_t nodes = session.scene().nodes.size();
  drop_files(session, state, {"/tmp/notes.txt"}, false);
  ASSERT_EQ(state.messages.size(), 1u);
  EXPECT_TRUE(state.messages.back().error);
  EXPECT_FALSE(state.request_open);

  const std::string sphere = test::asset("cornell_sphere.glb").string();
  drop_files(session, state, {sphere}, true);
  EXPECT_GT(session.scene().nodes.size(), nodes) << "imported";
  EXPECT_FALSE(state.request_open);
  EXPECT_TRUE(session.history().unsaved());

  const std::string box = test::asset("cornell_box.gltf").string();
  drop_files(session, state, {box, sphere}, false);
  EXPECT_TRUE(state.request_open);
  EXPECT_EQ(state.open_path, box) << "the first opens";
  EXPECT_FALSE(state.open_confirmed) << "the import is unsaved: asks first";
  ASSERT_TRUE(session.undo());
}

}  // namespace
}  // namespace hipr::viewer
