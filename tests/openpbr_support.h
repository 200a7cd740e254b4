#pragma once
// OpenPBR BSDF test support: the BSDF compiled on the CPU from the very GLSL headers the kernels
// include, parameter sets (the specification's defaults, white stacks, random mixtures) and the
// BSDF seen through bsdf_stats.h's sampler interface.
#include <cmath>
#include <random>

#include "bsdf_stats.h"

namespace hipr::shader {
using namespace glm;
#include "shaders/bsdf/openpbr.glsl"
}  // namespace hipr::shader

namespace hipr::test {

using shader::OpenPbrParams;

// A white, non-absorbing dielectric: the spec's defaults with a white base.
inline OpenPbrParams dielectric(float roughness, float ior = 1.5f) {
  OpenPbrParams p;
  p.baseColor = glm::vec3(1.0f);
  p.metalness = 0.0f;
  p.diffuseRoughness = 0.0f;
  p.specularColor = glm::vec3(1.0f);
  p.specularWeight = 1.0f;
  p.alpha = glm::vec2(shader::ggx_alpha(roughness));
  p.eta = ior;
  p.transmission = 0.0f;
  p.transmissionColor = glm::vec3(1.0f);
  p.thinWalled = false;
  p.subsurface = 0.0f;
  p.subsurfaceColor = glm::vec3(1.0f);
  p.coat = 0.0f;
  p.coatColor = glm::vec3(1.0f);
  p.coatAlpha = shader::ggx_alpha(0.0f);
  p.coatEta = 1.6f;
  p.coatDarkening = 1.0f;
  p.fuzz = 0.0f;
  p.fuzzColor = glm::vec3(1.0f);
  p.fuzzRoughness = 0.5f;
  p.thinFilm = 0.0f;
  p.thinFilmThickness = 500.0f;
  p.thinFilmIor = 1.4f;
  return p;
}

inline OpenPbrParams metal(float roughness) {
  OpenPbrParams p = dielectric(roughness);
  p.metalness = 1.0f;
  return p;
}

inline OpenPbrParams glass(float roughness, float eta, bool thin = false) {
  OpenPbrParams p = dielectric(roughness, eta);
  p.transmission = 1.0f;
  p.thinWalled = thin;
  return p;
}

inline OpenPbrParams coated(float roughness, float coat_roughness) {
  OpenPbrParams p = dielectric(roughness);
  p.coat = 1.0f;
  p.coatAlpha = shader::ggx_alpha(coat_roughness);
  return p;
}

// Every parameter drawn at random: the full BSDF with all its lobes at once.
inline OpenPbrParams random_params(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const auto color = [&] { return glm::vec3(u(rng), u(rng), u(rng)); };
  OpenPbrParams p = dielectric(0.2f + 0.8f * u(rng), 1.0f + 1.5f * u(rng));
  if (u(rng) < 0.3f) p.eta = 1.0f / p.eta;
  p.baseColor = color();
  p.metalness = u(rng) < 0.3f ? 0.0f : u(rng);
  p.specularColor = color();
  p.alpha = shader::ggx_alpha_anisotropic(0.3f + 0.7f * u(rng), u(rng));
  p.transmission = u(rng);
  p.transmissionColor = color();
  p.thinWalled = u(rng) < 0.5f;
  if (p.thinWalled && p.eta < 1.0f)
    p.eta = 1.0f / p.eta;  // a slab has the same index on both sides
  p.subsurface = u(rng);
  p.subsurfaceColor = color();
  p.coat = u(rng);
  p.coatColor = color();
  p.coatAlpha = shader::ggx_alpha(0.3f + 0.7f * u(rng));
  p.coatEta = 1.2f + u(rng);
  p.coatDarkening = u(rng);
  p.diffuseRoughness = u(rng);
  p.fuzz = u(rng) < 0.5f ? 0.0f : u(rng);
  p.fuzzColor = color();
  p.fuzzRoughness = u(rng);
  p.thinFilm = u(rng) < 0.5f ? 0.0f : u(rng);
  p.thinFilmThickness = 1000.0f * u(rng);
  p.thinFilmIor = 1.0f + u(rng);
  return p;
}

inline glm::vec3 direction(float theta) {
  return glm::vec3(std::sin(theta), 0.0f, std::cos(theta));
}

// The BSDF seen from wo through bsdf_stats.h's sampler interface. Delta events (index-matched
// pass-through) carry no density: the chi-square sampler skips them, the albedo one counts them.
inline SampleFn sampler(const OpenPbrParams& p, glm::vec3 wo, bool count_delta = false) {
  return [p, wo, count_delta](glm::vec2 u, float u_lobe) -> std::optional<DirectionSample> {
    const shader::OpenPbrSample s = shader::openpbr_sample(p, wo, u, u_lobe);
    if (!s.valid) return std::nullopt;
    if (s.delta) {
      if (!count_delta) return std::nullopt;
      return DirectionSample{s.wi, s.deltaWeight};
    }
    const float pdf = shader::openpbr_pdf(p, wo, s.wi);
    if (!(pdf > 0.0f)) return std::nullopt;
    return DirectionSample{s.wi, shader::openpbr_eval_cos(p, wo, s.wi) / pdf};
  };
}

inline ChiSquareResult fit(const OpenPbrParams& p, glm::vec3 wo) {
  return chi_square_sphere(sampler(p, wo),
                           [&](glm::vec3 wi) { return shader::openpbr_pdf(p, wo, wi); });
}

inline glm::dvec3 albedo(const OpenPbrParams& p, glm::vec3 wo, int samples = 40000) {
  return test::albedo(sampler(p, wo, true), samples);
}

}  // namespace hipr::test
