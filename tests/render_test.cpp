// Determinism and regression of the path tracer on the shipped Cornell box.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "image/image_io.h"
#include "test_support.h"

namespace hipr {
namespace {

// 40 x 36 is not a multiple of the tile sizes: partial tiles take part.
RenderSettings small_settings(uint32_t tile, Sampler sampler = Sampler::Sobol) {
  RenderSettings s = test::render_settings(40, 36, tile, 8, 7);
  s.sampler = sampler;
  return s;
}

ImageRGB render_full(const Scene& scene, const RenderSettings& s, uint32_t spp,
                     uint32_t per_dispatch) {
  Renderer renderer(test::context(), scene, s);
  for (uint32_t done = 0; done < spp; done += per_dispatch)
    renderer.add_samples_full_frame(per_dispatch);
  return renderer.image();
}

const Scene& cornell() {
  static const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  return scene;
}

TEST(Determinism, SameSeedTwiceIsBitIdentical) {
  const ImageRGB a = render_full(cornell(), small_settings(16), 4, 4);
  const ImageRGB b = render_full(cornell(), small_settings(16), 4, 4);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_GT(test::mean(a), 0.01);
}

TEST(Determinism, TileSizeAndBatchingDoNotChangeTheImage) {
  for (Sampler sampler : {Sampler::Sobol, Sampler::Random}) {
    const ImageRGB reference = render_full(cornell(), small_settings(16, sampler), 4, 4);
    for (uint32_t tile : {1u, 7u, 8u, 13u, 32u, 64u}) {
      EXPECT_EQ(render_full(cornell(), small_settings(tile, sampler), 4, 1).rgb, reference.rgb)
          << sampler_name(sampler) << ", tile " << tile;
    }
    EXPECT_EQ(render_full(cornell(), small_settings(16, sampler), 4, 2).rgb, reference.rgb)
        << sampler_name(sampler);
    // Uneven batches: 1 + 3 samples.
    Renderer renderer(test::context(), cornell(), small_settings(16, sampler));
    renderer.add_samples_full_frame(1);
    renderer.add_samples_full_frame(3);
    EXPECT_EQ(renderer.image().rgb, reference.rgb) << sampler_name(sampler);
  }
}

TEST(Determinism, SamplersDifferButAgreeOnTheMean) {
  const ImageRGB sobol = render_full(cornell(), small_settings(16, Sampler::Sobol), 16, 16);
  const ImageRGB random = render_full(cornell(), small_settings(16, Sampler::Random), 16, 16);
  EXPECT_NE(sobol.rgb, random.rgb);
  EXPECT_NEAR(test::mean(sobol) / test::mean(random), 1.0, 0.03);
}

TEST(Determinism, TileOrderDoesNotChangeTheImage) {
  const ImageRGB reference = render_full(cornell(), small_settings(8), 2, 1);
  Renderer renderer(test::context(), cornell(), small_settings(8));
  std::vector<uint32_t> tiles(renderer.tile_count());
  std::iota(tiles.begin(), tiles.end(), 0u);
  std::mt19937 rng(3);
  for (int pass = 0; pass < 2; ++pass) {
    std::shuffle(tiles.begin(), tiles.end(), rng);
    // Uneven subsets in random order, as a scheduler would issue them.
    const size_t half = tiles.size() / 3;
    renderer.add_samples(std::span(tiles).subspan(half), 1);
    renderer.add_samples(std::span(tiles).first(half), 1);
  }
  EXPECT_EQ(renderer.image().rgb, reference.rgb);
  const auto counts = renderer.sample_counts();
  EXPECT_TRUE(std::all_of(counts.begin(), counts.end(), [](uint32_t c) { return c == 2; }));
}

TEST(Determinism, DifferentSeedsGiveDifferentNoise) {
  RenderSettings other = small_settings(16);
  other.seed = 8;
  EXPECT_NE(render_full(cornell(), small_settings(16), 2, 2).rgb,
            render_full(cornell(), other, 2, 2).rgb);
}

TEST(Renderer, OnlyListedTilesReceiveSamples) {
  Renderer renderer(test::context(), cornell(), small_settings(8));
  const uint32_t tile = renderer.tiles_x() + 1;  // second row, second column
  renderer.add_samples(std::span(&tile, 1), 3);
  const auto counts = renderer.sample_counts();
  for (uint32_t y = 0; y < 36; ++y)
    for (uint32_t x = 0; x < 40; ++x) {
      const bool inside = x >= 8 && x < 16 && y >= 8 && y < 16;
      ASSERT_EQ(counts[y * 40 + x], inside ? 3u : 0u) << x << "," << y;
    }
  EXPECT_EQ(renderer.counters().samples, 64u * 3u);
  EXPECT_EQ(renderer.counters().non_finite_samples, 0u);
}

// The film's total of samples, summed on the GPU for the viewer's status line, is the sum of the
// pixels' counts: over a pixel count that is no multiple of the workgroup (40 x 36), with tiles
// at different counts, and not counting the owed bit an edit sets.
TEST(Renderer, TotalSamplesIsTheSumOfThePixelsCounts) {
  Renderer renderer(test::context(), cornell(), small_settings(8));
  EXPECT_EQ(renderer.total_samples(), 0u);
  renderer.add_samples_full_frame(2);
  const uint32_t first = 0, last = renderer.tile_count() - 1;
  renderer.add_samples(std::span(&first, 1), 3);
  renderer.add_samples(std::span(&last, 1), 5);
  const uint64_t expected =
      40u * 36u * 2u + 64u * 3u + 32u * 5u;  // the last tile has 8 x 4 pixels in the image
  EXPECT_EQ(renderer.total_samples(), expected);
  renderer.mark_all_owed();
  EXPECT_EQ(renderer.total_samples(), expected);
  uint64_t sum = 0;
  for (uint32_t count : renderer.sample_counts()) sum += count;
  EXPECT_EQ(sum, expected);
}

// Golden image: tests/data/cornell_golden_64.exr was rendered by this renderer at 4096 spp
// with the Sobol sampler (seed 1, max depth 32; `hipr render assets/scenes/cornell_box.gltf
// -o ... --width 64 --height 64 --spp 4096 --seed 1`) and checked against Cycles
// (reference_test). Its noise must stay well below the test renders', so it is made again when
// the sampler improves (1024 spp was enough for the random sampler). A bit-exact comparison
// would break on any other driver or compiler, so the test renders four 16-spp images with
// other seeds and requires (a) the mean within 1% and (b) the 4x4-block error of their mean to
// the golden image within 1.6x of what their spread explains. Noise alone gives ~1.0-1.2 (the
// golden image has noise too); a wrong light, colour, camera or geometry gives far more.
struct GoldenComparison {
  double mean_ratio;
  double error_to_noise;
};

GoldenComparison compare_with_golden(const Scene& scene) {
  const ImageRGB golden =
      read_image(std::filesystem::path(HIPR_TEST_DATA_DIR) / "cornell_golden_64.exr");
  EXPECT_EQ(golden.width, 64u);
  std::vector<ImageRGB> renders;
  double mean = 0.0;
  for (uint32_t i = 0; i < 4; ++i) {
    RenderSettings s;
    s.width = s.height = 64;
    s.seed = 11 + i;
    s.max_depth = 32;
    renders.push_back(render_full(scene, s, 16, 16));
    mean += test::mean(renders.back()) / 4.0;
  }
  return {mean / test::mean(golden), test::error_to_noise_ratio(renders, golden)};
}

TEST(Golden, CornellBoxMatchesTheStoredImage) {
  const GoldenComparison result = compare_with_golden(cornell());
  EXPECT_NEAR(result.mean_ratio, 1.0, 0.01);
  EXPECT_LT(result.error_to_noise, 1.6);
}

TEST(Golden, DetectsASmallSceneChange) {
  // The tall block moved by 6 cm x 8 cm: the comparison must notice.
  const GoldenComparison result =
      compare_with_golden(load_scene(test::asset("cornell_box_moved.gltf")));
  EXPECT_GT(result.error_to_noise, 3.0);
}

}  // namespace
}  // namespace hipr
