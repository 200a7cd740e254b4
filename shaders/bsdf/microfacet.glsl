// GGX (Trowbridge-Reitz) microfacets with height-correlated Smith shadowing and visible-normal
// sampling (Heitz 2018). Local frame: n = +Z. Isotropic for now. Shared with C++.
#ifndef HIPR_MICROFACET_GLSL
#define HIPR_MICROFACET_GLSL

#include "../common/sampling.glsl"

// Roughness below this is treated as the smoothest GGX we can represent in floats.
const float kMinAlpha = 1.0e-4f;

HIPR_FN float ggx_alpha(float roughness) { return max(roughness * roughness, kMinAlpha); }

// Written with the tangent components, not 1 - z^2: (a2 - 1) rounds to -1 in floats for the
// smallest alpha, which would put a 0/0 at the lobe's peak.
HIPR_FN float ggx_d(vec3 h, float alpha) {
  if (h.z <= 0.0f) return 0.0f;
  const float a2 = alpha * alpha;
  const float t = (h.x * h.x + h.y * h.y) / a2 + h.z * h.z;
  return 1.0f / (kPi * a2 * t * t);
}

// Smith Lambda for direction v.
HIPR_FN float ggx_lambda(vec3 v, float alpha) {
  const float c2 = v.z * v.z;
  if (c2 >= 1.0f) return 0.0f;
  const float tan2 = max(1.0f - c2, 0.0f) / max(c2, 1.0e-12f);
  return 0.5f * (-1.0f + sqrt(1.0f + alpha * alpha * tan2));
}

HIPR_FN float ggx_g1(vec3 v, float alpha) { return 1.0f / (1.0f + ggx_lambda(v, alpha)); }

HIPR_FN float ggx_g2(vec3 wo, vec3 wi, float alpha) {
  return 1.0f / (1.0f + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha));
}

// A visible normal for wo (wo.z > 0).
HIPR_FN vec3 ggx_sample_visible_normal(vec3 wo, float alpha, vec2 u) {
  const vec3 vh = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
  const float lensq = vh.x * vh.x + vh.y * vh.y;
  const vec3 t1 = lensq > 0.0f ? vec3(-vh.y, vh.x, 0.0f) / sqrt(lensq) : vec3(1.0f, 0.0f, 0.0f);
  const vec3 t2 = cross(vh, t1);
  const float r = sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  const float p1 = r * cos(phi);
  const float s = 0.5f * (1.0f + vh.z);
  const float p2 = (1.0f - s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + s * r * sin(phi);
  const vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
  return normalize(vec3(alpha * nh.x, alpha * nh.y, max(0.0f, nh.z)));
}

// Solid-angle pdf of reflecting wo into wi through visible-normal sampling.
HIPR_FN float ggx_reflection_pdf(vec3 wo, vec3 wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const vec3 h = normalize(wo + wi);
  const float oh = dot(wo, h);
  if (oh <= 0.0f) return 0.0f;
  // pdf_h = G1(wo) max(0, wo.h) D(h) / wo.z, and dwi/dh = 1 / (4 wo.h).
  return ggx_g1(wo, alpha) * ggx_d(h, alpha) / (4.0f * wo.z);
}

// D G2 / (4 cos_o cos_i) * cos_i: the Fresnel-free reflection, times the cosine.
HIPR_FN float ggx_reflection_eval_cos(vec3 wo, vec3 wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const vec3 h = normalize(wo + wi);
  return ggx_d(h, alpha) * ggx_g2(wo, wi, alpha) / (4.0f * wo.z);
}

#endif
