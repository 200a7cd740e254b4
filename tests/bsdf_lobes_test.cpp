// The stand-alone OpenPBR lobes (EON diffuse, fuzz, thin film) on the CPU, compiled from the
// same GLSL-style headers the kernels include.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bsdf_stats.h"

namespace hipr::shader {
using namespace glm;
#include "shaders/bsdf/eon.glsl"
#include "shaders/bsdf/fuzz_layer.glsl"
#include "shaders/bsdf/lambert.glsl"
#include "shaders/bsdf/thin_film.glsl"
}  // namespace hipr::shader

namespace hipr {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::vec3 direction(float theta) { return glm::vec3(std::sin(theta), 0.0f, std::cos(theta)); }

// Directions off the plane of wo, so phi-dependent terms are exercised.
glm::vec3 skew_direction(float theta, float phi) {
  return glm::vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                   std::cos(theta));
}

// A lobe seen from wo through the sampler interface of bsdf_stats.h.
template <class Eval, class Pdf, class Sample>
test::SampleFn lobe_sampler(Eval eval, Pdf pdf, Sample sample) {
  return [=](glm::vec2 u, float) -> std::optional<test::DirectionSample> {
    const glm::vec3 wi = sample(u);
    const float p = pdf(wi);
    if (!(p > 0.0f)) return std::nullopt;
    return test::DirectionSample{wi, eval(wi) / p};
  };
}

test::SampleFn eon_sampler(glm::vec3 rho, float roughness, glm::vec3 wo) {
  return lobe_sampler([=](glm::vec3 wi) { return shader::eon_eval_cos(rho, roughness, wo, wi); },
                      [=](glm::vec3 wi) { return shader::eon_pdf(roughness, wo, wi); },
                      [=](glm::vec2 u) { return shader::eon_sample(roughness, wo, u); });
}

test::SampleFn fuzz_sampler(float roughness, glm::vec3 wo) {
  return lobe_sampler(
      [=](glm::vec3 wi) { return glm::vec3(shader::fuzz_eval_cos(roughness, wo, wi)); },
      [=](glm::vec3 wi) { return shader::fuzz_pdf(roughness, wo, wi); },
      [=](glm::vec2 u) { return shader::fuzz_sample(roughness, wo, u); });
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// These lobes never reject a sample, so their pdfs integrate to 1.
void expect_samples_follow_pdf(const test::SampleFn& sampler, const test::PdfFn& pdf) {
  const auto result = test::chi_square_sphere(sampler, pdf, 100000);
  EXPECT_GT(result.p_value, 0.001)
      << "chi2 " << result.statistic << " dof " << result.degrees_of_freedom;
  EXPECT_NEAR(result.pdf_integral, 1.0, 2e-3);
  EXPECT_EQ(result.sampled_fraction, 1.0);
}

// ---------------------------------------------------------------------------------------------
// EON

class EonFit : public ::testing::TestWithParam<std::tuple<float, float>> {};

TEST_P(EonFit, SamplesFollowThePdf) {
  const auto [roughness, theta] = GetParam();
  const glm::vec3 wo = direction(theta);
  expect_samples_follow_pdf(eon_sampler(glm::vec3(0.8f), roughness, wo),
                            [&](glm::vec3 wi) { return shader::eon_pdf(roughness, wo, wi); });
}

INSTANTIATE_TEST_SUITE_P(Params, EonFit,
                         ::testing::Combine(::testing::Values(0.0f, 0.2f, 0.5f, 1.0f),
                                            ::testing::Values(0.0f, 1.0f, 1.5f)));

// The largest sample weight on a fixed stratified grid of 64 x 64 samples.
float highest_weight(const test::SampleFn& sampler) {
  float highest = 0.0f;
  for (int i = 0; i < 4096; ++i) {
    const auto s = sampler(glm::vec2((i % 64 + 0.5f) / 64, (i / 64 + 0.5f) / 64), 0.0f);
    if (s) highest = std::max(highest, s->weight.x);
  }
  return highest;
}

// The point of the CLTC sampler: weights of a white surface stay near its albedo (cosine
// sampling reaches 15 at grazing for roughness 1, with 16 times the variance).
TEST(Eon, SamplingWeightsStayBounded) {
  for (float roughness : {0.1f, 0.5f, 1.0f})
    for (float theta : {0.0f, 0.7f, 1.2f, 1.5f, 1.565f})
      EXPECT_LT(highest_weight(eon_sampler(glm::vec3(1.0f), roughness, direction(theta))), 5.0f)
          << "roughness " << roughness << " theta " << theta;
}

TEST(Eon, WhiteFurnaceAlbedoIsOneAtEveryRoughness) {
  for (float roughness : {0.0f, 0.5f, 1.0f})
    for (float theta : {0.0f, 0.5f, 1.0f, 1.3f, 1.5f}) {
      const glm::dvec3 a =
          test::albedo(eon_sampler(glm::vec3(1.0f), roughness, direction(theta)), 40000);
      EXPECT_NEAR(a.x, 1.0, 0.01) << "roughness " << roughness << " theta " << theta;
    }
}

TEST(Eon, AlbedoNeverExceedsOne) {
  for (float roughness = 0.0f; roughness <= 1.0f; roughness += 0.125f)
    for (float theta : {0.0f, 0.4f, 0.8f, 1.2f, 1.45f, 1.565f})
      for (float rho : {0.3f, 0.8f, 1.0f}) {
        const glm::vec3 wo = direction(theta);
        const double a = test::hemisphere_integral(
            [&](glm::vec3 wi) {
              return double(shader::eon_eval_cos(glm::vec3(rho), roughness, wo, wi).x);
            },
            96, 96);
        EXPECT_LE(a, 1.0 + 2e-3) << "rho " << rho << " roughness " << roughness << " theta "
                                 << theta;
        EXPECT_GE(a, 0.0);
      }
}

// The compensation is only as good as the closed-form albedo of Fujii's model it relies on:
// integrate that model (written out here independently) and compare.
TEST(Eon, ClosedFormFonAlbedoMatchesIntegration) {
  const auto fon_cos = [](float r, glm::vec3 wo, glm::vec3 wi) {
    const double a = 1.0 / (1.0 + (0.5 - 2.0 / (3.0 * kPi)) * r);
    const double s = double(glm::dot(wo, wi)) - double(wo.z) * wi.z;
    const double t = s > 0.0 ? std::max(wo.z, wi.z) : 1.0;
    return a * (1.0 + r * s / t) / kPi * wi.z;
  };
  for (float r : {0.25f, 0.6f, 1.0f}) {
    double average = 0.0;
    constexpr int kMuSteps = 48;
    for (int i = 0; i < kMuSteps; ++i) {
      const float mu = (i + 0.5f) / kMuSteps;
      const glm::vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
      const double e =
          test::hemisphere_integral([&](glm::vec3 wi) { return fon_cos(r, wo, wi); }, 128, 128);
      EXPECT_NEAR(shader::eon_fon_albedo(mu, r), e, 1e-3) << "r " << r << " mu " << mu;
      average += 2.0 * e * mu / kMuSteps;
    }
    const double closed_average = shader::eon_fon_a(r) * (1.0 + shader::kEonC2 * r);
    EXPECT_NEAR(closed_average, average, 1e-3) << "r " << r;
  }
}

TEST(Eon, ClosedFormAlbedoMatchesIntegration) {
  const glm::vec3 rho(0.9f, 0.5f, 0.1f);
  for (float roughness : {0.0f, 0.4f, 1.0f})
    for (float theta : {0.0f, 0.8f, 1.3f, 1.55f}) {
      const glm::vec3 wo = direction(theta);
      const glm::vec3 closed = shader::eon_albedo(rho, roughness, wo.z);
      for (int c = 0; c < 3; ++c) {
        const double integral = test::hemisphere_integral(
            [&](glm::vec3 wi) { return double(shader::eon_eval_cos(rho, roughness, wo, wi)[c]); },
            128, 128);
        EXPECT_NEAR(closed[c], integral, 1e-3)
            << "roughness " << roughness << " theta " << theta << " channel " << c;
      }
    }
}

TEST(Eon, Reciprocity) {
  const glm::vec3 rho(0.9f, 0.5f, 0.2f);
  for (float roughness : {0.3f, 1.0f})
    for (float a : {0.1f, 0.7f, 1.3f})
      for (float b : {0.2f, 0.9f, 1.5f})
        for (float phi : {0.0f, 1.0f, 3.0f}) {
          const glm::vec3 wo = direction(a), wi = skew_direction(b, phi);
          const glm::vec3 f1 = shader::eon_eval_cos(rho, roughness, wo, wi) / wi.z;
          const glm::vec3 f2 = shader::eon_eval_cos(rho, roughness, wi, wo) / wo.z;
          for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(f1[c], f2[c], 1e-5f) << roughness << " " << a << " " << b << " " << phi;
        }
}

TEST(Eon, RoughnessZeroIsExactlyLambert) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 rho(uniform(rng), uniform(rng), uniform(rng));
    const glm::vec3 wo = shader::sample_uniform_hemisphere(glm::vec2(uniform(rng), uniform(rng)));
    const glm::vec3 wi = shader::sample_uniform_hemisphere(glm::vec2(uniform(rng), uniform(rng)));
    if (wo.z <= 0.0f || wi.z <= 0.0f) continue;
    const glm::vec3 f = shader::eon_eval_cos(rho, 0.0f, wo, wi);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], rho[c] * wi.z / float(kPi), 1e-6f);
  }
}

TEST(Eon, FiniteAtGrazingAndExtremeInputs) {
  for (float roughness : {-1.0f, 0.0f, 1e-6f, 1.0f, 2.0f})
    for (float zo : {0.0f, 1e-30f, 1e-7f, 0.5f, 1.0f})
      for (float zi : {-0.1f, 0.0f, 1e-30f, 1e-7f, 1.0f})
        for (glm::vec3 rho : {glm::vec3(0.0f), glm::vec3(1.0f), glm::vec3(0.5f, 0.0f, 1.0f)}) {
          const glm::vec3 wo = glm::normalize(glm::vec3(std::sqrt(1.0f - zo * zo), 0.0f, zo));
          const glm::vec3 wi =
              glm::normalize(glm::vec3(-std::sqrt(std::max(0.0f, 1.0f - zi * zi)), 0.0f, zi));
          const glm::vec3 f = shader::eon_eval_cos(rho, roughness, wo, wi);
          EXPECT_TRUE(finite(f) && f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f)
              << roughness << " " << zo << " " << zi;
          EXPECT_TRUE(std::isfinite(shader::eon_pdf(roughness, wo, wi)));
        }
  for (float mu : {0.0f, 1e-30f, 1e-7f, 1.0f}) EXPECT_TRUE(std::isfinite(shader::eon_fon_loss(mu)));
  // Samples at the corners of the unit square, for wo from normal to grazing.
  for (float roughness : {0.0f, 0.5f, 1.0f})
    for (float theta : {0.0f, 1.0f, 1.5707f, 1.5708f})
      for (glm::vec2 u : {glm::vec2(0.0f), glm::vec2(0.99999994f), glm::vec2(0.0f, 0.99999994f),
                          glm::vec2(0.99999994f, 0.0f), glm::vec2(0.19999999f, 0.5f)}) {
        const glm::vec3 wo = direction(theta);
        const glm::vec3 wi = shader::eon_sample(roughness, wo, u);
        EXPECT_TRUE(finite(wi) && wi.z >= 0.0f)
            << roughness << " " << theta << " " << u.x << " " << u.y;
        EXPECT_NEAR(glm::length(wi), 1.0f, 1e-5f);
        EXPECT_TRUE(std::isfinite(shader::eon_pdf(roughness, wo, wi)));
      }
}

// ---------------------------------------------------------------------------------------------
// Fuzz

class FuzzFit : public ::testing::TestWithParam<std::tuple<float, float>> {};

TEST_P(FuzzFit, SamplesFollowThePdf) {
  const auto [roughness, theta] = GetParam();
  const glm::vec3 wo = direction(theta);
  expect_samples_follow_pdf(fuzz_sampler(roughness, wo),
                            [&](glm::vec3 wi) { return shader::fuzz_pdf(roughness, wo, wi); });
}

INSTANTIATE_TEST_SUITE_P(Params, FuzzFit,
                         ::testing::Combine(::testing::Values(0.3f, 1.0f),
                                            ::testing::Values(0.0f, 0.2f, 1.0f, 1.4f)));
// Smooth fuzz seen at grazing is a sliver along the horizon, finer than the sphere grid.
INSTANTIATE_TEST_SUITE_P(Smooth, FuzzFit,
                         ::testing::Combine(::testing::Values(0.1f),
                                            ::testing::Values(0.0f, 1.0f)));

// The LTC integrates to one above the horizon, so the lobe's albedo is the tabulated R, which
// fuzz_energy returns: the layering's budget is exactly what the lobe takes.
TEST(Fuzz, AlbedoIsTheTabulatedReflectance) {
  for (float roughness : {0.0f, 0.1f, 0.33f, 0.7f, 1.0f})
    for (float theta : {0.05f, 0.6f, 1.1f, 1.4f, 1.53f}) {
      const glm::vec3 wo = direction(theta);
      const double a = test::albedo(fuzz_sampler(roughness, wo), 40000).x;
      EXPECT_LE(a, 1.0) << "roughness " << roughness << " theta " << theta;
      EXPECT_NEAR(shader::fuzz_energy(wo.z, roughness), a, 0.002 + 0.005 * a)
          << "roughness " << roughness << " theta " << theta;
    }
}

// Sampling is exact (a cosine sample through the LTC's matrix): every sample weighs R.
TEST(Fuzz, SamplesWeighTheAlbedo) {
  for (float roughness : {0.0f, 0.3f, 1.0f})
    for (float theta : {0.0f, 0.8f, 1.3f, 1.5f, 1.565f}) {
      const glm::vec3 wo = direction(theta);
      EXPECT_NEAR(highest_weight(fuzz_sampler(roughness, wo)), shader::fuzz_energy(wo.z, roughness),
                  1e-3f)
          << "roughness " << roughness << " theta " << theta;
    }
}

// The lobe keeps its shape when wo turns about the normal.
TEST(Fuzz, TurnsWithTheViewAzimuth) {
  for (float roughness : {0.2f, 0.8f})
    for (float phi : {0.7f, 2.5f, 4.0f}) {
      const glm::vec3 wo = skew_direction(1.0f, 0.0f), wi = skew_direction(0.6f, 2.0f);
      const glm::vec3 wo_turned = skew_direction(1.0f, phi),
                      wi_turned = skew_direction(0.6f, 2.0f + phi);
      EXPECT_NEAR(shader::fuzz_eval_cos(roughness, wo, wi),
                  shader::fuzz_eval_cos(roughness, wo_turned, wi_turned), 1e-5f);
    }
}

TEST(Fuzz, FiniteAtTheRoughnessLimitsAndGrazing) {
  for (float roughness : {-1.0f, 0.0f, shader::kFuzzMinRoughness, 1.0f, 3.0f})
    for (float zo : {0.0f, 1e-30f, 1e-7f, 0.5f, 1.0f})
      for (float zi : {0.0f, 1e-30f, 1e-7f, 0.5f, 1.0f})
        for (float phi : {0.0f, 3.14159265f}) {
          const glm::vec3 wo = glm::normalize(glm::vec3(std::sqrt(1.0f - zo * zo), 0.0f, zo));
          const glm::vec3 wi = skew_direction(std::acos(zi), phi);
          const float f = shader::fuzz_eval_cos(roughness, wo, wi);
          EXPECT_TRUE(std::isfinite(f) && f >= 0.0f)
              << roughness << " " << zo << " " << zi << " " << phi;
          EXPECT_TRUE(std::isfinite(shader::fuzz_energy(zo, roughness)));
          const float scale = shader::fuzz_layer_scale(1.0f, roughness, zo);
          EXPECT_TRUE(scale >= 0.0f && scale <= 1.0f);
        }
}

// OpenPBR's fuzz over a white Lambertian base: the fuzz reflects w E(mu_o), the base what
// fuzz_layer_scale lets through, so the stack reflects all it receives.
TEST(Fuzz, LayeredOverWhiteLambertKeepsItsEnergy) {
  for (float weight : {0.5f, 1.0f})
    for (float roughness : {0.0f, 0.3f, 0.6f, 1.0f})
      for (float theta : {0.0f, 0.6f, 1.1f, 1.4f, 1.55f}) {
        const glm::vec3 wo = direction(theta);
        // Half the samples from the fuzz, half cosine-distributed (smooth fuzz seen at grazing is
        // a sliver along the horizon that a quadrature grid misses).
        const test::SampleFn stack = [&](glm::vec2 u,
                                         float u_lobe) -> std::optional<test::DirectionSample> {
          const glm::vec3 wi = u_lobe < 0.5f ? shader::fuzz_sample(roughness, wo, u)
                                             : shader::lambert_sample_local(u);
          const float pdf =
              0.5f * (shader::fuzz_pdf(roughness, wo, wi) + shader::lambert_pdf(wi.z));
          if (!(pdf > 0.0f)) return std::nullopt;
          const float f =
              weight * shader::fuzz_eval_cos(roughness, wo, wi) +
              shader::fuzz_layer_scale(weight, roughness, wo.z) * shader::lambert_eval_cos(wi.z);
          return test::DirectionSample{wi, glm::vec3(f / pdf)};
        };
        const double a = test::albedo(stack, 100000).x;
        EXPECT_NEAR(a, 1.0, 5e-3) << "weight " << weight << " roughness " << roughness << " theta "
                                  << theta;
      }
}

// ---------------------------------------------------------------------------------------------
// Thin film

TEST(ThinFilm, NoFilmIsThePlainInterface) {
  for (float base : {1.0f / 3.0f, 0.7f, 1.0f, 1.5f, 3.0f})
    for (int i = 0; i <= 200; ++i) {
      const float c = float(i) / 200;
      const float plain = shader::fresnel_dielectric(c, base);
      const glm::vec3 zero_thickness = shader::fresnel_thin_film(c, 1.8f, base, 0.0f);
      const glm::vec3 vacuum_film = shader::fresnel_thin_film(c, 1.0f, base, 380.0f);
      const glm::vec3 matched_film = shader::fresnel_thin_film(c, base, base, 380.0f);
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(zero_thickness[k], plain, 1e-4f) << "base " << base << " cos " << c;
        EXPECT_NEAR(vacuum_film[k], plain, 1e-4f) << "base " << base << " cos " << c;
        EXPECT_NEAR(matched_film[k], plain, 1e-4f) << "base " << base << " cos " << c;
      }
      const glm::vec3 unweighted = shader::fresnel_with_thin_film(c, base, 0.0f, 1.8f, 380.0f);
      EXPECT_EQ(unweighted, glm::vec3(plain));
    }
}

TEST(ThinFilm, ReflectanceStaysWithinZeroAndOne) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  float highest = 0.0f;
  for (int i = 0; i < 20000; ++i) {
    const float c = uniform(rng);
    const float film = 0.5f + 2.5f * uniform(rng);
    const float base = 0.3f + 2.7f * uniform(rng);
    const float thickness = 2000.0f * uniform(rng);
    const glm::vec3 r = shader::fresnel_thin_film(c, film, base, thickness);
    for (int k = 0; k < 3; ++k) {
      ASSERT_GE(r[k], 0.0f) << c << " " << film << " " << base << " " << thickness;
      ASSERT_LE(r[k], 1.0f + 1e-5f) << c << " " << film << " " << base << " " << thickness;
      highest = std::max(highest, r[k]);
    }
  }
  EXPECT_GT(highest, 0.5f);  // the inputs did reach strongly reflecting configurations
}

TEST(ThinFilm, QuarterWaveFilmIsAntiReflective) {
  // n_film = sqrt(n_base) and optical thickness lambda / 4: the two reflections have equal
  // amplitude and opposite phase at the design wavelength.
  const float base = 1.5f, film = std::sqrt(base);
  const float thickness = 532.0f / (4.0f * film);
  EXPECT_LT(shader::thin_film_reflectance(1.0f, film, base, thickness, 532.0f), 1e-3f);
  EXPECT_GT(shader::thin_film_reflectance(1.0f, film, base, thickness, 420.0f), 2e-3f);
  // A half-wave film of the same material is invisible at its design wavelength.
  EXPECT_NEAR(shader::thin_film_reflectance(1.0f, film, base, 2.0f * thickness, 532.0f),
              shader::fresnel_dielectric(1.0f, base), 1e-5f);
  // Over the spectrum the coating still removes most of the reflection, most of all in green.
  const glm::vec3 rgb = shader::fresnel_thin_film(1.0f, film, base, thickness);
  const float plain = shader::fresnel_dielectric(1.0f, base);
  EXPECT_LT(rgb.g, 0.1f * plain);
  EXPECT_LT(rgb.g, rgb.r);
  EXPECT_LT(rgb.g, rgb.b);
}

// CIE 1931 matching functions, Wyman, Sloan and Shirley's (2013) piecewise-Gaussian fit: an
// independent description of the eye to check the spectral integration against.
double cie_lobe(double lambda, double mean, double sigma_below, double sigma_above) {
  const double t = (lambda - mean) / (lambda < mean ? sigma_below : sigma_above);
  return std::exp(-0.5 * t * t);
}

glm::dvec3 cie_xyz(double lambda) {
  return glm::dvec3(
      1.056 * cie_lobe(lambda, 599.8, 37.9, 31.0) + 0.362 * cie_lobe(lambda, 442.0, 16.0, 26.7) -
          0.065 * cie_lobe(lambda, 501.1, 20.4, 26.2),
      0.821 * cie_lobe(lambda, 568.8, 46.9, 40.5) + 0.286 * cie_lobe(lambda, 530.9, 16.3, 31.1),
      1.217 * cie_lobe(lambda, 437.0, 11.8, 36.0) + 0.681 * cie_lobe(lambda, 459.0, 26.0, 13.8));
}

// XYZ of a spectrum by brute-force quadrature, each channel normalised by a flat spectrum.
template <class Spectrum>
glm::dvec3 integrate_spectrum(Spectrum spectrum) {
  glm::dvec3 sum(0.0), norm(0.0);
  for (int i = 0; i < 2000; ++i) {
    const double lambda = 360.0 + 470.0 * (i + 0.5) / 2000;
    sum += cie_xyz(lambda) * spectrum(lambda);
    norm += cie_xyz(lambda);
  }
  return sum / norm;
}

TEST(ThinFilm, SensitivityMatchesTheMatchingFunctions) {
  for (float opd : {0.0f, 150.0f, 400.0f, 800.0f, 1500.0f, 4000.0f})
    for (float shift : {0.0f, 1.0f, 2.5f}) {
      const glm::dvec3 reference = integrate_spectrum(
          [&](double lambda) { return std::cos(2.0 * kPi * opd / lambda + shift); });
      const glm::vec3 model = shader::thin_film_sensitivity(opd, shift);
      // Two independent fits of the same curves: they agree to a few percent.
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(model[c], reference[c], 0.07)
            << "opd " << opd << " shift " << shift << " channel " << c;
    }
}

// The Fourier-series integration against brute-force integration of the exact
// single-wavelength reflectance (mean difference 0.0014; sampling R, G and B at 650, 532 and
// 450 nm instead would differ by 0.02 on average and up to 0.47).
TEST(ThinFilm, RgbMatchesSpectralIntegration) {
  double worst = 0.0;
  for (float c : {1.0f, 0.7f, 0.3f, 0.05f})
    for (float film : {1.0f, 1.33f, 1.8f, 3.0f})
      for (float base : {1.0f / 1.5f, 1.5f, 2.4f})
        for (float thickness : {120.0f, 300.0f, 700.0f, 3000.0f}) {
          const glm::dvec3 xyz = integrate_spectrum([&](double lambda) {
            return double(shader::thin_film_reflectance(c, film, base, thickness, float(lambda)));
          });
          const glm::vec3 reference = glm::clamp(shader::thin_film_xyz_to_rgb(glm::vec3(xyz)),
                                                 glm::vec3(0.0f), glm::vec3(1.0f));
          const glm::vec3 rgb = shader::fresnel_thin_film(c, film, base, thickness);
          for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(rgb[k], reference[k], 0.05)
                << c << " " << film << " " << base << " " << thickness << " channel " << k;
            worst = std::max(worst, double(std::abs(rgb[k] - reference[k])));
          }
        }
  std::printf("largest RGB difference to brute-force spectral integration: %.4f\n", worst);
}

TEST(ThinFilm, ThickFilmsAverageToGrey) {
  // Far past the coherence length of visible light the colours wash out.
  const glm::vec3 rgb = shader::fresnel_thin_film(0.8f, 1.8f, 1.5f, 20000.0f);
  EXPECT_NEAR(rgb.r, rgb.g, 0.01f);
  EXPECT_NEAR(rgb.b, rgb.g, 0.01f);
  EXPECT_GT(rgb.g,
            shader::fresnel_dielectric(0.8f, 1.5f));  // the film's own interface adds reflection
}

TEST(ThinFilm, GrazingReflectsEverything) {
  for (float film : {1.0f, 1.3f, 2.5f})
    for (float base : {1.0f / 3.0f, 1.0f, 1.5f, 3.0f})
      for (float thickness : {0.0f, 250.0f, 1e4f}) {
        const glm::vec3 r = shader::fresnel_thin_film(0.0f, film, base, thickness);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(r[k], 1.0f);
        // Just above grazing it tends to 1 too, unless there is no interface at all (a base
        // of index 1 with no film, or with a film of index 1).
        if (base == 1.0f && (film == 1.0f || thickness == 0.0f)) continue;
        const glm::vec3 near = shader::fresnel_thin_film(1e-4f, film, base, thickness);
        for (int k = 0; k < 3; ++k)
          EXPECT_GT(near[k], 0.99f) << film << " " << base << " " << thickness;
      }
}

TEST(ThinFilm, FiniteAtExtremeInputs) {
  const auto check = [](glm::vec3 r) {
    return finite(r) && r.x >= 0.0f && r.y >= 0.0f && r.z >= 0.0f && r.x <= 1.0f + 1e-5f &&
           r.y <= 1.0f + 1e-5f && r.z <= 1.0f + 1e-5f;
  };
  for (float c : {-1.0f, 0.0f, 1e-30f, 1e-7f, 0.5f, 1.0f, 2.0f})
    for (float film : {0.0f, 1.0f, 1.0001f, 3.0f})
      for (float base : {0.0f, 1.0f / 3.0f, 1.0f, 1.0001f, 3.0f})
        for (float thickness : {-5.0f, 0.0f, 1e-3f, 1e4f}) {
          EXPECT_TRUE(check(shader::fresnel_thin_film(c, film, base, thickness)))
              << c << " " << film << " " << base << " " << thickness;
          // The blend also calls the plain fresnel_dielectric, which needs a positive index.
          if (base == 0.0f) continue;
          for (float weight : {0.0f, 0.5f, 1.0f})
            EXPECT_TRUE(check(shader::fresnel_with_thin_film(c, base, weight, film, thickness)))
                << c << " " << film << " " << base;
        }
}

TEST(ThinFilm, TotalInternalReflectionAtTheBaseIsComplete) {
  // Seen from inside glass (relative base index 1 / 1.5) past the critical angle, no film
  // changes the fact that everything is reflected.
  for (float film : {1.0f, 1.33f, 2.0f})
    for (float thickness : {100.0f, 400.0f}) {
      const glm::vec3 r = shader::fresnel_thin_film(0.5f, film, 1.0f / 1.5f, thickness);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(r[k], 1.0f, 1e-5f) << film << " " << thickness;
    }
}

}  // namespace
}  // namespace hipr
