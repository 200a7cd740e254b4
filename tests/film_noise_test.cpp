// The film's noise estimate (Renderer::noise, film_noise.comp): what the viewer's noise target
// stops at. It must be what the image's error against its converged limit turns out to be, fall
// as 1/samples, and refuse to judge pixels it cannot (one sample, samples owed to a past scene).
#include <gtest/gtest.h>

#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "image/error_metrics.h"
#include "test_support.h"

namespace hipr {
namespace {

RenderSettings settings_with(uint32_t seed, Sampler sampler = Sampler::Random) {
  RenderSettings s = test::render_settings(32, 32, 8, 4, seed);
  s.sampler = sampler;
  return s;
}

struct Errors {
  double estimated = 0.0, measured = 0.0;  // summed over seeds
};

// The estimate and the relMSE measured against `truth`, summed over four seeds, at 16 spp and
// after 48 more.
std::pair<Errors, Errors> errors_over_seeds(const Scene& scene, Sampler sampler,
                                            const ImageRGB& truth) {
  Errors early, later;
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    Renderer renderer(test::context(), scene, settings_with(seed, sampler));
    renderer.add_samples_full_frame(16);
    const FilmNoise noise = renderer.noise();
    EXPECT_EQ(noise.unknown_pixels, 0u);
    EXPECT_EQ(noise.pixels, 32u * 32u);
    early.estimated += noise.relmse;
    early.measured += relmse(renderer.image(), truth);
    renderer.add_samples_full_frame(48);
    later.estimated += renderer.noise().relmse;
    later.measured += relmse(renderer.image(), truth);
  }
  return {early, later};
}

// With independent samples the estimate is the relMSE measured against a 1024-spp render of
// another seed (whose own noise adds about 1/64 to 1/16 of it), at 16 spp and at 64, and falls
// as 1/samples. Sobol's samples converge faster than independent ones, so there the estimate
// is above the error (the viewer pauses later than it could), never far below it.
TEST(FilmNoise, IsTheErrorAgainstTheConvergedImage) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer reference(test::context(), scene, settings_with(99));
  reference.add_samples_full_frame(1024);
  const ImageRGB truth = reference.image();

  const auto [early, later] = errors_over_seeds(scene, Sampler::Random, truth);
  EXPECT_GT(early.estimated, 0.0);
  EXPECT_NEAR(early.estimated / early.measured, 1.0, 0.25)
      << early.estimated << " estimated, " << early.measured << " measured";
  EXPECT_NEAR(later.estimated / later.measured, 1.0, 0.25)
      << later.estimated << " estimated, " << later.measured << " measured";
  EXPECT_NEAR(later.estimated / early.estimated, 0.25, 0.06);

  const auto [sobol_early, sobol_later] = errors_over_seeds(scene, Sampler::Sobol, truth);
  EXPECT_GT(sobol_early.estimated, 0.8 * sobol_early.measured);
  EXPECT_GT(sobol_later.estimated, 0.8 * sobol_later.measured);

  const FilmNoise known{0.01, 0, 1024}, partly_unknown{0.01, 1, 1024};
  EXPECT_TRUE(known.within(0.01));
  EXPECT_FALSE(known.within(0.009));
  EXPECT_FALSE(partly_unknown.within(0.01));
}

// One sample has no variance, and a pixel owing a restart holds samples of another scene: the
// estimate counts them as unknown, and a target is never met while any is.
TEST(FilmNoise, PixelsItCannotJudgeAreUnknown) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, settings_with(1));
  EXPECT_EQ(renderer.noise().unknown_pixels, 32u * 32u) << "no samples";
  renderer.add_samples_full_frame(1);
  const FilmNoise one = renderer.noise();
  EXPECT_EQ(one.unknown_pixels, 32u * 32u) << "one sample";
  EXPECT_FALSE(one.within(1e30));
  renderer.add_samples_full_frame(3);
  EXPECT_EQ(renderer.noise().unknown_pixels, 0u);
  renderer.mark_all_owed();
  EXPECT_EQ(renderer.noise().unknown_pixels, 32u * 32u) << "owed";
}

}  // namespace
}  // namespace hipr
