// A program that uses the library through its public API alone: this file is compiled with
// include/ as its only hipr include path (no src/, no shader ABI), so it can reach nothing
// else. It opens a device, loads a scene, renders it, edits it through the edit pipeline and a
// HiPR scheduler, and ends on exactly the image a fresh render of the edited scene gives.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "hipr/device.h"
#include "hipr/edit_pipeline.h"
#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "hipr/schedule_settings.h"
#include "hipr/scheduler.h"

namespace {

hipr::ImageRGB fresh_display(const hipr::Device& device, const hipr::Scene& scene,
                             const hipr::RenderSettings& settings, uint32_t spp) {
  hipr::Renderer renderer(device, scene, settings);
  renderer.add_samples_full_frame(spp);
  renderer.resolve_display_all(hipr::DisplayRule::Immediate);
  return renderer.displayed_image();
}

TEST(PublicApi, RendersAndEditsThroughIncludeHiprAlone) {
  const std::unique_ptr<hipr::Device> device = hipr::open_device();
  ASSERT_FALSE(device->device_name().empty());
  hipr::Scene scene = hipr::load_scene(std::string(HIPR_ASSETS_DIR) + "/cornell_box.gltf");
  hipr::RenderSettings settings;
  settings.width = 48;
  settings.height = 40;
  settings.tile_size = 8;
  settings.max_depth = 4;
  const uint32_t spp = 4;

  hipr::Renderer renderer(*device, scene, settings);
  renderer.add_samples_full_frame(spp);
  const hipr::ImageRGB before = renderer.image();
  hipr::Scheduler scheduler(renderer, hipr::make_policy(hipr::Policy::Hipr),
                            hipr::default_tiles_per_step(renderer.tile_count()));
  scheduler.configure(hipr::ScheduleSettings{}, spp);

  hipr::EditPipeline pipeline(scene, scheduler);
  const hipr::ChangeSet changes =
      pipeline.apply(hipr::TransformEdit{"tall_block", glm::vec3(0.05f, 0.0f, 0.0f), std::nullopt});
  EXPECT_FALSE(changes.empty());
  for (int step = 0; step < 10000 && scheduler.work_since_edit() < double(spp); ++step)
    scheduler.step();
  ASSERT_GE(scheduler.work_since_edit(), double(spp));

  const hipr::ImageRGB shown = scheduler.displayed_image();
  EXPECT_NE(shown.rgb, before.rgb) << "the edit shows";
  EXPECT_EQ(shown.rgb, fresh_display(*device, scene, settings, spp).rgb)
      << "the re-render ends on the full-frame render of the edited scene";
}

}  // namespace
