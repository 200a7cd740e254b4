// OpenPBR conformance: hipr's BSDF against numbers measured on the specification's reference
// implementation (Adobe's OpenPBR BSDF compiled as C++; directional albedo, mean of f cos / pdf
// over 200,000 samples, one standard error at most 0.2 %), at view cosines 1, 0.5 and 0.1.
// Where hipr differs on purpose, the difference is pinned here and sized in docs/openpbr.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "openpbr_support.h"
#include "tools/sheen_volume.h"

namespace hipr {
namespace {

using shader::OpenPbrParams;
using test::albedo;
using test::dielectric;
using test::metal;

const float kCosines[3] = {1.0f, 0.5f, 0.1f};

glm::vec3 view(float cosine) { return glm::vec3(std::sqrt(1.0f - cosine * cosine), 0.0f, cosine); }

// The specification's default material (base 0.8, specular roughness 0.3, ior 1.5).
OpenPbrParams defaults() {
  OpenPbrParams p = dielectric(0.3f);
  p.baseColor = glm::vec3(0.8f);
  return p;
}

double relative(double value, double reference) { return std::abs(value - reference) / reference; }

// A coat (ior 1.6, roughness 0.1) coloured (1, 0.5, 0.5) over the default base: the colour is
// absorbed along the refracted path on the way in and out, and the base's reflection sees the
// coat's index. Reference R, G per cosine.
TEST(OpenPbrConformance, ColouredCoatOverTheDefaultBase) {
  const double reference[3][2] = {{0.606, 0.318}, {0.628, 0.340}, {0.821, 0.679}};
  for (int k = 0; k < 3; ++k) {
    OpenPbrParams p = defaults();
    p.coat = 1.0f;
    p.coatAlpha = shader::ggx_alpha(0.1f);
    p.coatEta = 1.6f;
    p.coatColor = glm::vec3(1.0f, 0.5f, 0.5f);
    const glm::dvec3 a = albedo(p, view(kCosines[k]), 200000);
    std::printf("coloured coat, cos %.1f: R %.3f G %.3f (reference %.3f %.3f)\n", kCosines[k], a.x,
                a.y, reference[k][0], reference[k][1]);
    EXPECT_LT(relative(a.x, reference[k][0]), 0.02) << "R at cos " << kCosines[k] << ": " << a.x;
    EXPECT_LT(relative(a.y, reference[k][1]), 0.02) << "G at cos " << kCosines[k] << ": " << a.y;
  }
}

// Under a coat the base's reflection sees the coat's index: specular_ior 1.5 under coat_ior 1.6
// reflects like an interface of 1.6 / 1.5 (the specification's inversion of a ratio below 1),
// half a coat like one of 1.5 / 1.3; specular_weight still scales its F0, down to none at 0.
TEST(OpenPbrConformance, BaseReflectionUnderACoatSeesTheCoatsIndex) {
  const float eta = 1.5f;
  EXPECT_NEAR(shader::specular_eta_under_coat(eta, 1.0f, 1.0f, 1.6f), 1.6f / 1.5f, 1e-4f);
  EXPECT_NEAR(shader::specular_eta_under_coat(eta, 1.0f, 0.5f, 1.6f), 1.5f / 1.3f, 1e-4f);
  EXPECT_EQ(shader::specular_eta_under_coat(eta, 1.0f, 0.0f, 1.6f), eta);
  EXPECT_EQ(shader::specular_eta_under_coat(shader::ior_with_specular_weight(eta, 0.0f), 0.0f, 1.0f,
                                            1.6f),
            1.0f);
  const auto f0 = [](float n) { return (n - 1) * (n - 1) / ((n + 1) * (n + 1)); };
  for (float weight : {0.01f, 0.3f, 0.8f}) {
    const float under = shader::specular_eta_under_coat(
        shader::ior_with_specular_weight(eta, weight), weight, 1.0f, 1.6f);
    EXPECT_NEAR(f0(under), weight * f0(1.6f / 1.5f), 1e-5f) << "weight " << weight;
  }
}

// The coat roughens the base's specular as the specification recommends.
TEST(OpenPbrConformance, ARoughCoatRoughensTheBase) {
  EXPECT_NEAR(shader::coat_roughened(0.3f, 0.1f, 1.0f),
              std::pow(0.3f * 0.3f * 0.3f * 0.3f + 2.0e-4f, 0.25f), 1e-6f);
  EXPECT_EQ(shader::coat_roughened(0.3f, 0.8f, 0.0f), 0.3f);
  EXPECT_NEAR(shader::coat_roughened(0.3f, 0.0f, 1.0f), 0.3f, 1e-6f);
  EXPECT_EQ(shader::coat_roughened(0.2f, 1.0f, 1.0f), 1.0f);
  EXPECT_NEAR(shader::coat_roughened(0.0f, 0.5f, 0.5f), 0.5f * std::pow(2.0f * 0.0625f, 0.25f),
              1e-6f);
}

// Under a coat the film sees the coat's index above it: a film of the coat's own index is then
// no film (the coat is merely thicker), over the dielectric and over the metal.
TEST(OpenPbrConformance, AFilmOfTheCoatsIndexUnderTheCoatIsInvisible) {
  for (float cosine : {0.2f, 0.6f, 1.0f}) {
    const glm::vec3 wo = view(cosine), wi = glm::vec3(-wo.x, 0.0f, wo.z);
    OpenPbrParams p = defaults();
    p.baseColor = glm::vec3(0.0f);
    p.coat = 1.0f;
    p.coatEta = 1.6f;
    p.coatAlpha = shader::ggx_alpha(0.2f);
    const glm::vec3 bare = shader::openpbr_eval_cos(p, wo, wi);
    p.thinFilm = 1.0f;
    p.thinFilmIor = 1.6f;
    p.thinFilmThickness = 400.0f;
    const glm::vec3 filmed = shader::openpbr_eval_cos(p, wo, wi);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(filmed[c], bare[c], 1e-3f * bare[c] + 1e-6f) << "dielectric, cos " << cosine;
    p.thinFilmIor = 1.3f;
    EXPECT_GT(glm::length(shader::openpbr_eval_cos(p, wo, wi) - bare), 1e-3f * glm::length(bare))
        << "a film of another index shows";
    const glm::vec3 nk = glm::vec3(0.9f, 0.6f, 0.3f);
    const glm::vec3 metal_under =
        shader::fresnel_thin_film_metal(cosine, 1.6f, nk, glm::vec3(1.0f), 400.0f, 1.6f);
    const glm::vec3 metal_thin =
        shader::fresnel_thin_film_metal(cosine, 1.6f, nk, glm::vec3(1.0f), 0.0f, 1.6f);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(metal_under[c], metal_thin[c], 2e-3f) << "metal, cos " << cosine;
  }
}

// A white coat over a white Lambertian base (specular_weight 0): the reference reflects 1.000.
TEST(OpenPbrConformance, WhiteCoatOverWhiteDiffuse) {
  for (float cosine : kCosines) {
    OpenPbrParams p = dielectric(0.3f, 1.0f);
    p.specularWeight = 0.0f;
    p.coat = 1.0f;
    p.coatAlpha = shader::ggx_alpha(0.1f);
    p.coatEta = 1.6f;
    EXPECT_NEAR(albedo(p, view(cosine), 200000).x, 1.0, 0.005) << "cos " << cosine;
  }
}

// The fuzz lobe alone (roughness 0.5). Both read R from a 32 x 32 table of the same volume's
// albedo: the reference the paper's, hipr its own random walks (tools/sheen_volume.cpp). They
// agree within 0.5 % at cos 0.5 and 0.1; at normal incidence, where the lobe is faint, hipr's
// 0.0184 is 0.0006 below the reference's 0.019 (3 %; the reference gives three decimals).
TEST(OpenPbrConformance, FuzzLobeAlbedo) {
  const double reference[3] = {0.019, 0.154, 0.552};
  for (int k = 0; k < 3; ++k) {
    const double a = shader::fuzz_energy(kCosines[k], 0.5f);
    std::printf("fuzz lobe, cos %.1f: %.4f (reference %.3f)\n", kCosines[k], a, reference[k]);
    if (kCosines[k] < 1.0f) {
      EXPECT_LT(relative(a, reference[k]), 0.02) << "cos " << kCosines[k];
    } else {
      EXPECT_NEAR(a, reference[k], 0.001) << "cos " << kCosines[k];
    }
  }
}

// The table's R against a fresh simulation off its grid points, and against the paper's own
// simulation at the points the reference was measured at.
TEST(OpenPbrConformance, FuzzAlbedoIsTheVolumes) {
  for (float alpha : {0.37f, 0.81f})
    for (float cosine : {0.23f, 0.64f, 0.97f}) {
      const double fresh = tools::sheen_volume_albedo(cosine, alpha, 200000, 99);
      EXPECT_NEAR(shader::fuzz_energy(cosine, alpha), fresh, 0.004 + 0.02 * fresh)
          << "alpha " << alpha << " cos " << cosine;
    }
}

// White fuzz over a white base reflects 1.000 in the reference; over diffuse 0.5
// (specular_weight 0) 0.509, 0.577, 0.776.
TEST(OpenPbrConformance, FuzzOverDiffuse) {
  const double reference[3] = {0.509, 0.577, 0.776};
  for (int k = 0; k < 3; ++k) {
    OpenPbrParams p = dielectric(0.3f, 1.0f);
    p.specularWeight = 0.0f;
    p.fuzz = 1.0f;
    p.fuzzRoughness = 0.5f;
    EXPECT_NEAR(albedo(p, view(kCosines[k]), 100000).x, 1.0, 0.005) << "white, cos " << kCosines[k];
    p.baseColor = glm::vec3(0.5f);
    const double a = albedo(p, view(kCosines[k]), 100000).x;
    std::printf("fuzz over diffuse 0.5, cos %.1f: %.3f (reference %.3f)\n", kCosines[k], a,
                reference[k]);
    EXPECT_LT(relative(a, reference[k]), 0.02) << "diffuse 0.5, cos " << kCosines[k];
  }
}

// A 500 nm film of index 1.4 over metal (0.9, 0.6, 0.3), roughness 0.2. The reference evaluates
// the film at one wavelength per channel (620, 540, 450 nm); hipr integrates each channel over
// the spectrum (what the reference's recommended random wavelengths converge to), so colours
// agree in kind, not to 2 %: within 0.04 per channel. Without the film the metal is unchanged.
TEST(OpenPbrConformance, ThinFilmOverMetal) {
  const double reference[3][3] = {
      {0.873, 0.694, 0.223}, {0.930, 0.703, 0.384}, {0.826, 0.830, 0.601}};
  for (int k = 0; k < 3; ++k) {
    OpenPbrParams p = metal(0.2f);
    p.baseColor = glm::vec3(0.9f, 0.6f, 0.3f);
    p.thinFilm = 1.0f;
    p.thinFilmThickness = 500.0f;
    p.thinFilmIor = 1.4f;
    const glm::dvec3 film = albedo(p, view(kCosines[k]), 200000);
    p.thinFilm = 0.0f;
    const glm::dvec3 bare = albedo(p, view(kCosines[k]), 200000);
    std::printf(
        "film over metal, cos %.1f: %.3f %.3f %.3f (reference %.3f %.3f %.3f; bare metal %.3f %.3f "
        "%.3f)\n",
        kCosines[k], film.x, film.y, film.z, reference[k][0], reference[k][1], reference[k][2],
        bare.x, bare.y, bare.z);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(film[c], reference[k][c], 0.04) << "channel " << c << " cos " << kCosines[k];
    EXPECT_GT(std::abs(film.z - bare.z), 0.02)
        << "the film must change the metal's colour, cos " << kCosines[k];
  }
}

// A 0 nm film is no film: the metal keeps its F82-tint Fresnel exactly.
TEST(OpenPbrConformance, ThinFilmOfNoThicknessLeavesTheMetalAlone) {
  for (float cosine : {0.05f, 0.3f, 0.7f, 1.0f}) {
    const glm::vec3 f0(0.9f, 0.6f, 0.3f), tint(0.8f, 0.9f, 1.0f);
    const glm::vec3 plain = shader::fresnel_f82_tint(f0, tint, cosine);
    EXPECT_EQ(shader::metal_fresnel(f0, tint, glm::vec4(1.0f, 1.4f, 0.0f, 1.0f), cosine), plain);
    EXPECT_EQ(shader::metal_fresnel(f0, tint, glm::vec4(0.0f, 1.4f, 500.0f, 1.0f), cosine), plain);
  }
}

// Gulbrandsen's index reflects exactly the base colour at normal incidence, and a film of the
// ambient index (1) is invisible: the filmed Fresnel is then the conductor's own.
TEST(OpenPbrConformance, MetalIndexReproducesTheBaseColour) {
  for (float r : {0.05f, 0.3f, 0.6f, 0.95f})
    for (float g : {0.0f, 0.5f, 1.0f}) {
      const glm::vec2 nk = shader::metal_complex_index(r, g);
      const float normal =
          ((nk.x - 1) * (nk.x - 1) + nk.y * nk.y) / ((nk.x + 1) * (nk.x + 1) + nk.y * nk.y);
      EXPECT_NEAR(normal, r, 1e-4f) << "r " << r << " g " << g;
      const glm::vec3 vacuum =
          shader::fresnel_thin_film_metal(1.0f, 1.0f, glm::vec3(r), glm::vec3(g), 400.0f, 1.0f);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(vacuum[c], r, 2e-3f) << "r " << r << " g " << g;
    }
}

// Not conformance targets, measured and kept: hipr's rough coloured metal uses height-correlated
// masking and the Kulla-Conty multiple-scattering colour, the reference a separable masking and
// F_avg^2: hipr is 2-7 % darker at normal incidence and up to 10 % brighter in blue at grazing
// (docs/openpbr.md). Pinned so a change shows.
TEST(OpenPbrConformance, RoughColouredMetalStaysNearTheReference) {
  const double reference[3][3] = {
      {0.863, 0.503, 0.216}, {0.867, 0.515, 0.229}, {0.879, 0.550, 0.268}};
  for (int k = 0; k < 3; ++k) {
    OpenPbrParams p = metal(0.8f);
    p.baseColor = glm::vec3(0.9f, 0.6f, 0.3f);
    const glm::dvec3 a = albedo(p, view(kCosines[k]), 100000);
    std::printf("rough metal, cos %.1f: %.3f %.3f %.3f (reference %.3f %.3f %.3f)\n", kCosines[k],
                a.x, a.y, a.z, reference[k][0], reference[k][1], reference[k][2]);
    for (int c = 0; c < 3; ++c)
      EXPECT_LT(relative(a[c], reference[k][c]), 0.1) << "channel " << c << " cos " << kCosines[k];
  }
}

}  // namespace
}  // namespace hipr
