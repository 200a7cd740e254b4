#pragma once
// What the display denoiser's tests share: a view of two cards, displays written directly
// (values, their samples and noise, stale or fresh), noisy and settings helpers.
#include <cstdint>
#include <optional>
#include <vector>

#include "hipr/denoise.h"
#include "hipr/renderer.h"
#include "hipr/scene.h"

namespace hipr::test {

inline constexpr uint32_t kSize = 32;  // the synthetic displays' width and height

DenoiseSettings denoise_on();

// Two cards side by side filling the view, each its own surface (G-buffer record): the left
// one on x < 0, the right one on x > 0.
Scene two_cards();

// A display written directly: per pixel the value shown, whether it is of the scene since the
// last edit, and behind it `samples` samples of standard deviation `deviation` (the
// accumulation's sums say so, as if they had been rendered).
struct SyntheticPixel {
  glm::vec3 shown{0.0f};
  bool current = true;
  uint32_t samples = 4;    // behind what is shown (DisplayTexel::shownSamples)
  float deviation = 0.5f;  // of one sample, in the accumulation
  uint32_t fresh = 0;      // samples in the accumulation, when fewer than `samples` (0: as many)
  // The stale estimate (of the scene before the last edit), where it is not `shown`: a current
  // pixel whose stale estimate is what it shows found no change since the edit.
  std::optional<glm::vec3> stale;
  // Above 0: the pixel shows its stale estimate relit by this factor (relight.comp), from the
  // samples still in the accumulation, of the scene before the edit (owed), `deviation` theirs.
  float relitBy = 0.0f;
};

void write_display(Renderer& renderer, const std::vector<SyntheticPixel>& pixels);

// kSize x kSize pixels of white noise around `value` (seeded), as a render's 4-sample pixels
// scatter around their mean.
std::vector<SyntheticPixel> noisy(float value, float deviation, uint32_t seed);

}  // namespace hipr::test
