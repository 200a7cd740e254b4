// Independent check: our Lambert Cornell box against Blender Cycles (an independent
// production renderer) at 64x64. tools/reference/cycles_cornell.py made the reference image
// (see tools/reference/README.md for the command, sample count and conventions).
#include <gtest/gtest.h>

#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "image/image_io.h"
#include "test_support.h"

namespace hipr {
namespace {

TEST(Reference, CornellBoxMatchesCycles) {
  const auto reference_path = std::filesystem::path(HIPR_TEST_DATA_DIR) / "cornell_cycles_64.exr";
  if (!std::filesystem::exists(reference_path)) GTEST_SKIP() << "no Cycles reference image";
  const ImageRGB cycles = read_image(reference_path);
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));

  // Two independent renders: their difference measures our own noise level.
  ImageRGB ours[2];
  for (int i = 0; i < 2; ++i) {
    RenderSettings s;
    s.width = s.height = 64;
    s.max_depth = 64;
    s.seed = 100 + uint32_t(i);
    Renderer renderer(test::context(), scene, s);
    for (int k = 0; k < 8; ++k) renderer.add_samples_full_frame(32);
    ours[i] = renderer.image();
  }
  // Mean brightness within 0.5%; blocks within what our noise explains (see test_support.h).
  EXPECT_NEAR(test::mean(test::average(ours[0], ours[1])) / test::mean(cycles), 1.0, 0.005);
  EXPECT_LT(test::error_to_noise_ratio(ours[0], ours[1], cycles), 1.5);
}

}  // namespace
}  // namespace hipr
