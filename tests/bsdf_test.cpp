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
  EXPECT_NEAR(test::gamma_q(0.5, 3.841459 / 2), 0.05, 1e-5);  // k = 1, 95th percentile
  EXPECT_NEAR(test::gamma_q(5.0, 18.307038 / 2), 0.05, 1e-5);  // k = 10
  EXPECT_NEAR(test::gamma_q(50.0, 124.342 / 2), 0.05, 1e-4);   // k = 100
}

TEST(StatisticsHelpers, ChiSquareRejectsAWrongPdf) {
  // Cosine samples judged against a uniform-hemisphere pdf must fail.
  const auto uniform_pdf = [](glm::vec3 d) { return d.z > 0.0f ? float(0.5 / M_PI) : 0.0f; };
  EXPECT_LT(test::chi_square_sphere(lambert_sampler(), uniform_pdf).p_value, 1e-6);
}

TEST(Lambert, SamplesFollowThePdf) {
  const auto result = test::chi_square_sphere(lambert_sampler(), [](glm::vec3 d) { return shader::lambert_pdf(d.z); });
  EXPECT_GT(result.p_value, 0.01) << "chi2 " << result.statistic << " dof " << result.degrees_of_freedom;
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
  for (glm::vec2 u : {glm::vec2(0.0f), glm::vec2(1.0f), glm::vec2(0.5f), glm::vec2(0.0f, 1.0f), glm::vec2(0.99999994f)}) {
    const glm::vec3 d = shader::lambert_sample_local(u);
    EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z));
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    EXPECT_GE(d.z, 0.0f);
  }
}

}  // namespace
}  // namespace hipr

namespace hipr::shader {
#include "shaders/bsdf/openpbr_base.glsl"
}  // namespace hipr::shader

namespace hipr {
namespace {

// The base BSDF seen from direction wo, through the sampler interface of bsdf_stats.h.
test::SampleFn base_sampler(shader::BaseParams p, glm::vec3 wo) {
  return [p, wo](glm::vec2 u, float u_lobe) -> std::optional<test::DirectionSample> {
    glm::vec3 wi;
    if (shader::base_sample(p, wo, u, u_lobe, wi) < 0) return std::nullopt;
    const float pdf = shader::base_pdf(p, wo, wi);
    if (!(pdf > 0.0f)) return std::nullopt;
    return test::DirectionSample{wi, shader::base_eval_cos(p, wo, wi) / pdf};
  };
}

shader::BaseParams base_params(glm::vec3 color, float metalness, float roughness, float specular = 1.0f, float ior = 1.5f) {
  return {color, metalness, glm::vec3(1.0f), specular, ior, shader::ggx_alpha(roughness)};
}

glm::vec3 direction(float theta) { return glm::vec3(std::sin(theta), 0.0f, std::cos(theta)); }

class BaseLobeFit : public ::testing::TestWithParam<std::tuple<float, float, float>> {};

TEST_P(BaseLobeFit, SamplesFollowThePdf) {
  const auto [metalness, roughness, theta] = GetParam();
  const shader::BaseParams p = base_params(glm::vec3(0.7f, 0.5f, 0.3f), metalness, roughness);
  const glm::vec3 wo = direction(theta);
  const auto result = test::chi_square_sphere(base_sampler(p, wo), [&](glm::vec3 wi) { return shader::base_pdf(p, wo, wi); });
  EXPECT_GT(result.p_value, 0.001) << "chi2 " << result.statistic << " dof " << result.degrees_of_freedom;
  // Reflections that leave below the horizon are rejected, so the pdf integrates to the
  // sampled mass, not to 1.
  EXPECT_NEAR(result.pdf_integral, result.sampled_fraction, 0.01);
}

// Rough enough for the sphere grid to resolve the lobe; smoother lobes are checked by the
// furnace and reciprocity tests.
INSTANTIATE_TEST_SUITE_P(Params, BaseLobeFit,
                         ::testing::Combine(::testing::Values(0.0f, 0.5f, 1.0f), ::testing::Values(0.3f, 0.6f, 1.0f),
                                            ::testing::Values(0.2f, 1.0f, 1.45f)));

TEST(BaseLobes, FurnaceAlbedoNeverExceedsOne) {
  for (float metalness : {0.0f, 1.0f})
    for (float roughness : {0.0f, 0.05f, 0.2f, 0.5f, 1.0f})
      for (float theta : {0.0f, 0.7f, 1.3f, 1.55f}) {
        const glm::dvec3 a = test::albedo(base_sampler(base_params(glm::vec3(1.0f), metalness, roughness), direction(theta)), 50000);
        EXPECT_LE(a.x, 1.01) << "metal " << metalness << " roughness " << roughness << " theta " << theta;
        // The white metal keeps its energy at every roughness (multiple-scattering
        // compensation); the dielectric base is not compensated yet and loses about 10%.
        if (metalness == 1.0f) {
          EXPECT_NEAR(a.x, 1.0, 0.02) << "roughness " << roughness << " theta " << theta;
        } else if (roughness <= 0.2f && theta < 1.3f) {
          EXPECT_GT(a.x, 0.88) << "roughness " << roughness;
        }
      }
}

TEST(BaseLobes, ReciprocityOfTheEvaluation) {
  const shader::BaseParams p = base_params(glm::vec3(0.8f, 0.6f, 0.4f), 0.3f, 0.4f);
  for (float a : {0.1f, 0.6f, 1.2f})
    for (float b : {0.2f, 0.9f, 1.4f}) {
      const glm::vec3 wo = direction(a), wi = glm::vec3(-std::sin(b) * 0.6f, std::sin(b) * 0.8f, std::cos(b));
      // f(wo, wi) = f(wi, wo): compare f*cos_i / cos_i both ways.
      const glm::vec3 f1 = shader::base_eval_cos(p, wo, wi) / wi.z;
      const glm::vec3 f2 = shader::base_eval_cos(p, wi, wo) / wo.z;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(f1[c], f2[c], 1e-4f * std::max(1.0f, f1[c]));
    }
}

TEST(BaseLobes, SpecularWeightZeroIsPureLambert) {
  const shader::BaseParams p = base_params(glm::vec3(0.73f), 0.0f, 1.0f, 0.0f);
  const glm::vec3 wo = direction(0.4f), wi = direction(-0.9f);
  EXPECT_NEAR(shader::base_eval_cos(p, wo, wi).x, 0.73f * std::cos(0.9f) / M_PI, 1e-6);
  EXPECT_NEAR(shader::base_pdf(p, wo, wi), std::cos(0.9f) / M_PI, 1e-6);
}

TEST(BaseLobes, SmoothDielectricReflectsFresnel) {
  // A near-mirror dielectric (no diffuse) reflects F(theta) of the exact Fresnel equations.
  const shader::BaseParams p = base_params(glm::vec3(0.0f), 0.0f, 0.0f, 1.0f, 1.5f);
  for (float theta : {0.0f, 0.8f, 1.2f}) {
    const glm::dvec3 a = test::albedo(base_sampler(p, direction(theta)), 20000);
    EXPECT_NEAR(a.x, shader::fresnel_dielectric(std::cos(theta), 1.5f), 0.01) << theta;
  }
  EXPECT_NEAR(shader::fresnel_dielectric(1.0f, 1.5f), 0.04f, 1e-6f);
}

TEST(BaseLobes, ExtremeInputsStayFinite) {
  for (float roughness : {0.0f, 1.0f})
    for (float ior : {1.0f, 1.0001f, 3.0f})
      for (float theta : {0.0f, 1.5707f, 1.5708f}) {
        const shader::BaseParams p = base_params(glm::vec3(1.0f), 0.5f, roughness, 1.0f, ior);
        const glm::vec3 wo = direction(theta);
        for (glm::vec2 u : {glm::vec2(0.0f), glm::vec2(0.999999f), glm::vec2(0.5f, 0.0f)}) {
          glm::vec3 wi;
          if (shader::base_sample(p, wo, u, 0.9f, wi) < 0) continue;
          const glm::vec3 f = shader::base_eval_cos(p, wo, wi);
          const float pdf = shader::base_pdf(p, wo, wi);
          EXPECT_TRUE(std::isfinite(f.x + f.y + f.z) && std::isfinite(pdf)) << roughness << " " << ior << " " << theta;
        }
      }
}

}  // namespace
}  // namespace hipr
