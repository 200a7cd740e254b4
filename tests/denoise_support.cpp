#include "denoise_support.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "card_scene.h"
#include "render/render_state.h"

namespace hipr::test {

DenoiseSettings denoise_on() {
  DenoiseSettings s;
  s.enabled = true;
  return s;
}

Scene two_cards() {
  Scene scene = make_card_camera_scene(1.0f);
  const glm::mat4 half = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 1.0f, 1.0f));
  add_card(scene, "left", glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f, 0, 0)) * half,
           default_material_params());
  add_card(scene, "right", glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0, 0)) * half,
           default_material_params());
  return scene;
}

void write_display(Renderer& renderer, const std::vector<SyntheticPixel>& pixels) {
  RenderState& state = *renderer.render_state();
  std::vector<abi::DisplayTexel> texels(pixels.size());
  std::vector<abi::PixelAccum> accum(pixels.size());
  for (size_t i = 0; i < pixels.size(); ++i) {
    const SyntheticPixel& p = pixels[i];
    abi::DisplayTexel& t = texels[i];
    t.shown = p.shown;
    t.stale = p.stale.value_or(p.shown);
    t.shownSamples = t.staleSamples = p.samples;
    t.shownRecord = t.staleRecord = abi::kRecordUnknown;
    t.shownNormal = t.staleNormal = abi::kNormalUnknown;
    t.flags = p.current ? abi::kShownCurrent : 0u;
    if (p.relitBy > 0.0f)
      t.flags = abi::kShownGrouped | abi::kStaleGrouped | abi::kShownCurrent | abi::kStaleCurrent;
    t.screenNoise = 1.0f;
    const uint32_t count = p.fresh > 0u ? p.fresh : p.samples;
    const float n = float(count);
    const glm::vec3 mean = p.relitBy > 0.0f ? p.shown / p.relitBy : p.shown;
    accum[i].sum = mean * n;
    accum[i].count = p.relitBy > 0.0f ? count | abi::kPixelOwed : p.current ? count : 0u;
    // sum of squares = n (mean^2 + variance (n - 1) / n): the sample variance is deviation^2.
    accum[i].sumSquares = n * mean * mean + glm::vec3((n - 1.0f) * p.deviation * p.deviation);
  }
  state.resolve.display.upload(texels.data(), texels.size() * sizeof(abi::DisplayTexel));
  state.film.accumulation.upload(accum.data(), accum.size() * sizeof(abi::PixelAccum));
}

std::vector<SyntheticPixel> noisy(float value, float deviation, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> normal(0.0f, deviation / 2.0f);  // 4 samples: sd / 2
  std::vector<SyntheticPixel> pixels(kSize * kSize);
  for (SyntheticPixel& p : pixels) {
    p.shown = glm::vec3(std::max(value + normal(rng), 0.0f));
    p.deviation = deviation;
  }
  return pixels;
}

}  // namespace hipr::test
