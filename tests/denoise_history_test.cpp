// The denoised display's history (denoise_temporal.comp): a view converging sample by sample is
// steadier from frame to frame with it, at little cost against the reference; nothing of the
// last frame is kept across a change, and a precise pixel shows its own filtered value, whatever
// the last frame showed.
#include <gtest/gtest.h>

#include <cmath>

#include "denoise_support.h"
#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "image/error_metrics.h"
#include "test_support.h"

namespace hipr {
namespace {

using test::denoise_on;
using test::kSize;
using test::noisy;
using test::SyntheticPixel;
using test::two_cards;
using test::write_display;

// Mean absolute difference of two images' luminance: how much a frame moved from the last.
double mean_change(const ImageRGB& a, const ImageRGB& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.rgb.size(); i += 3)
    sum += std::abs(0.2126 * (a.rgb[i] - b.rgb[i]) + 0.7152 * (a.rgb[i + 1] - b.rgb[i + 1]) +
                    0.0722 * (a.rgb[i + 2] - b.rgb[i + 2]));
  return sum / double(a.rgb.size() / 3);
}

// The Cornell box converging a sample a frame, filtered after each: the same samples in two
// renderers, one keeping history, the other not. Measured (48 x 48, frames 5-16): 1.9x less
// change between frames (mean absolute luminance; FLIP at 128 x 128: 2.9x), the last frame's
// relMSE within 10 % of the history-free one's.
TEST(DenoiseHistory, AConvergingViewIsSteadierFromFrameToFrame) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  Renderer steady(test::context(), scene, test::render_settings(48, 48, 8, 4, 3));
  Renderer plain(test::context(), scene, test::render_settings(48, 48, 8, 4, 3));
  Renderer reference(test::context(), scene, test::render_settings(48, 48, 8, 4, 11));
  reference.add_samples_full_frame(256);
  double steady_change = 0.0, plain_change = 0.0;
  ImageRGB last_steady, last_plain;
  for (uint32_t frame = 1; frame <= 16; ++frame) {
    for (Renderer* renderer : {&steady, &plain}) {
      renderer->add_samples_full_frame(1);
      renderer->resolve_display_all(DisplayRule::Immediate);
    }
    ImageRGB now_steady = steady.denoised_image(denoise_on());
    ImageRGB now_plain = plain.denoised_image(without_history(denoise_on()));
    if (frame > 4) {
      steady_change += mean_change(now_steady, last_steady);
      plain_change += mean_change(now_plain, last_plain);
    }
    last_steady = std::move(now_steady);
    last_plain = std::move(now_plain);
  }
  EXPECT_LT(steady_change, plain_change / 1.5) << steady_change << " against " << plain_change;
  const double steady_error = relmse(last_steady, reference.image());
  const double plain_error = relmse(last_plain, reference.image());
  EXPECT_LT(steady_error, 1.1 * plain_error) << steady_error << " against " << plain_error;
  EXPECT_TRUE(test::all_finite(last_steady));
}

// Two frames of noise on the cards, the second with more samples: it keeps part of the first.
// After a change (here the view, moved to where it was: the guides are traced again), the frame
// is its own filter alone, bit for bit.
TEST(DenoiseHistory, NothingOfTheLastFrameIsKeptAcrossAChange) {
  const Scene scene = two_cards();
  Renderer renderer(test::context(), scene, test::render_settings(kSize, kSize, 8, 4, 0));
  Renderer alone(test::context(), scene, test::render_settings(kSize, kSize, 8, 4, 0));
  write_display(renderer, noisy(0.5f, 0.4f, 1));
  renderer.denoised_image(denoise_on());
  std::vector<SyntheticPixel> second = noisy(0.5f, 0.4f, 2);
  for (SyntheticPixel& p : second) p.samples = 8;
  write_display(renderer, second);
  write_display(alone, second);
  const ImageRGB own_filter = alone.denoised_image(denoise_on());
  EXPECT_NE(renderer.denoised_image(denoise_on()).rgb, own_filter.rgb) << "no history kept";

  write_display(renderer, noisy(0.5f, 0.4f, 1));
  renderer.denoised_image(denoise_on());
  ChangeSet changes;
  changes.camera = true;
  renderer.update_scene(scene, changes);
  write_display(renderer, second);
  EXPECT_EQ(renderer.denoised_image(denoise_on()).rgb, own_filter.rgb);
}

// A precise pixel shows its own value within two of its standard errors (0.4 / 1024 here),
// although the last frame showed another and it gained only a few samples since (which would
// keep 0.8^4 of the last value: 0.48 instead of 0.61).
TEST(DenoiseHistory, APrecisePixelShowsItsOwnValue) {
  Renderer renderer(test::context(), two_cards(), test::render_settings(kSize, kSize, 8, 4, 0));
  const size_t precise = 10 * kSize + 8;
  std::vector<SyntheticPixel> first = noisy(0.5f, 0.4f, 3), second = noisy(0.5f, 0.4f, 4);
  first[precise].shown = glm::vec3(0.3f);
  first[precise].samples = 1u << 20;
  second[precise].shown = glm::vec3(0.61f, 0.52f, 0.43f);
  second[precise].samples = (1u << 20) + 4u;
  for (SyntheticPixel& p : second) p.samples = std::max(p.samples, 5u);
  write_display(renderer, first);
  renderer.denoised_image(denoise_on());
  write_display(renderer, second);
  const ImageRGB shown = renderer.displayed_image();
  const ImageRGB denoised = renderer.denoised_image(denoise_on());
  for (size_t c = 0; c < 3; ++c)
    EXPECT_NEAR(denoised.rgb[3 * precise + c], shown.rgb[3 * precise + c], 2.0f * 0.4f / 1024.0f)
        << c;
}

}  // namespace
}  // namespace hipr
