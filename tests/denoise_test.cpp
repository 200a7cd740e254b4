// The display denoiser (src/render/denoise_pass.h): it filters a copy of the display and nothing
// else; a precise pixel stays as it is; it never mixes two surfaces, nor a value of the scene
// before an edit with one after it; and it takes the noise out of a real render.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "card_scene.h"
#include "core/timer.h"
#include "denoise_support.h"
#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "image/error_metrics.h"
#include "render/render_state.h"
#include "test_support.h"

namespace hipr {
namespace {

using test::denoise_on;
using test::kSize;
using test::noisy;
using test::SyntheticPixel;
using test::two_cards;
using test::write_display;

TEST(Denoise, FiltersACopyAndLeavesAccumulationAndDisplayAlone) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, test::render_settings(48, 48, 8, 4, 1));
  renderer.add_samples_full_frame(4);
  renderer.resolve_display_all(DisplayRule::Immediate);
  const ImageRGB accumulation = renderer.image();
  const ImageRGB display = renderer.displayed_image();
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  EXPECT_TRUE(test::all_finite(denoised));
  EXPECT_NE(denoised.rgb, display.rgb);
  EXPECT_EQ(renderer.image().rgb, accumulation.rgb);
  EXPECT_EQ(renderer.displayed_image().rgb, display.rgb);
  // Off, or at strength 0, it is the display bit for bit.
  EXPECT_EQ(renderer.denoised_image(DenoiseSettings{}).rgb, display.rgb);
  DenoiseSettings zero = denoise_on();
  zero.strength = 0.0f;
  EXPECT_EQ(renderer.denoised_image(zero).rgb, display.rgb);
}

TEST(Denoise, TakesTheNoiseOutOfARender) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  const RenderSettings settings = test::render_settings(48, 48, 8, 4, 2);
  Renderer reference(test::context(), scene, test::render_settings(48, 48, 8, 4, 9));
  reference.add_samples_full_frame(256);
  Renderer renderer(test::context(), scene, settings);
  renderer.add_samples_full_frame(4);
  renderer.resolve_display_all(DisplayRule::Immediate);
  const double raw = relmse(renderer.displayed_image(), reference.image());
  const double denoised = relmse(renderer.denoised_image(denoise_on()), reference.image());
  // At 4 spp the filter takes at least two thirds of the error (measured: 4.0x less).
  EXPECT_LT(denoised, raw / 3.0) << "raw " << raw << ", denoised " << denoised;
}

// Pixel `precise` (on the left card) of `pixels` gets 2^20 samples showing `value`: the
// denoiser leaves it within `tolerance` while it filters its noisy neighbours.
void expect_precise_pixel_kept(std::vector<SyntheticPixel> pixels, size_t precise, glm::vec3 value,
                               float tolerance) {
  Renderer renderer(test::context(), two_cards(), test::render_settings(kSize, kSize, 8, 4, 0));
  pixels[precise].shown = value;
  pixels[precise].samples = 1u << 20;
  write_display(renderer, pixels);
  const ImageRGB shown = renderer.displayed_image();
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  for (size_t c = 0; c < 3; ++c)
    EXPECT_NEAR(denoised.rgb[3 * precise + c], shown.rgb[3 * precise + c], tolerance) << c;
  EXPECT_NE(denoised.rgb[3 * (precise + 1)], shown.rgb[3 * (precise + 1)]) << "not filtered";
}

TEST(Denoise, APrecisePixelIsLeftAsItIs) {
  expect_precise_pixel_kept(noisy(0.5f, 0.4f, 3), 10 * kSize + 8, glm::vec3(0.61f, 0.52f, 0.43f),
                            1e-6f);
}

// Pixels scattered as 2-sample estimates are, each one's two samples happening to agree (a new
// shadow's pixel after an edit: both dark, or both lit): the variance of two samples is a
// guess with one degree of freedom, and a value with fewer than three behind it takes its
// neighbours' spread (as SVGF does with a short history). Trusted, the pairs stayed a speckle.
// With four samples that agree, a pixel's own variance stands.
TEST(Denoise, AValueOnFewSamplesTakesItsNeighboursSpread) {
  for (const uint32_t samples : {2u, 4u}) {
    Renderer renderer(test::context(), two_cards(), test::render_settings(kSize, kSize, 8, 4, 0));
    std::vector<SyntheticPixel> pixels = noisy(0.5f, 0.4f, 5);
    for (SyntheticPixel& p : pixels) {
      p.samples = samples;
      p.deviation = 0.0f;
    }
    write_display(renderer, pixels);
    const ImageRGB shown = renderer.displayed_image();
    const ImageRGB denoised = renderer.denoised_image(denoise_on());
    double before = 0.0, after = 0.0;
    for (size_t i = 0; i < shown.rgb.size(); ++i) {
      before += (shown.rgb[i] - 0.5) * (shown.rgb[i] - 0.5);
      after += (denoised.rgb[i] - 0.5) * (denoised.rgb[i] - 0.5);
    }
    if (samples < 4u)
      EXPECT_LT(after, before / 4.0) << "before " << before << ", after " << after;
    else
      EXPECT_GT(after, before * 0.99) << "four samples that agree are precise";
  }
}

// After an edit hipr keeps a converged stale value where the edit changed nothing (the difference
// rule's b = 0), and the pixel, re-rendered, shows it over its first pair of fresh samples
// (shownSamples 16, two in the accumulation). The pair's variance, one degree of freedom, is
// mostly too small where rare paths carry the noise (here: the two agree exactly), and the kept
// value passed for a precise one and was shown unfiltered: the denoised display grew noisier as
// hipr re-rendered (CornellBox's sphere move). The noise measured on the value's own 16 samples,
// before the edit, stands for it.
TEST(Denoise, AKeptValueOverAPairOfFreshSamplesKeepsTheNoiseOfItsOwnSamples) {
  Renderer renderer(test::context(), two_cards(), test::render_settings(kSize, kSize, 8, 4, 0));
  // Scattered as 4 samples of deviation 0.4 would be, or 16 of 0.8.
  std::vector<SyntheticPixel> pixels = noisy(0.5f, 0.4f, 7);
  for (SyntheticPixel& p : pixels) {
    p.samples = 16;
    p.deviation = 0.8f;
  }
  write_display(renderer, pixels);
  const ImageRGB shown = renderer.displayed_image();
  const auto scatter = [](const ImageRGB& image) {
    double sum = 0.0;
    for (const float v : image.rgb) sum += (v - 0.5) * (v - 0.5);
    return sum;
  };
  const double before = scatter(renderer.denoised_image(denoise_on()));
  for (SyntheticPixel& p : pixels) {
    p.fresh = 2;
    p.deviation = 0.0f;
  }
  write_display(renderer, pixels);
  ASSERT_EQ(renderer.displayed_image().rgb, shown.rgb);
  const double after = scatter(renderer.denoised_image(denoise_on()));
  EXPECT_LT(before, 0.7 * scatter(shown)) << "filtered before the edit";
  EXPECT_LT(after, 1.2 * before) << "raw " << scatter(shown) << ", before " << before << ", after "
                                 << after;
}

// The left card's pixels show 1, the right card's 0.25, noisy as far as their samples tell: the
// filter may average within a card (the values are all alike) but any weight across the edge
// shows. `scene`: two_cards(), with whatever else in front.
void expect_the_cards_apart(const Scene& scene) {
  Renderer renderer(test::context(), scene, test::render_settings(kSize, kSize, 8, 4, 0));
  std::vector<SyntheticPixel> pixels(kSize * kSize);
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      pixels[y * kSize + x].shown = glm::vec3(x < kSize / 2 ? 1.0f : 0.25f);
      pixels[y * kSize + x].deviation = 2.0f;
    }
  write_display(renderer, pixels);
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x)
      ASSERT_NEAR(denoised.rgb[3 * (y * kSize + x) + 1], x < kSize / 2 ? 1.0f : 0.25f, 1e-5f)
          << x << ", " << y;
}

// The green channel's squared error against `value`, summed over the image.
double squared_error(const ImageRGB& image, float value) {
  double sum = 0.0;
  for (size_t i = 1; i < image.rgb.size(); i += 3) sum += std::pow(image.rgb[i] - value, 2.0);
  return sum;
}

TEST(Denoise, NeverMixesTwoSurfaces) { expect_the_cards_apart(two_cards()); }

// A veil in front of the two cards, 30 % opaque (stochastic BLEND): most of each pixel's samples
// see the card behind it, and so does its guide (common/cutout.glsl, HIPR_CUTOUT_MAJORITY). A
// guide that stopped where a random 30 % of rays stop keyed those pixels to the veil, one surface
// across both cards, and the filter mixed the two cards' values there.
TEST(Denoise, AMostlyTransparentSurfaceDoesNotJoinTheSurfacesBehindIt) {
  Scene scene = two_cards();
  MaterialParameters veil = default_material_params();
  veil.geometry_opacity = 0.3f;
  test::add_card(scene, "veil", glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 1.0f)), veil);
  expect_the_cards_apart(scene);
}

// The same veil with only the environment behind it: no surface stops most of a pixel's rays,
// but the veil is where its noise comes from (the environment alone has none), and its pixels
// are filtered together, as one surface. A guide that passed through to the environment would
// show every pixel as it is; one stopped at random would key a third of them to the veil.
TEST(Denoise, AVeilBeforeTheEnvironmentIsFilteredAsOneSurface) {
  Scene scene = test::make_card_camera_scene(1.0f);
  MaterialParameters veil = default_material_params();
  veil.geometry_opacity = 0.3f;
  test::add_card(scene, "veil", glm::mat4(1.0f), veil);
  Renderer renderer(test::context(), scene, test::render_settings(kSize, kSize, 8, 4, 0));
  const float value = 0.5f;
  write_display(renderer, noisy(value, 0.4f, 5));
  const ImageRGB shown = renderer.displayed_image();
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  const double raw = squared_error(shown, value), filtered = squared_error(denoised, value);
  EXPECT_LT(filtered, raw / 3.0) << "raw " << raw << ", denoised " << filtered;
}

// A card whose normal map tilts each pixel's normal its own way (a texel a pixel, up to 55
// degrees): the map's detail is the surface's shading, not an edge between surfaces. Its noisy
// pixels are filtered as one surface: measured, 4.2x less squared error (with the mapped normal
// as the guide, the a-trous normal and tangent-plane weights kept nearly every pixel apart: 1.2x).
TEST(Denoise, ANormalMapsDetailDoesNotSplitItsSurface) {
  Scene scene = test::make_card_camera_scene(1.0f);
  Image bumps;
  bumps.name = "bumps";
  bumps.width = bumps.height = kSize;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> tilt(-0.58f, 0.58f);
  for (uint32_t i = 0; i < kSize * kSize; ++i) {
    const float x = tilt(rng), y = tilt(rng);
    const glm::vec3 n(x, y, std::sqrt(1.0f - x * x - y * y));
    for (int c = 0; c < 3; ++c) bumps.rgba8.push_back(uint8_t(std::lround(127.5f * (n[c] + 1.0f))));
    bumps.rgba8.push_back(255);
  }
  scene.images.push_back(bumps);
  Texture texture;
  texture.name = "bumps";
  texture.flags = kTextureNearest;
  scene.textures.push_back(texture);
  MaterialParameters card = default_material_params();
  card.normal_texture = 0;
  test::add_card(scene, "card", glm::mat4(1.0f), card);
  Renderer renderer(test::context(), scene, test::render_settings(kSize, kSize, 8, 4, 0));
  const float value = 0.5f;
  write_display(renderer, noisy(value, 0.4f, 5));
  const ImageRGB shown = renderer.displayed_image();
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  const double raw = squared_error(shown, value), filtered = squared_error(denoised, value);
  EXPECT_LT(filtered, raw / 3.0) << "raw " << raw << ", denoised " << filtered;
}

// A relit pixel (relight.comp) shows the samples of the scene before the edit, each light
// group's share scaled: their spread, scaled as the value was, is its noise. Taken from its
// neighbours instead, as if it had no samples, a converged relit image was filtered as noise
// wherever its shading varied. Here a checkerboard of 64 samples a pixel (relit by half: one
// sample's deviation 0.01, the mean's about 0.001) is detail 80 standard errors deep, and stays.
TEST(Denoise, ARelitPixelKeepsTheNoiseOfItsSamples) {
  Renderer renderer(test::context(), two_cards(), test::render_settings(kSize, kSize, 8, 4, 0));
  std::vector<SyntheticPixel> pixels(kSize * kSize);
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      SyntheticPixel& p = pixels[y * kSize + x];
      p.shown = glm::vec3((x + y) % 2 == 0 ? 0.3f : 0.4f);
      p.samples = 64u;
      p.deviation = 0.02f;
      p.relitBy = 0.5f;
    }
  write_display(renderer, pixels);
  const ImageRGB shown = renderer.displayed_image();
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  float moved = 0.0f;
  for (size_t i = 0; i < shown.rgb.size(); ++i)
    moved = std::max(moved, std::abs(denoised.rgb[i] - shown.rgb[i]));
  EXPECT_LT(moved, 0.01f);
}

// One surface (the left card): its top half re-rendered since the edit and showing 0.2, its
// bottom half still the stale image's 0.8; the re-rendered pixels' stale estimate is `stale`.
std::vector<SyntheticPixel> half_re_rendered(float stale) {
  std::vector<SyntheticPixel> pixels(kSize * kSize);
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize / 2; ++x) {
      SyntheticPixel& p = pixels[y * kSize + x];
      p.current = y < kSize / 2;
      p.shown = glm::vec3(p.current ? 0.2f : 0.8f);
      p.stale = glm::vec3(p.current ? stale : 0.8f);
      p.deviation = 2.0f;
      p.samples = p.current ? 2u : 64u;
    }
  return pixels;
}

TEST(Denoise, NeverMixesTheSceneBeforeAnEditWithTheSceneAfter) {
  Renderer renderer(test::context(), two_cards(), test::render_settings(kSize, kSize, 8, 4, 0));
  write_display(renderer, half_re_rendered(0.8f));
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize / 2; ++x)
      ASSERT_NEAR(denoised.rgb[3 * (y * kSize + x) + 1], y < kSize / 2 ? 0.2f : 0.8f, 1e-5f)
          << x << ", " << y;
  // The ablation that knows only the accumulation mixes them: what the test looks for is there.
  DenoiseSettings plain = denoise_on();
  plain.display_state = false;
  const ImageRGB mixed = renderer.denoised_image(plain);
  EXPECT_GT(mixed.rgb[3 * ((kSize / 2 - 1) * kSize + 4) + 1], 0.2f + 1e-3f);
}

// A re-rendered pixel that shows its stale estimate bit for bit (the difference rule found no
// change in its samples) shows what the pixels not re-rendered yet show, and what re-rendered
// ones estimate where nothing changed: the filter mixes it with either. Kept apart from the
// first, the line the re-render had reached cut the filter's footprint and the screen grew
// noisier where nothing changed; a stale pixel and a changed one still never mix (above).
TEST(Denoise, APixelShowingItsStaleEstimateMixesWithEitherState) {
  Renderer renderer(test::context(), two_cards(), test::render_settings(kSize, kSize, 8, 4, 0));
  const size_t aboveTheLine = 3 * ((kSize / 2 - 1) * kSize + 4) + 1;
  const size_t belowTheLine = 3 * ((kSize / 2) * kSize + 4) + 1;
  // Unchanged (0.2) above, not re-rendered (0.8) below.
  write_display(renderer, half_re_rendered(0.2f));
  EXPECT_GT(renderer.denoised_image(denoise_on()).rgb[aboveTheLine], 0.2f + 1e-3f);
  // Changed (0.2) above, unchanged (0.8) below.
  std::vector<SyntheticPixel> pixels = half_re_rendered(0.5f);
  for (uint32_t y = kSize / 2; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize / 2; ++x) {
      pixels[y * kSize + x].current = true;
      pixels[y * kSize + x].samples = 2u;
    }
  write_display(renderer, pixels);
  EXPECT_LT(renderer.denoised_image(denoise_on()).rgb[belowTheLine], 0.8f - 1e-3f);
}

// Pixels of 4 skewed samples each (10 % of them 13x brighter), seeded.
std::vector<SyntheticPixel> skewed(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<SyntheticPixel> pixels(kSize * kSize);
  for (SyntheticPixel& p : pixels) {
    float sum = 0.0f, squares = 0.0f;
    for (uint32_t i = 0; i < p.samples; ++i) {
      const float sample = 0.1f + 0.2f * uniform(rng) + (uniform(rng) < 0.1f ? 4.0f : 0.0f);
      sum += sample;
      squares += sample * sample;
    }
    const float n = float(p.samples);
    p.shown = glm::vec3(sum / n);
    p.deviation = std::sqrt(std::max(squares - sum * sum / n, 0.0f) / (n - 1.0f));
  }
  return pixels;
}

// A render's few samples per pixel are skewed: most paths miss the light, a few find it. An
// edge-stopping filter weighs a neighbour by how alike its value is, so the many dim pixels
// take little from the rare bright ones, and the image grows darker than its samples (measured
// on this image: 2.7 % darker before the blend restored the local mean, 0.8 % since; the Cornell
// box's walls were 2-4 % darker at 4 spp).
TEST(Denoise, KeepsTheMeanOfSkewedSamples) {
  Renderer renderer(test::context(), two_cards(), test::render_settings(kSize, kSize, 8, 4, 0));
  write_display(renderer, skewed(11));
  const ImageRGB shown = renderer.displayed_image();
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  const double raw_mean = test::mean(shown, 1), denoised_mean = test::mean(denoised, 1);
  EXPECT_NEAR(denoised_mean / raw_mean, 1.0, 0.015);
  // And it filtered all the same (unfiltered, the mean would be kept trivially): measured, the
  // pixels scatter a third less.
  double raw_scatter = 0.0, denoised_scatter = 0.0;
  for (size_t i = 1; i < shown.rgb.size(); i += 3) {
    raw_scatter += std::pow(shown.rgb[i] - raw_mean, 2.0);
    denoised_scatter += std::pow(denoised.rgb[i] - denoised_mean, 2.0);
  }
  EXPECT_LT(denoised_scatter, 0.8 * raw_scatter);
}

// The blend brings the filtered values back to their window's mean; a precise pixel among
// skewed noisy ones, which the filter left alone, must not be moved by that correction (it
// took nothing from its neighbours, so it has no lean to correct).
TEST(Denoise, APrecisePixelAmongSkewedNoiseIsLeftAsItIs) {
  // Before the restoration was scaled by samples: moved by 1.4 %.
  expect_precise_pixel_kept(skewed(5), 12 * kSize + 7, glm::vec3(0.6f, 0.5f, 0.4f), 1e-4f);
}

// The filter's cost as the device timed it (GPU timestamps): what `--stats-json` states as
// denoise_filter_gpu_seconds. Each kernel's part is positive and the whole fits inside the wall
// time around the submission; the guides are traced at the first run only.
TEST(Denoise, TheDeviceTimesEachKernelOfTheFilter) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer renderer(test::context(), scene, test::render_settings(48, 48, 8, 4, 1));
  renderer.add_samples_full_frame(2);
  renderer.resolve_display_all(DisplayRule::Immediate);
  const std::optional<DenoiseGpuSeconds> first = renderer.run_denoiser(denoise_on());
  const Timer timer;
  const std::optional<DenoiseGpuSeconds> again = renderer.run_denoiser(denoise_on());
  const double wall = timer.seconds();
  ASSERT_TRUE(first.has_value()) << "lavapipe and NVIDIA's queues have timestamps";
  ASSERT_TRUE(again.has_value());
  EXPECT_GT(first->guides, 0.0);
  EXPECT_EQ(again->guides, 0.0);
  EXPECT_GT(again->prepare, 0.0);
  EXPECT_GT(again->atrous, 0.0);
  EXPECT_GT(again->blend, 0.0);
  EXPECT_GT(again->temporal, 0.0);
  EXPECT_LE(again->total(), wall);
}

TEST(Denoise, NothingNonFiniteComesOut) {
  Renderer renderer(test::context(), two_cards(), test::render_settings(kSize, kSize, 8, 4, 0));
  std::vector<SyntheticPixel> pixels = noisy(0.5f, 0.4f, 5);
  pixels[40].shown = glm::vec3(3.0e38f);  // a firefly at float's edge
  pixels[41].deviation = 3.0e38f;         // sums that overflowed
  write_display(renderer, pixels);
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  EXPECT_TRUE(test::all_finite(denoised));
}

// A card in the middle of the view, under an environment of one-texel checks (1 and 0.05): seen
// directly, the environment changes several times across each pixel, and a few samples of it
// alias.
Scene card_under_checked_environment() {
  Scene scene = test::make_card_camera_scene(0.0f);
  test::add_card(scene, "card", glm::scale(glm::mat4(1.0f), glm::vec3(0.4f)),
                 default_material_params());
  Environment environment;
  environment.width = 1024;
  environment.height = 512;
  for (uint32_t y = 0; y < environment.height; ++y)
    for (uint32_t x = 0; x < environment.width; ++x)
      environment.texels.push_back(glm::vec3((x + y) % 2 == 0 ? 1.0f : 0.05f));
  scene.environment = environment;
  return scene;
}

// Pixels whose centre and eight neighbours' centres see the environment.
std::vector<size_t> environment_pixels(const Renderer& renderer, uint32_t size) {
  const std::vector<uint32_t> instances = renderer.gbuffer_instances();
  std::vector<size_t> out;
  for (uint32_t y = 1; y + 1 < size; ++y)
    for (uint32_t x = 1; x + 1 < size; ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) all &= instances[(y + dy) * size + x + dx] == UINT32_MAX;
      if (all) out.push_back(size_t(y) * size + x);
    }
  return out;
}

double relmse_at(const ImageRGB& image, const ImageRGB& reference,
                 const std::vector<size_t>& pixels) {
  double sum = 0.0;
  for (size_t p : pixels)
    for (size_t c = 0; c < 3; ++c) {
      const double r = reference.rgb[3 * p + c], d = image.rgb[3 * p + c] - r;
      sum += d * d / (r * r + 0.01);
    }
  return sum / (3.0 * double(pixels.size()));
}

// The environment seen directly is shown as its mean over each pixel (denoise_guides.comp): at 2
// spp far closer to the converged image than the samples' aliasing, and it does not change as
// samples arrive.
TEST(Denoise, ShowsTheEnvironmentSeenDirectlyAsItsMeanOverEachPixel) {
  const Scene scene = card_under_checked_environment();
  constexpr uint32_t kEnvSize = 48;
  Renderer reference(test::context(), scene, test::render_settings(kEnvSize, kEnvSize, 8, 4, 9));
  reference.add_samples_full_frame(256);
  Renderer renderer(test::context(), scene, test::render_settings(kEnvSize, kEnvSize, 8, 4, 2));
  renderer.add_samples_full_frame(2);
  renderer.resolve_display_all(DisplayRule::Immediate);
  renderer.refresh_gbuffer();
  const std::vector<size_t> environment = environment_pixels(renderer, kEnvSize);
  ASSERT_GT(environment.size(), kEnvSize * kEnvSize / 2u);
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  const double raw = relmse_at(renderer.displayed_image(), reference.image(), environment);
  const double shown = relmse_at(denoised, reference.image(), environment);
  // Measured: 970x less error than the raw 2-spp pixels against this 256-spp reference (2,500x
  // against 1024 samples: the reference's own aliasing is most of what is left). Without the
  // environment's mean the two are the same.
  EXPECT_LT(shown, raw / 100.0) << "raw " << raw << ", denoised " << shown;
  renderer.add_samples_full_frame(1);
  renderer.resolve_display_all(DisplayRule::Immediate);
  const ImageRGB next = renderer.denoised_image(denoise_on());
  for (size_t p : environment)
    for (size_t c = 0; c < 3; ++c) EXPECT_EQ(next.rgb[3 * p + c], denoised.rgb[3 * p + c]) << p;
}

// A pixel whose samples saw something the guide's rays did not (a sliver of a surface between
// them) is shown as it is: its samples disagree with the environment's mean. One whose samples
// agree, or that has none yet, shows the environment's mean.
TEST(Denoise, AnEnvironmentPixelWhoseSamplesSawASurfaceIsShownAsItIs) {
  Renderer renderer(test::context(), card_under_checked_environment(),
                    test::render_settings(kSize, kSize, 8, 4, 0));
  std::vector<SyntheticPixel> pixels(kSize * kSize);
  for (SyntheticPixel& p : pixels) p.shown = glm::vec3(0.5f);
  const size_t corner = 2 * kSize + 2;  // the environment, far from the card
  pixels[corner].shown = glm::vec3(3.0f, 2.0f, 1.0f);
  pixels[corner].deviation = 0.1f;
  write_display(renderer, pixels);
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  EXPECT_EQ(denoised.rgb[3 * corner], 3.0f);
  EXPECT_EQ(denoised.rgb[3 * corner + 1], 2.0f);
  EXPECT_EQ(denoised.rgb[3 * corner + 2], 1.0f);
  // Its neighbour, whose samples agree with the environment (0.5 over a 0.475-spread checker,
  // give or take what the pixel's few lookups of it differ by), shows the environment's mean.
  EXPECT_NE(denoised.rgb[3 * (corner + 1)], 0.5f);
  EXPECT_NEAR(denoised.rgb[3 * (corner + 1)], 0.525f, 0.1f);
  // One with no samples yet (the render has just begun) shows it too.
  pixels[corner + 2].samples = 0;
  write_display(renderer, pixels);
  const ImageRGB started = renderer.denoised_image(denoise_on());
  EXPECT_NEAR(started.rgb[3 * (corner + 2)], 0.525f, 0.1f);
  EXPECT_NE(started.rgb[3 * (corner + 2)], 0.5f);
}

// The pixels on the card's outline whose centres see the environment show 0.1 and 0.9 by turns
// (what a few samples falling on the card or beside it show), each sample `deviation` from its
// pixel's mean; the rest shows 0.5. Returns their squared error against 0.5, denoised / shown.
double outline_error_left(float deviation) {
  Renderer renderer(test::context(), card_under_checked_environment(),
                    test::render_settings(kSize, kSize, 8, 4, 0));
  renderer.refresh_gbuffer();
  const std::vector<uint32_t> instances = renderer.gbuffer_instances();
  const auto on_card = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < int(kSize) && y < int(kSize) &&
           instances[y * kSize + x] != UINT32_MAX;
  };
  std::vector<SyntheticPixel> pixels(kSize * kSize);
  std::vector<size_t> outline;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      SyntheticPixel& p = pixels[y * kSize + x];
      p.shown = glm::vec3(0.5f);
      p.deviation = 0.4f;
      const int ix = int(x), iy = int(y);
      if (on_card(ix, iy) || !(on_card(ix - 1, iy) || on_card(ix + 1, iy) || on_card(ix, iy - 1) ||
                               on_card(ix, iy + 1)))
        continue;
      p.shown = glm::vec3((x + y) % 2 == 0 ? 0.1f : 0.9f);
      p.deviation = deviation;
      outline.push_back(y * kSize + x);
    }
  EXPECT_GE(outline.size(), 20u);
  write_display(renderer, pixels);
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  double shown = 0.0, filtered = 0.0;
  for (size_t p : outline) {
    shown += std::pow(pixels[p].shown.y - 0.5, 2.0);
    filtered += std::pow(denoised.rgb[3 * p + 1] - 0.5, 2.0);
  }
  return filtered / shown;
}

// A pixel on an outline whose centre sees the environment mixes the surface and the environment
// in its samples, and at a few samples they may all fall on one side: along the outline such
// pixels show dark and lit dots (SheenChair at 4 spp). Its guide takes the surface its footprint
// finds (denoise_guides.comp), so it is filtered with the surface's other outline pixels, where
// shown as it is it kept every dot. Measured: 48 such pixels, 0.064x the squared error shown
// (0.27x without the variance floor below, 1x keyed to the environment).
TEST(Denoise, AnOutlinePixelWhoseCentreSeesTheEnvironmentIsFilteredWithItsSurface) {
  EXPECT_LT(outline_error_left(0.4f), 1.0 / 3.0);
}

// And one whose few samples agree (all on the dark background, or all on the surface) is not
// taken as precise for that: below 16 samples an outline pixel's variance is at least its
// neighbours' (denoise_prepare.comp). Measured: 0.064x the squared error shown (0.99x without).
TEST(Denoise, AnOutlinePixelWhoseFewSamplesAgreeIsStillFiltered) {
  EXPECT_LT(outline_error_left(0.01f), 0.5);
}

// A glint: a thin line of pixels far brighter than the surface around it, on 64 samples of a
// large spread (a highlight only some paths find), which pin its value down all the same, on
// `scene` (two cards). Returns the share of the line's shown luminance the denoiser keeps and
// the surface's squared error after the filter over before it (the left card away from the line).
struct GlintKept {
  double line = 0.0, surface = 0.0;
};
GlintKept glint_kept(const Scene& scene) {
  constexpr float kSurface = 0.3f, kGlint = 1.5f, kGlintDeviation = 1.2f;
  constexpr uint32_t kSamples = 64;
  Renderer renderer(test::context(), scene, test::render_settings(kSize, kSize, 8, 4, 0));
  // Shown to within 0.05, as 64 samples of spread 0.4 are.
  std::vector<SyntheticPixel> pixels = noisy(kSurface, 0.1f, 17);
  for (SyntheticPixel& p : pixels) {
    p.samples = kSamples;
    p.deviation = 0.4f;
  }
  std::mt19937 rng(23);
  std::normal_distribution<float> glint_noise(0.0f, kGlintDeviation / std::sqrt(float(kSamples)));
  std::vector<size_t> glint;
  for (size_t y = 4; y < kSize - 4; ++y) glint.push_back(y * kSize + 8);  // on the left card
  for (size_t i : glint) {
    pixels[i].shown = glm::vec3(kGlint + glint_noise(rng));
    pixels[i].deviation = kGlintDeviation;
  }
  write_display(renderer, pixels);
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  double shown = 0.0, kept = 0.0;
  for (size_t i : glint) {
    shown += pixels[i].shown.y;
    kept += denoised.rgb[3 * i + 1];
  }
  double surface_shown = 0.0, surface_filtered = 0.0;
  for (size_t i = 0; i < pixels.size(); ++i) {
    const size_t x = i % kSize;
    if (x < kSize / 2 && (x < 6 || x > 10)) {  // the left card away from the glint
      surface_shown += std::pow(pixels[i].shown.y - kSurface, 2.0);
      surface_filtered += std::pow(denoised.rgb[3 * i + 1] - kSurface, 2.0);
    }
  }
  return {kept / shown, surface_filtered / surface_shown};
}

// The blend's window weighs each pixel as relMSE does, and a hundred dim pixels outweigh the
// line: the filter dimmed it (ClearCoatTest's highlights at 64 spp: 0.25 shown as 0.08). A pixel
// whose own value lies further from the filtered one than its noise explains now shows at most
// Var / (f - r)^2 of the filtered value (denoise_blend.comp, own_weight). Measured: the line
// keeps 94.1 % of its samples' mean (90.1 % without the rule); the surface around it keeps 0.36x
// its squared error (0.12x without: a pixel whose noise happens to lie beyond one standard
// error is filtered less too).
TEST(Denoise, AGlintItsSamplesPinDownIsNotDimmed) {
  const GlintKept kept = glint_kept(two_cards());
  EXPECT_GT(kept.line, 0.93) << "the glint was dimmed";
  EXPECT_LT(kept.surface, 0.5) << "the surface was not filtered";
}

// The same white glint on a deep blue surface. The filter works on radiance divided by the
// albedo, where white light is mostly red and green; the variance of what is shown is that of
// the radiance, which the channels' own spreads tell on 32 samples or more
// (denoise_prepare.comp, sample_variance's toRadiance). Taken as the demodulated variance times
// the albedo's luminance squared, right for grey light only, the line's standard error read 2.1x
// too high and the filter dimmed it. Measured: the line keeps 94.1 % of its mean, as on the grey
// cards (88.6 % before); the surface's white noise, read 2.1x too high as well, was filtered to
// 0.065x its squared error, 0.36x now.
TEST(Denoise, AWhiteGlintOnAColouredSurfaceIsNotDimmed) {
  Scene scene = two_cards();
  for (Material& m : scene.materials) m.params.base_color = glm::vec3(0.05f, 0.05f, 0.9f);
  const GlintKept kept = glint_kept(scene);
  EXPECT_GT(kept.line, 0.93) << "the glint was dimmed";
  EXPECT_LT(kept.surface, 0.5) << "the surface was not filtered";
}

}  // namespace
}  // namespace hipr
