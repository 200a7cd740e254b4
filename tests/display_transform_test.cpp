// The display transform (image/tonemap.h, image/auto_exposure.h): the tone mappers against
// their published definitions, the clamp mapper against the project's original display, and
// automatic exposure on a white floor under the studio and under the daylight sky.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <random>

#include "core/error.h"
#include "image/auto_exposure.h"
#include "image/builtin_environments.h"
#include "image/tonemap.h"
#include "shaders/shared/bindings/exposure.h"
#include "test_support.h"

namespace hipr {
namespace {

struct Published {
  ToneMapper mapper;
  glm::vec3 in, out;
};

// Evaluated in double precision, outside this code base, from each mapper's published
// definition (the formulas and constants named in shaders/common/tone_mappers.glsl):
//   pbr-neutral: the specification's f, p, p_n and g; e.g. 0.18 grey: x = 0.18 > 2 F90, so
//   f = F90 = 0.04 and the output is 0.14, below K_s (no compression).
//   aces: M_out * RRTAndODTFit(M_in * c), clamped. agx: outset * contrast(normalized log2(inset
//   * c)), then ^2.2.
const Published kPublished[] = {
    {ToneMapper::PbrNeutral, {0.18f, 0.18f, 0.18f}, {0.140000f, 0.140000f, 0.140000f}},
    {ToneMapper::PbrNeutral, {0.5f, 0.3f, 0.1f}, {0.460000f, 0.260000f, 0.060000f}},
    {ToneMapper::PbrNeutral, {1.0f, 1.0f, 1.0f}, {0.869091f, 0.869091f, 0.869091f}},
    {ToneMapper::PbrNeutral, {4.0f, 2.0f, 0.5f}, {0.983256f, 0.639951f, 0.382473f}},
    {ToneMapper::PbrNeutral, {0.02f, 0.05f, 0.01f}, {0.010625f, 0.040625f, 0.000625f}},
    {ToneMapper::PbrNeutral, {16.0f, 16.0f, 16.0f}, {0.996269f, 0.996269f, 0.996269f}},
    {ToneMapper::Agx, {0.18f, 0.18f, 0.18f}, {0.214467f, 0.214533f, 0.214537f}},
    {ToneMapper::Agx, {0.5f, 0.3f, 0.1f}, {0.442067f, 0.318233f, 0.145779f}},
    {ToneMapper::Agx, {1.0f, 1.0f, 1.0f}, {0.589977f, 0.590207f, 0.590221f}},
    {ToneMapper::Agx, {4.0f, 2.0f, 0.5f}, {0.891026f, 0.757789f, 0.493517f}},
    {ToneMapper::Agx, {0.02f, 0.05f, 0.01f}, {0.019105f, 0.064142f, 0.007246f}},
    {ToneMapper::Agx, {16.0f, 16.0f, 16.0f}, {0.994749f, 0.995202f, 0.995231f}},
    {ToneMapper::Aces, {0.18f, 0.18f, 0.18f}, {0.105591f, 0.105591f, 0.105590f}},
    {ToneMapper::Aces, {0.5f, 0.3f, 0.1f}, {0.367585f, 0.216310f, 0.058775f}},
    {ToneMapper::Aces, {1.0f, 1.0f, 1.0f}, {0.619115f, 0.619115f, 0.619109f}},
    {ToneMapper::Aces, {4.0f, 2.0f, 0.5f}, {0.936928f, 0.811187f, 0.522419f}},
    {ToneMapper::Aces, {0.02f, 0.05f, 0.01f}, {0.003078f, 0.013320f, 0.001426f}},
    {ToneMapper::Aces, {16.0f, 16.0f, 16.0f}, {0.989935f, 0.989935f, 0.989925f}},
};

TEST(ToneMappers, MatchTheirPublishedDefinitions) {
  for (const Published& p : kPublished) {
    const glm::vec3 out = tone_map(p.in, p.mapper);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(out[c], p.out[c], 1e-4f) << tone_mapper_name(p.mapper) << " (" << p.in.x << ", "
                                           << p.in.y << ", " << p.in.z << ") channel " << c;
  }
}

TEST(ToneMappers, NonFiniteAndNegativeInputShowsBlackNeverNaN) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (ToneMapper mapper : tone_mappers()) {
    for (const glm::vec3 in : {glm::vec3(nan, 0.5f, inf), glm::vec3(-inf, -1.0f, 0.0f),
                               glm::vec3(0.0f), glm::vec3(1e30f)}) {
      const glm::vec3 out = tone_map(in, mapper);
      for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(std::isfinite(out[c])) << tone_mapper_name(mapper);
        EXPECT_GE(out[c], 0.0f);
        EXPECT_LE(out[c], 1.0f);
      }
    }
    EXPECT_EQ(tone_map(glm::vec3(nan, -1.0f, inf), mapper).x, tone_map(glm::vec3(0.0f), mapper).x);
  }
}

TEST(ToneMappers, GreyRampsRiseAndNeverReachPastWhite) {
  for (ToneMapper mapper : tone_mappers()) {
    float last = -1.0f;
    for (float v = 1e-4f; v < 1e4f; v *= 1.25f) {
      const float out = tone_map(glm::vec3(v), mapper).g;
      EXPECT_GE(out, last) << tone_mapper_name(mapper) << " at " << v;
      last = out;
    }
    EXPECT_GT(last, 0.95f) << tone_mapper_name(mapper) << ": very bright greys show near white";
  }
}

TEST(ToneMappers, ClampIsTheOriginalDisplayByteForByte) {
  std::vector<float> rgb;
  for (float v = -0.5f; v < 3.0f; v += 0.0137f) rgb.push_back(v);
  rgb.resize(rgb.size() / 3 * 3);
  for (float ev : {0.0f, -2.5f, 1.0f}) {
    const std::vector<uint8_t> bytes = tonemap_srgb8(rgb, DisplayTransform{ev, ToneMapper::Clamp});
    for (size_t i = 0; i < rgb.size(); ++i)
      ASSERT_EQ(bytes[i], uint8_t(std::lround(srgb_encode(rgb[i] * std::exp2(ev)) * 255.0f)));
  }
}

TEST(ToneMappers, NamesRoundTripAndAnUnknownOneIsAnInputError) {
  for (ToneMapper mapper : tone_mappers())
    EXPECT_EQ(parse_tone_mapper(tone_mapper_name(mapper)), mapper);
  EXPECT_EQ(tone_mappers().size(), 4u);
  try {
    parse_tone_mapper("filmic");
    FAIL() << "an unknown mapper was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pbr-neutral"), std::string::npos) << e.what();
  }
}

// ---- Automatic exposure

TEST(AutoExposure, PutsTheNinetiethPercentileAtEightyPercentOfWhite) {
  std::vector<float> rgb;
  for (int i = 0; i < 100; ++i) {
    const float y = 0.01f * float(i + 1);  // luminances 0.01 .. 1.00 (grey: Y = the value)
    rgb.insert(rgb.end(), {y, y, y});
  }
  const float ev = metered_exposure_ev(rgb);
  EXPECT_NEAR(ev, std::log2(0.8f / 0.91f), 1e-4f);  // rank 90 of 100 (0-based)
}

TEST(AutoExposure, IgnoresBlackAndNonFinitePixelsAndStaysInRange) {
  EXPECT_EQ(metered_exposure_ev({}), 0.0f);
  EXPECT_EQ(metered_exposure_ev({0.0f, 0.0f, 0.0f}), 0.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NEAR(metered_exposure_ev({nan, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f, 2.0f, 2.0f, 2.0f}),
              std::log2(0.8f / 2.0f), 1e-5f);
  EXPECT_EQ(metered_exposure_ev({1e-30f, 1e-30f, 1e-30f}), kMaxExposureEv);
  EXPECT_EQ(metered_exposure_ev({1e30f, 1e30f, 1e30f}), kMinExposureEv);
}

// The device's meter (render/exposure_meter.h) bins log2 luminances by 1/16 of a stop; read
// from the bins, the rule meters within half a bin of the pixels' own percentile.
TEST(AutoExposure, AHistogramOfLog2LuminancesMetersAsThePixelsDo) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> stops(-12.0f, 6.0f);
  for (int image = 0; image < 20; ++image) {
    LuminanceHistogram histogram{std::vector<uint32_t>(abi::kMeterBins, 0u),
                                 float(abi::kMeterLowestStop), float(abi::kMeterBinsPerStop)};
    std::vector<float> rgb;
    for (int i = 0; i < 500; ++i) {
      const float y = std::exp2(stops(rng));
      rgb.insert(rgb.end(), {y, y, y});
      ++histogram.counts[size_t(
          std::floor((std::log2(y) - histogram.lowest_stop) * histogram.bins_per_stop))];
    }
    EXPECT_NEAR(histogram_exposure_ev(histogram), metered_exposure_ev(rgb),
                0.5f / histogram.bins_per_stop + 1e-5f);
  }
  EXPECT_EQ(histogram_exposure_ev({std::vector<uint32_t>(abi::kMeterBins, 0u),
                                   float(abi::kMeterLowestStop), float(abi::kMeterBinsPerStop)}),
            0.0f);
}

// A white (0.8) diffuse floor reaching to the horizon under each built-in environment, the
// camera looking slightly down (the floor below, the environment above): metered, it shows
// well exposed (neither grey nor clipped) through the viewer's default mapper, although the
// studio and the sky differ by thousands in brightness.
TEST(AutoExposure, AWhiteFloorOpensWellExposedUnderTheStudioAndTheSky) {
  float exposures[2];
  for (int e = 0; e < 2; ++e) {
    Scene scene = test::make_furnace_scene(1.0f, glm::vec3(0.0f), 0.8f, 1.0f);
    scene.nodes[0].local = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -1001.0f, 0.0f)) *
                           glm::scale(glm::mat4(1.0f), glm::vec3(1000.0f));
    scene.nodes[1].local = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 4.0f)),
                                       glm::radians(-15.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    scene.environment = e == 0 ? make_studio_environment() : make_sky_environment(SkyParameters{});
    RenderSettings s;
    s.width = s.height = 32;
    s.max_depth = 4;
    const ImageRGB image = test::render_finite(scene, s, 16);
    const float ev = metered_exposure_ev(image.rgb);
    exposures[e] = ev;
    // The floor: the bottom quarter of the frame, well below the horizon.
    double shown = 0.0;
    for (uint32_t y = 24; y < 32; ++y)
      for (uint32_t x = 0; x < 32; ++x) {
        const float* p = &image.rgb[(size_t(y) * 32 + x) * 3];
        shown += tone_map(glm::vec3(p[0], p[1], p[2]) * std::exp2(ev), ToneMapper::PbrNeutral).g;
      }
    shown /= 8.0 * 32.0;
    EXPECT_GT(shown, 0.5) << (e ? "sky" : "studio") << ": the white floor shows grey";
    EXPECT_LT(shown, 0.97) << (e ? "sky" : "studio") << ": the white floor clips";
  }
  EXPECT_GT(exposures[0] - exposures[1], 8.0f) << "the sky needs far less exposure";
}

}  // namespace
}  // namespace hipr
