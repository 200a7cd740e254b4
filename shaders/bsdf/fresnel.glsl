// Fresnel terms. Shared with C++.
#ifndef HIPR_FRESNEL_GLSL
#define HIPR_FRESNEL_GLSL

#include "../common/sampling.glsl"

// Unpolarized Fresnel reflectance of a dielectric interface, eta = n_inside / n_outside,
// for light arriving from outside at cosine cos_i (> 0). Total internal reflection gives 1.
HIPR_FN float fresnel_dielectric(float cos_i, float eta) {
  cos_i = clamp(cos_i, 0.0f, 1.0f);
  const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return 1.0f;
  const float cos_t = sqrt(1.0f - sin2_t);
  const float rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const float rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5f * (rs * rs + rp * rp);
}

HIPR_FN vec3 fresnel_schlick(vec3 f0, float mu) {
  const float m = clamp(1.0f - mu, 0.0f, 1.0f);
  const float m5 = m * m * m * m * m;
  return f0 + (vec3(1.0f) - f0) * m5;
}

// OpenPBR's metal Fresnel, "F82-tint" (Kutz et al. 2021): Schlick through F0 = base colour,
// minus a term that bends the reflectance at mu = 1/7 to specular_color x Schlick(1/7).
HIPR_FN vec3 fresnel_f82_tint(vec3 f0, vec3 tint, float mu) {
  const float mu_bar = 1.0f / 7.0f;
  const float denominator = mu_bar * pow(1.0f - mu_bar, 6.0f);
  const vec3 schlick_bar = fresnel_schlick(f0, mu_bar);
  const vec3 a = schlick_bar * (vec3(1.0f) - tint) / denominator;
  mu = clamp(mu, 0.0f, 1.0f);
  return clamp(fresnel_schlick(f0, mu) - a * mu * pow(1.0f - mu, 6.0f), vec3(0.0f), vec3(1.0f));
}

#endif
