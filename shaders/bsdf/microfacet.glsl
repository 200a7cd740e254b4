// GGX (Trowbridge-Reitz) microfacets with height-correlated Smith shadowing and visible-normal
// sampling (Heitz 2018). Anisotropic: alpha.x along the local +X (the tangent), alpha.y along +Y.
// Local frame: n = +Z. Shared with C++.
#ifndef HIPR_MICROFACET_GLSL
#define HIPR_MICROFACET_GLSL

#include "../common/sampling.glsl"

// Roughness below this is treated as the smoothest GGX we can represent in floats.
const float kMinAlpha = 1.0e-4f;

HIPR_FN float ggx_alpha(float roughness) { return max(roughness * roughness, kMinAlpha); }

// OpenPBR's anisotropic roughness: the tangent keeps alpha * sqrt(2 / (1 + (1 - a)^2)) and the
// bitangent (1 - a) times that, so the lobe's "area" follows roughness at any anisotropy a.
HIPR_FN vec2 ggx_alpha_anisotropic(float roughness, float anisotropy) {
  const float a = clamp(anisotropy, 0.0f, 1.0f);
  const float r2 = roughness * roughness;
  const float along = r2 * sqrt(2.0f / (1.0f + (1.0f - a) * (1.0f - a)));
  return max(vec2(along, (1.0f - a) * along), vec2(kMinAlpha));
}

// One scalar roughness for tables that are tabulated isotropically.
HIPR_FN float ggx_alpha_mean(vec2 alpha) { return sqrt(alpha.x * alpha.y); }

// Anisotropic lobes read the isotropic albedo tables at their smaller alpha. Near grazing an
// anisotropic lobe can keep more energy than any isotropic one, so energy compensation is
// faded out with the anisotropy (ggx_isotropy): an anisotropic lobe may lose a little energy,
// but never gains any.
HIPR_FN float ggx_alpha_for_tables(vec2 alpha) { return min(alpha.x, alpha.y); }

HIPR_FN float ggx_isotropy(vec2 alpha) { return min(alpha.x, alpha.y) / max(alpha.x, alpha.y); }

// Written with the tangent components, not 1 - z^2: (a2 - 1) rounds to -1 in floats for the
// smallest alpha, which would put a 0/0 at the lobe's peak.
HIPR_FN float ggx_d(vec3 h, vec2 alpha) {
  if (h.z <= 0.0f) return 0.0f;
  const float t = (h.x * h.x) / (alpha.x * alpha.x) + (h.y * h.y) / (alpha.y * alpha.y) + h.z * h.z;
  return 1.0f / (kPi * alpha.x * alpha.y * t * t);
}

// Smith Lambda for direction v.
HIPR_FN float ggx_lambda(vec3 v, vec2 alpha) {
  const float c2 = v.z * v.z;
  if (c2 >= 1.0f) return 0.0f;
  const float t2 = (alpha.x * alpha.x * v.x * v.x + alpha.y * alpha.y * v.y * v.y) / max(c2, 1.0e-12f);
  return 0.5f * (-1.0f + sqrt(1.0f + t2));
}

HIPR_FN float ggx_g1(vec3 v, vec2 alpha) { return 1.0f / (1.0f + ggx_lambda(v, alpha)); }

// Height-correlated masking-shadowing; directions may lie on either side (transmission).
HIPR_FN float ggx_g2(vec3 wo, vec3 wi, vec2 alpha) {
  return 1.0f / (1.0f + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha));
}

// Density of visible normals for wo (wo.z > 0): G1(wo) max(0, wo.m) D(m) / wo.z.
HIPR_FN float ggx_visible_normal_pdf(vec3 wo, vec3 m, vec2 alpha) {
  const float om = dot(wo, m);
  if (om <= 0.0f || wo.z <= 0.0f) return 0.0f;
  return ggx_g1(wo, alpha) * om * ggx_d(m, alpha) / wo.z;
}

// A visible normal for wo (wo.z > 0).
HIPR_FN vec3 ggx_sample_visible_normal(vec3 wo, vec2 alpha, vec2 u) {
  const vec3 vh = normalize(vec3(alpha.x * wo.x, alpha.y * wo.y, wo.z));
  const float lensq = vh.x * vh.x + vh.y * vh.y;
  const vec3 t1 = lensq > 0.0f ? vec3(-vh.y, vh.x, 0.0f) / sqrt(lensq) : vec3(1.0f, 0.0f, 0.0f);
  const vec3 t2 = cross(vh, t1);
  const float r = sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  const float p1 = r * cos(phi);
  const float s = 0.5f * (1.0f + vh.z);
  const float p2 = (1.0f - s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + s * r * sin(phi);
  const vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
  return normalize(vec3(alpha.x * nh.x, alpha.y * nh.y, max(0.0f, nh.z)));
}

// Solid-angle pdf of reflecting wo into wi through visible-normal sampling.
HIPR_FN float ggx_reflection_pdf(vec3 wo, vec3 wi, vec2 alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const vec3 h = normalize(wo + wi);
  const float oh = dot(wo, h);
  if (oh <= 0.0f) return 0.0f;
  // pdf_h = G1(wo) (wo.h) D(h) / wo.z, and dwi/dh = 1 / (4 wo.h).
  return ggx_g1(wo, alpha) * ggx_d(h, alpha) / (4.0f * wo.z);
}

// D G2 / (4 cos_o cos_i) * cos_i: the Fresnel-free reflection, times the cosine.
HIPR_FN float ggx_reflection_eval_cos(vec3 wo, vec3 wi, vec2 alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const vec3 h = normalize(wo + wi);
  return ggx_d(h, alpha) * ggx_g2(wo, wi, alpha) / (4.0f * wo.z);
}

#endif
