// The OpenPBR base layer (so far): a metal (GGX + F82-tint Fresnel) mixed by base_metalness
// with a dielectric base, which is GGX specular reflection (Fresnel from specular_ior, scaled
// by specular_weight and specular_color) over a Lambertian diffuse. The diffuse lobe is scaled
// by (1 - F(cos_o)) (1 - F(cos_i)), which keeps it reciprocal and the total albedo <= 1;
// multiple-scattering compensation, transmission, coat, fuzz and thin film come later.
// Local frame (n = +Z); wo.z > 0. Shared with C++.
#ifndef HIPR_OPENPBR_BASE_GLSL
#define HIPR_OPENPBR_BASE_GLSL

#include "fresnel.glsl"
#include "lambert.glsl"
#include "microfacet.glsl"

struct BaseParams {
  vec3 baseColor;  // already times base_weight
  float metalness;
  vec3 specularColor;
  float specularWeight;
  float specularIor;
  float alpha;  // GGX roughness parameter
};

// Sampling probabilities of the three lobes (diffuse, dielectric specular, metal) for wo.
HIPR_FN vec3 base_lobe_probabilities(BaseParams p, float cos_o) {
  const float fs = min(p.specularWeight * fresnel_dielectric(cos_o, p.specularIor), 1.0f);
  const float diffuse = (1.0f - p.metalness) * luminance(p.baseColor) * (1.0f - fs);
  const float specular = (1.0f - p.metalness) * fs * luminance(p.specularColor);
  const float metal = p.metalness * luminance(fresnel_f82_tint(p.baseColor, p.specularColor, cos_o));
  const float total = diffuse + specular + metal;
  return total > 0.0f ? vec3(diffuse, specular, metal) / total : vec3(0.0f);
}

// f(wo, wi) * cos(wi).
HIPR_FN vec3 base_eval_cos(BaseParams p, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
  const vec3 h = normalize(wo + wi);
  const float spec = ggx_reflection_eval_cos(wo, wi, p.alpha);
  const float fo = min(p.specularWeight * fresnel_dielectric(wo.z, p.specularIor), 1.0f);
  const float fi = min(p.specularWeight * fresnel_dielectric(wi.z, p.specularIor), 1.0f);
  const float fh = min(p.specularWeight * fresnel_dielectric(dot(wo, h), p.specularIor), 1.0f);
  const vec3 dielectric = p.baseColor * (lambert_eval_cos(wi.z) * (1.0f - fo) * (1.0f - fi)) + p.specularColor * (fh * spec);
  const vec3 metal = fresnel_f82_tint(p.baseColor, p.specularColor, dot(wo, h)) * spec;
  return (1.0f - p.metalness) * dielectric + p.metalness * metal;
}

HIPR_FN float base_pdf(BaseParams p, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const vec3 w = base_lobe_probabilities(p, wo.z);
  return w.x * lambert_pdf(wi.z) + (w.y + w.z) * ggx_reflection_pdf(wo, wi, p.alpha);
}

// Picks a lobe with u_lobe, samples a direction from it; returns the lobe index
// (0 diffuse, 1 dielectric specular, 2 metal) or -1 for no sample.
HIPR_FN int base_sample(BaseParams p, vec3 wo, vec2 u, float u_lobe, OUT(vec3) wi) {
  wi = vec3(0.0f, 0.0f, 1.0f);
  const vec3 w = base_lobe_probabilities(p, wo.z);
  if (w.x + w.y + w.z <= 0.0f || wo.z <= 0.0f) return -1;
  if (u_lobe < w.x) {
    wi = lambert_sample_local(u);
    return 0;
  }
  const vec3 m = ggx_sample_visible_normal(wo, p.alpha, u);
  wi = 2.0f * dot(wo, m) * m - wo;
  if (wi.z <= 0.0f) return -1;
  return u_lobe < w.x + w.y ? 1 : 2;
}

#endif
