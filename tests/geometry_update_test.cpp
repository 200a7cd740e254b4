// Geometry edits on the GPU: after a duplicate, delete, import or deform (and their undo) the
// incremental update leaves the renderer exactly where a fresh upload of the edited scene would,
// every policy ends on exactly the full-frame image, stage 1 finds what left and what came, and
// records stay flat over many duplicate/delete cycles.
#include <gtest/gtest.h>

#include <functional>

#include <glm/gtc/matrix_transform.hpp>

#include "bench/oracle_policy.h"
#include "hipr/edit_pipeline.h"
#include "hipr/edits.h"
#include "hipr/hipr_stages.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scene_writer.h"
#include "hipr/scheduler.h"
#include "image/error_metrics.h"
#include "render/gpu_scene.h"
#include "render/render_readback.h"
#include "test_support.h"
#include "vk/buffer.h"

namespace hipr {
namespace {

RenderSettings settings() { return test::render_settings(32, 32, 16, 6, 4); }

// A renderer made for the scene, its samples checked (non-fatally) to be finite.
ImageRGB fresh_render(const Scene& scene, uint32_t spp) {
  return test::render_finite(scene, settings(), spp);
}

glm::mat4 stretch() { return glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 1.6f, 1.0f)); }
glm::mat4 mirror() { return glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)); }

struct OpCase {
  const char* name;
  std::vector<Edit> edits;  // applied one after another, each followed by an update
};

void PrintTo(const OpCase& c, std::ostream* out) { *out << c.name; }

std::vector<OpCase> op_cases() {
  const std::filesystem::path sphere = test::asset("cornell_sphere.glb");
  return {
      {"duplicate", {DuplicateEdit{"short_block", "copy", glm::vec3(-0.3f, 0.0f, 0.2f)}}},
      {"delete", {DeleteEdit{"tall_block"}}},
      {"delete_first_instance", {DeleteEdit{"floor"}}},
      {"import", {ImportEdit{sphere, "sphere", glm::vec3(0.1f, 0.1f, 0.0f)}}},
      {"deform", {DeformEdit{"tall_block", stretch(), nullptr}}},
      {"deform_mirrored", {DeformEdit{"tall_block", mirror(), nullptr}}},
      // A freed record range taken by a later instance of another size; an instance whose node
      // is gone and back.
      {"delete_then_duplicate",
       {DeleteEdit{"short_block"},
        DuplicateEdit{"tall_block", "copy", glm::vec3(0.2f, 0.0f, 0.0f)}}},
      {"import_delete_import",
       {ImportEdit{sphere, "a", {}}, DeleteEdit{"a"},
        ImportEdit{sphere, "b", glm::vec3(0.0f, 0.1f, 0.0f)}}},
  };
}

class GeometryUpdate : public ::testing::TestWithParam<OpCase> {};

// Render, edit, update, restart -> the same samples as a renderer made for the edited scene; and
// the undo, updated the same way, gives back the image before.
TEST_P(GeometryUpdate, MatchesAFreshUploadBitForBitAndUndoes) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  const ImageRGB original = fresh_render(scene, 2);
  Renderer renderer(test::context(), scene, settings());
  renderer.add_samples_full_frame(2);
  std::vector<Edit> undo;
  for (const Edit& edit : GetParam().edits) {
    undo.push_back(inverse_edit(scene, edit));
    test::expect_update_matches_fresh(renderer, scene, edit);
  }
  for (auto it = undo.rbegin(); it != undo.rend(); ++it)
    renderer.update_scene(scene, test::edit_scene(scene, *it));
  renderer.reset();
  renderer.add_samples_full_frame(2);
  EXPECT_EQ(renderer.image().rgb, original.rgb) << "undone";
}

INSTANTIATE_TEST_SUITE_P(Ops, GeometryUpdate, ::testing::ValuesIn(op_cases()),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// Records keep their index while their instance stays, so after a delete the records of later
// instances are not where a fresh upload puts them: the cutout's random choice keys on the
// record's identity (its index in a fresh upload), not its index.
TEST(GeometryUpdate, CutoutChoicesDoNotDependOnWhereRecordsSit) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  apply_edit(scene, MaterialEdit{"white", {{"geometry_opacity", {0.5f}}}});
  Renderer renderer(test::context(), scene, settings());
  renderer.update_scene(scene, test::edit_scene(scene, DeleteEdit{"floor"}));
  renderer.add_samples_full_frame(2);
  EXPECT_EQ(renderer.image().rgb, fresh_render(scene, 2).rgb);
}

// Many duplicate/delete cycles reuse the records the deleted copies had: the record table (and
// every buffer sized by it) and the device memory stay as they were after the first cycle.
TEST(GeometryUpdate, DuplicateDeleteCyclesKeepRecordsAndDeviceMemoryFlat) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  GpuScene gpu(test::context(), scene);
  const uint32_t records = gpu.record_count();
  Renderer renderer(test::context(), scene, settings());
  hipr_stages(renderer);  // its buffers too
  uint32_t after_first = 0;
  uint64_t device_after_first = 0;
  const auto update = [&](const Edit& edit) {
    const ChangeSet changes = test::edit_scene(scene, edit);
    gpu.update_instances(scene);
    renderer.update_scene(scene, changes);
    hipr_stages(renderer).stage1_visibility(changes);
  };
  for (int i = 0; i < 200; ++i) {
    update(DuplicateEdit{i % 3 ? "short_block" : "tall_block", "copy",
                         glm::vec3(0.01f * float(i % 5))});
    if (i == 0) after_first = gpu.record_count();
    EXPECT_EQ(gpu.record_count(), after_first) << i;
    update(DeleteEdit{"copy"});
    if (i == 0) device_after_first = vk::device_bytes_in_use();
  }
  EXPECT_GT(after_first, records);
  EXPECT_EQ(gpu.record_count(), after_first);
  EXPECT_EQ(gpu.info().instance_count, scene.instances().size());
  EXPECT_EQ(vk::device_bytes_in_use(), device_after_first);
}

// Stage 1 after a delete finds the tiles where the deleted block was (the G-buffer before the
// edit shows it), and after a duplicate where the copy is.
TEST(GeometryUpdate, StageOneMarksWhereTheNodeWasAndWhereTheCopyIs) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  RenderSettings s = test::render_settings(64, 64, 8, 4, 2);
  Renderer renderer(test::context(), scene, s);
  renderer.refresh_gbuffer();
  std::vector<uint32_t> was = renderer.gbuffer_instances();
  const std::vector<Instance> old_instances = scene.instances();
  uint32_t tall = UINT32_MAX;
  for (uint32_t i = 0; i < old_instances.size(); ++i)
    if (scene.nodes[old_instances[i].node].name == "tall_block") tall = i;
  const auto tiles_showing = [&](const std::vector<uint32_t>& pixel_instances, uint32_t instance) {
    std::vector<bool> tiles(renderer.tile_count(), false);
    for (size_t p = 0; p < pixel_instances.size(); ++p)
      if (pixel_instances[p] == instance)
        tiles[(p / s.width / s.tile_size) * renderer.tiles_x() + (p % s.width) / s.tile_size] =
            true;
    return tiles;
  };
  const std::vector<bool> tall_tiles = tiles_showing(was, tall);
  // Stage 1 after the edit; then how many of the tiles `showing` names (asked after stage 1) it
  // made active, of how many.
  const auto stage1_marks = [&](const ChangeSet& changes,
                                const std::function<std::vector<bool>()>& showing) {
    renderer.update_scene(scene, changes);
    hipr_stages(renderer).stage1_visibility(changes);
    const std::vector<uint32_t> flags = read_tile_flags(renderer);
    const std::vector<bool> tiles = showing();
    size_t marked = 0, expected = 0, active = 0;
    for (size_t t = 0; t < flags.size(); ++t) {
      active += (flags[t] & abi::kTileActive) ? 1 : 0;
      if (!tiles[t]) continue;
      ++expected;
      marked += (flags[t] & abi::kTileActive) ? 1 : 0;
    }
    EXPECT_LT(active, flags.size()) << "tiles that never showed the change stay as they were";
    return std::pair(marked, expected);
  };

  const auto [marked, expected] =
      stage1_marks(test::edit_scene(scene, DeleteEdit{"tall_block"}), [&] { return tall_tiles; });
  ASSERT_GT(expected, 0u);
  EXPECT_EQ(marked, expected) << "every tile that showed the deleted block is active";

  const ChangeSet changes =
      test::edit_scene(scene, DuplicateEdit{"short_block", "copy", glm::vec3(0.25f, 0.0f, 0.0f)});
  ASSERT_EQ(changes.instances.size(), 1u);
  const auto [copy_marked, copy_expected] = stage1_marks(
      changes, [&] { return tiles_showing(renderer.gbuffer_instances(), changes.instances[0]); });
  ASSERT_GT(copy_expected, 0u);
  EXPECT_EQ(copy_marked, copy_expected) << "every tile that shows the copy is active";
}

// A textured import saved (its images as PNGs of the decoded texels, its samplers, texture
// references and transforms) renders as the edited scene, from .gltf and .glb: within noise,
// as the issue asks, and in fact far closer (the loader normalizes normals and tangents again,
// which moves their last bits: nothing else differs).
TEST(TexturedImport, SavedRendersAsTheEditedScene) {
  if (!test::shared_scenes_available()) GTEST_SKIP() << "no shared scenes (DamagedHelmet)";
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  apply_edit(scene, ImportEdit{test::shared_scene("DamagedHelmet/DamagedHelmet.glb"), "helmet",
                               glm::vec3(0.28f, 0.25f, 0.28f)});
  apply_edit(scene, TransformEdit{
                        "helmet", std::nullopt,
                        glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.28f, 0.25f, 0.28f)),
                                   glm::vec3(0.15f))});
  const ImageRGB edited = fresh_render(scene, 2);
  RenderSettings other_seed = settings();
  other_seed.seed = 1;
  Renderer noise(test::context(), scene, other_seed);
  noise.add_samples_full_frame(2);
  const double noise_level = relmse(noise.image(), edited);
  ASSERT_GT(noise_level, 0.0);
  const std::filesystem::path dir = test::temp_dir("textured_import");
  for (const char* name : {"helmet.gltf", "helmet.glb"}) {
    save_scene(scene, dir / name);
    const Scene reloaded = load_scene(dir / name);
    EXPECT_EQ(reloaded.images.size(), scene.images.size()) << name;
    for (size_t i = 0; i < scene.images.size() && i < reloaded.images.size(); ++i)
      EXPECT_EQ(reloaded.images[i].rgba8, scene.images[i].rgba8)
          << name << ": image " << i << " lossless";
    EXPECT_LT(relmse(fresh_render(reloaded, 2), edited), 1e-3 * noise_level) << name;
  }
}

// Imports into a textured scene append their images to the device's texels (the scene's stay
// where they are); an undone import's images are replaced by the next one's at the same
// indices. Each update renders as a fresh upload does.
TEST(TexturedImport, AppendsItsImagesAndUpdatesAsAFreshUpload) {
  if (!test::shared_scenes_available())
    GTEST_SKIP() << "no shared scenes (DamagedHelmet, SheenChair)";
  Scene scene =
      load_scene(test::shared_scene("DamagedHelmet/DamagedHelmet.glb"), {.environment = "studio"});
  Renderer renderer(test::context(), scene, settings());
  renderer.add_samples_full_frame(1);
  const Edit chair = ImportEdit{test::shared_scene("SheenChair/SheenChair.gltf"), "chair",
                                glm::vec3(0.5f, -0.6f, 0.0f)};
  const Edit undo = inverse_edit(scene, chair);
  test::expect_update_matches_fresh(renderer, scene, chair);
  test::expect_update_matches_fresh(renderer, scene, undo);
  test::expect_update_matches_fresh(
      renderer, scene,
      ImportEdit{test::shared_scene("DamagedHelmet/DamagedHelmet.glb"), "helmet",
                 glm::vec3(0.6f, 0.0f, -0.5f)});
}

// A focus names instances by number: a delete before them renumbers them, and the focus follows
// its node (what left drops out).
TEST(GeometryUpdate, TheFocusFollowsItsObjectsThroughADelete) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 4);
  EditPipeline pipeline(scene, scheduler);
  pipeline.apply(FocusEdit{.node = "tall_block"});
  pipeline.apply(FocusEdit{.node = "floor"});
  pipeline.apply(DeleteEdit{"floor"});
  const std::vector<Instance> instances = scene.instances();
  ASSERT_EQ(pipeline.focus().seeds.size(), 2u);
  ASSERT_EQ(pipeline.focus().seeds[0].instances.size(), 1u);
  EXPECT_EQ(scene.nodes[instances[pipeline.focus().seeds[0].instances[0]].node].name, "tall_block");
  EXPECT_TRUE(pipeline.focus().seeds[1].instances.empty()) << "the floor left";
  EXPECT_EQ(scheduler.focus(), pipeline.focus());
}

// Scheduling: whatever the policy and display rule, the display ends on exactly the full-frame
// image of the edited scene after each geometry edit.
struct PolicyCase {
  Policy policy;
  DisplayRule display;
};

class GeometryEveryPolicy : public ::testing::TestWithParam<PolicyCase> {};

TEST_P(GeometryEveryPolicy, ConvergesToTheFullFrameImageOfTheEditedScene) {
  const PolicyCase c = GetParam();
  const RenderSettings s = test::render_settings(48, 40, 8, 6, 13);
  const uint32_t spp = 3;
  const auto full_frame = [&](const Scene& scene) {
    Renderer renderer(test::context(), scene, s);
    renderer.add_samples_full_frame(spp);
    renderer.resolve_display_all(DisplayRule::Immediate);
    return renderer.displayed_image();
  };
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, s);
  ImageRGB expected;
  Scheduler scheduler(renderer, bench::make_bench_policy(c.policy, expected), 7);
  scheduler.set_display_rule(c.display);
  renderer.add_samples_full_frame(spp);
  const std::vector<Edit> edits = {
      DuplicateEdit{"short_block", "copy", glm::vec3(-0.3f, 0.0f, 0.25f)},
      DeformEdit{"tall_block", stretch(), nullptr}, DeleteEdit{"short_block"},
      ImportEdit{test::asset("cornell_sphere.glb"), "sphere", glm::vec3(0.0f, 0.1f, 0.0f)}};
  for (const Edit& edit : edits) {
    const ChangeSet changes = test::edit_scene(scene, edit);
    expected = full_frame(scene);
    scheduler.on_edit(scene, changes);
    for (int step = 0; step < 10000 && scheduler.work_since_edit() < double(spp); ++step)
      scheduler.step();
    EXPECT_EQ(scheduler.displayed_image().rgb, expected.rgb) << describe(edit);
  }
}

INSTANTIATE_TEST_SUITE_P(Policies, GeometryEveryPolicy,
                         ::testing::Values(PolicyCase{Policy::Hipr, DisplayRule::Difference},
                                           PolicyCase{Policy::Hipr, DisplayRule::Blend},
                                           PolicyCase{Policy::Full, DisplayRule::Immediate},
                                           PolicyCase{Policy::Scanline, DisplayRule::Immediate},
                                           PolicyCase{Policy::Spiral, DisplayRule::Switch},
                                           PolicyCase{Policy::Random, DisplayRule::Immediate},
                                           PolicyCase{Policy::Oracle, DisplayRule::Difference}),
                         [](const auto& param_info) {
                           return policy_name(param_info.param.policy) + "_" +
                                  display_rule_name(param_info.param.display);
                         });

}  // namespace
}  // namespace hipr
