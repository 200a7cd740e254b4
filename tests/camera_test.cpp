// Cameras: choosing one (--camera, a camera edit's "use"), and the thin lens (depth of field):
// every schedule ends bit-identical on the full-frame render of the edited scene, the lens
// blurs what is off the focus plane and keeps that plane sharp.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "bench/oracle_policy.h"
#include "core/error.h"
#include "hipr/edits.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "scene/default_camera.h"
#include "test_support.h"

namespace hipr {
namespace {

RenderSettings settings() { return test::render_settings(40, 40, 8, 6, 11); }

// The Cornell box with a second camera, "side", looking at the blocks from the left.
Scene two_camera_box() {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Camera side = resolve_camera(scene);
  side.name = "side lens";
  scene.cameras.push_back(side);
  Node node;
  node.name = "side";
  node.camera = int(scene.cameras.size() - 1);
  const glm::vec3 eye(-0.2f, 0.35f, 0.9f), target(0.28f, 0.15f, 0.28f);
  node.local = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
  scene.nodes.push_back(node);
  scene.children.emplace_back();
  scene.root_nodes.push_back(uint32_t(scene.nodes.size() - 1));
  return scene;
}

TEST(Cameras, FoundByIndexOrNameAndListedInSceneOrder) {
  const Scene scene = two_camera_box();
  const std::vector<uint32_t> cameras = scene.camera_nodes();
  ASSERT_EQ(cameras.size(), 2u);
  EXPECT_EQ(find_camera_node(scene, "1"), cameras[1]);
  EXPECT_EQ(find_camera_node(scene, "side"), cameras[1]);
  EXPECT_EQ(find_camera_node(scene, "side lens"), cameras[1]) << "the glTF camera's name too";
  EXPECT_EQ(scene.camera_node(), int(cameras[0])) << "the first unless one is chosen";
  try {
    find_camera_node(scene, "7");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("side"), std::string::npos) << "lists the cameras";
  }
}

// Switch to the other camera, open its lens, move it with the lens open, close it, switch back:
// under hipr (which reprojects pinhole switches) and a full restart alike, each edit ends on
// exactly the full-frame render of the edited scene.
TEST(Cameras, SwitchingAndLensEditsConvergeBitForBit) {
  const uint32_t spp = 3;
  for (const auto& [policy, display] : {std::pair{Policy::Hipr, DisplayRule::Difference},
                                        std::pair{Policy::Hipr, DisplayRule::Blend},
                                        std::pair{Policy::Full, DisplayRule::Immediate}}) {
    Scene scene = two_camera_box();
    Renderer renderer(test::context(), scene, settings());
    ImageRGB unused;
    Scheduler scheduler(renderer, bench::make_bench_policy(policy, unused), 7);
    scheduler.set_display_rule(display);
    renderer.add_samples_full_frame(spp);
    std::vector<Edit> edits;
    CameraEdit use_side;
    use_side.use = "side";
    edits.push_back(use_side);
    CameraEdit lens;
    lens.aperture_radius = 0.03f;
    lens.focus_distance = 0.6f;
    edits.push_back(lens);
    edits.push_back(CameraEdit{glm::vec3(0.05f, 0.0f, 0.0f), std::nullopt});
    CameraEdit focus;
    focus.focus_distance = 1.0f;
    edits.push_back(focus);
    CameraEdit pinhole;
    pinhole.aperture_radius = 0.0f;
    edits.push_back(pinhole);
    CameraEdit use_first;
    use_first.use = "0";
    use_first.use = "#" + std::to_string(scene.camera_nodes()[0]);
    edits.push_back(use_first);
    for (const Edit& edit : edits) {
      const Scene before = scene;
      apply_edit(scene, edit);
      const ChangeSet changes = diff_scenes(before, scene);
      EXPECT_TRUE(changes.camera) << describe(edit);
      scheduler.on_edit(scene, changes);
      for (int s = 0; s < 10000 && scheduler.work_since_edit() < double(spp); ++s) scheduler.step();
      EXPECT_EQ(scheduler.displayed_image().rgb,
                test::full_frame_display(scene, settings(), spp).rgb)
          << policy_name(policy) << " " << describe(edit);
    }
  }
}

TEST(Cameras, AnEditUsingANodeWithoutACameraIsRefused) {
  Scene scene = two_camera_box();
  CameraEdit edit;
  edit.use = "tall_block";
  EXPECT_THROW(apply_edit(scene, edit), InputError);
  edit.use = "teapot";
  EXPECT_THROW(apply_edit(scene, edit), InputError);
  CameraEdit bad;
  bad.aperture_radius = -1.0f;
  EXPECT_THROW(apply_edit(scene, bad), InputError);
  bad.aperture_radius.reset();
  bad.focus_distance = 0.0f;
  EXPECT_THROW(apply_edit(scene, bad), InputError);
}

// Undo of each camera edit puts back what it changed (the camera used, the lens); a switch
// goes alone, so that its undo is a switch back.
TEST(Cameras, InverseEditsRestoreTheView) {
  Scene scene = two_camera_box();
  const Camera start = resolve_camera(scene);
  CameraEdit both;
  both.use = "side";
  both.aperture_radius = 0.02f;
  EXPECT_THROW(apply_edit(scene, both), InputError);
  CameraEdit use;
  use.use = "side";
  const Edit back = inverse_edit(scene, use);
  apply_edit(scene, use);
  EXPECT_NE(resolve_camera(scene).camera_to_world, start.camera_to_world);
  CameraEdit lens;
  lens.aperture_radius = 0.02f;
  lens.focus_distance = 0.5f;
  const Edit closed = inverse_edit(scene, lens);
  apply_edit(scene, lens);
  EXPECT_EQ(resolve_camera(scene).aperture_radius, 0.02f);
  apply_edit(scene, closed);
  EXPECT_EQ(resolve_camera(scene).aperture_radius, 0.0f);
  EXPECT_EQ(resolve_camera(scene).focus_distance, start.focus_distance);
  apply_edit(scene, back);
  EXPECT_EQ(resolve_camera(scene).camera_to_world, start.camera_to_world);
}

// The lens focused on the back wall: the wall stays as sharp as through the pinhole, and the
// edges of the blocks in front of it blur (their image loses contrast across the edge).
TEST(ThinLens, BlursWhatIsOffTheFocusPlane) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  RenderSettings s = test::render_settings(64, 64, 16, 4, 3);
  const uint32_t spp = 64;
  const ImageRGB pinhole = test::render_finite(scene, s, spp);
  // A zero radius is the pinhole, bit for bit.
  CameraEdit closed;
  closed.aperture_radius = 0.0f;
  closed.focus_distance = 3.0f;
  Scene same = scene;
  apply_edit(same, closed);
  EXPECT_EQ(test::render_finite(same, s, spp).rgb, pinhole.rgb);

  // The back wall's depth from the centre pixel's ray: eye to wall along the view axis.
  Renderer probe(test::context(), scene, s);
  probe.add_samples_full_frame(1);
  const float wall = probe.gbuffer_at(44, 16).depth;
  ASSERT_GT(wall, 0.0f);
  CameraEdit lens;
  lens.aperture_radius = 0.1f;
  lens.focus_distance = wall;
  apply_edit(scene, lens);
  const ImageRGB blurred = test::render_finite(scene, s, spp);
  // What the lens changes, in 4x4 block means (noise averages out, blur does not): far more
  // in the lower half (the blocks' silhouettes, nearer than the wall) than on the wall's band.
  const auto change = [&](uint32_t y0, uint32_t y1, uint32_t x0, uint32_t x1) {
    double sum = 0.0;
    int blocks = 0;
    for (uint32_t by = y0; by < y1; by += 4)
      for (uint32_t bx = x0; bx < x1; bx += 4, ++blocks)
        for (int c = 0; c < 3; ++c) {
          double a = 0.0, b = 0.0;
          for (uint32_t y = by; y < by + 4; ++y)
            for (uint32_t x = bx; x < bx + 4; ++x) {
              a += pinhole.rgb[(size_t(y) * 64 + x) * 3 + c];
              b += blurred.rgb[(size_t(y) * 64 + x) * 3 + c];
            }
          sum += std::abs(a - b) / 16.0;
        }
    return sum / blocks;
  };
  // On focus: the back wall right of the tall block, below the ceiling, above the short block.
  const double on_focus = change(12, 24, 36, 52), off_focus = change(36, 60, 4, 60);
  EXPECT_GT(off_focus, 2.0 * on_focus) << on_focus << " on the wall, " << off_focus << " below";
}

}  // namespace
}  // namespace hipr
