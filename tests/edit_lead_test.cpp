// The edit's lead (docs/method.md#the-edits-lead): after an edit that moves geometry, the pixels
// that show the moved object, or a surface they no longer see, get more samples before the
// rest of the first round; every pixel still ends with the converged count, on exactly the
// full-frame render.
#include <gtest/gtest.h>

#include <algorithm>

#include "hipr/edits.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "test_support.h"

namespace hipr {
namespace {

RenderSettings settings() { return test::render_settings(64, 48, 8, 6, 33); }

// The index of `node`'s instance in Scene::instances() (what the G-buffer reports).
uint32_t instance_of(const Scene& scene, const char* node) {
  const size_t index = find_node(scene, node);
  const std::vector<Instance> instances = scene.instances();
  for (uint32_t i = 0; i < instances.size(); ++i)
    if (instances[i].node == index) return i;
  ADD_FAILURE() << node << " has no instance";
  return UINT32_MAX;
}

TEST(EditLead, AMovedObjectsPixelsRunAheadThenEveryPixelEndsEven) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  const RenderSettings s = settings();
  // Before the edit the render had converged: pixels not visited since still count its samples.
  const uint32_t spp = 8, lead = 3, first = 2, prior = spp;
  Renderer renderer(test::context(), scene, s);
  Scheduler scheduler(renderer, Policy::Hipr, 4);
  scheduler.set_first_visit_spp(first);
  scheduler.set_converged_spp(spp);
  scheduler.set_edit_lead(lead);
  renderer.add_samples_full_frame(prior);
  const std::vector<uint32_t> before = renderer.gbuffer_instances();
  const Scene unmoved = scene;
  apply_edit(scene, TransformEdit{"tall_block", glm::vec3(0.06f, 0.0f, -0.08f), std::nullopt});
  scheduler.on_edit(scene, diff_scenes(unmoved, scene));
  const std::vector<uint32_t> now = renderer.gbuffer_instances();
  const uint32_t block = instance_of(scene, "tall_block");

  for (int step = 0;
       step < 1000 && !scheduler.lead_pass_pending() && scheduler.work_since_edit() < first; ++step)
    scheduler.step();
  ASSERT_TRUE(scheduler.lead_pass_pending()) << "the lead comes within the first round";
  while (scheduler.lead_pass_pending()) scheduler.step();
  const std::vector<uint32_t> counts = renderer.sample_counts();
  uint32_t leading = 0, behind = 0;
  for (size_t p = 0; p < counts.size(); ++p) {
    const bool moved = now[p] == block || now[p] != before[p];
    if (moved) {
      EXPECT_EQ(counts[p], first + lead)
          << "pixel " << p << " shows the moved block or a surface it uncovered";
      ++leading;
    } else {
      EXPECT_TRUE(counts[p] <= first || counts[p] == prior)
          << "pixel " << p << " waits for the round: " << counts[p];
      behind += counts[p] == prior;
    }
  }
  EXPECT_GT(leading, 0u);
  EXPECT_GT(behind, 0u) << "the lead came before the first round's end";

  for (int step = 0; step < 10000 && scheduler.work_since_edit() < double(spp); ++step) {
    scheduler.step();
    for (uint32_t count : renderer.sample_counts())
      ASSERT_LE(count, spp) << "no pixel passes the converged count";
  }
  const std::vector<uint32_t> final_counts = renderer.sample_counts();
  EXPECT_TRUE(
      std::all_of(final_counts.begin(), final_counts.end(), [&](uint32_t c) { return c == spp; }));
  EXPECT_EQ(scheduler.displayed_image().rgb, test::full_frame_display(scene, s, spp).rgb);
}

// A recolour moves nothing: its pixels keep their difference estimate (two kept samples) and
// get no lead.
TEST(EditLead, ARecolourLeadsNoPixel) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings());
  Scheduler scheduler(renderer, Policy::Hipr, 4);
  scheduler.set_first_visit_spp(2);
  scheduler.set_converged_spp(8);
  renderer.add_samples_full_frame(12);  // pixels not visited since the edit still count these
  const Scene before = scene;
  apply_edit(scene, MaterialEdit{"red", {{"base_color", {0.1f, 0.2f, 0.7f}}}});
  scheduler.on_edit(scene, diff_scenes(before, scene));
  for (int step = 0; step < 12; ++step) {
    scheduler.step();
    EXPECT_FALSE(scheduler.lead_pass_pending());
  }
  for (uint32_t count : renderer.sample_counts()) EXPECT_TRUE(count <= 2u || count == 12u) << count;
}

}  // namespace
}  // namespace hipr
