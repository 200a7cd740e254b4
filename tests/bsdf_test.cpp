// BSDF lobes on the CPU, compiled from the same GLSL-style headers the kernels include.
#include <gtest/gtest.h>

#include "bsdf_stats.h"

namespace hipr::shader {
using namespace glm;
#include "shaders/bsdf/lambert.glsl"
}  // namespace hipr::shader

namespace hipr {
namespace {

test::SampleFn lambert_sampler() {
  return [](glm::vec2 u, float) -> std::optional<test::DirectionSample> {
    const glm::vec3 d = shader::lambert_sample_local(u);
    const float pdf = shader::lambert_pdf(d.z);
    if (!(pdf > 0.0f)) return std::nullopt;
    return test::DirectionSample{d, glm::vec3(shader::lambert_eval_cos(d.z) / pdf)};
  };
}

TEST(StatisticsHelpers, GammaQMatchesKnownChiSquareValues) {
  // Chi-square survival function: P(X > x) for dof k is Q(k/2, x/2).
  EXPECT_NEAR(test::gamma_q(0.5, 3.841459 / 2), 0.05, 1e-5);   // k = 1, 95th percentile
  EXPECT_NEAR(test::gamma_q(5.0, 18.307038 / 2), 0.05, 1e-5);  // k = 10
  EXPECT_NEAR(test::gamma_q(50.0, 124.342 / 2), 0.05, 1e-4);   // k = 100
}

TEST(StatisticsHelpers, ChiSquareRejectsAWrongPdf) {
  // Cosine samples judged against a uniform-hemisphere pdf must fail.
  const auto uniform_pdf = [](glm::vec3 d) { return d.z > 0.0f ? float(0.5 / M_PI) : 0.0f; };
  EXPECT_LT(test::chi_square_sphere(lambert_sampler(), uniform_pdf).p_value, 1e-6);
}

TEST(Lambert, SamplesFollowThePdf) {
  const auto result = test::chi_square_sphere(lambert_sampler(),
                                              [](glm::vec3 d) { return shader::lambert_pdf(d.z); });
  EXPECT_GT(result.p_value, 0.01) << "chi2 " << result.statistic << " dof "
                                  << result.degrees_of_freedom;
  EXPECT_NEAR(result.pdf_integral, 1.0, 1e-3);
  EXPECT_EQ(result.sampled_fraction, 1.0);
}

TEST(Lambert, WhiteFurnaceAlbedoIsOne) {
  const glm::dvec3 a = test::albedo(lambert_sampler());
  EXPECT_NEAR(a.x, 1.0, 1e-6);  // cosine sampling makes every weight exactly the albedo
}

TEST(Lambert, NoNaNAtGrazingAndDegenerateInputs) {
  for (float c : {-1.0f, -0.0f, 0.0f, 1e-30f, 1e-7f, 1.0f}) {
    EXPECT_TRUE(std::isfinite(shader::lambert_eval_cos(c)));
    EXPECT_GE(shader::lambert_pdf(c), 0.0f);
  }
  for (glm::vec2 u : {glm::vec2(0.0f), glm::vec2(1.0f), glm::vec2(0.5f), glm::vec2(0.0f, 1.0f),
                      glm::vec2(0.99999994f)}) {
    const glm::vec3 d = shader::lambert_sample_local(u);
    EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z));
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    EXPECT_GE(d.z, 0.0f);
  }
}

}  // namespace
}  // namespace hipr
