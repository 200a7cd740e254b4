// Rough dielectric interface (Walter et al. 2007, sampled through visible normals): reflection
// and refraction by GGX microfacets with exact Fresnel, and the thin-walled variant in which a
// slab's two interfaces act together. Local frame (n = +Z), wo.z > 0 on the side light leaves
// toward; `eta` is the relative index n(far side) / n(wo side): > 1 entering, < 1 leaving.
// Shared with C++.
#ifndef HIPR_DIELECTRIC_GLSL
#define HIPR_DIELECTRIC_GLSL

#include "fresnel.glsl"
#include "microfacet.glsl"

// Within this of 1 the two media match: refraction goes straight through, and the microfacet
// refraction formulas divide by (eta - 1)^2, so the interface is handled as a delta pass-through.
const float kIndexMatchedEpsilon = 1.0e-3f;

HIPR_FN bool index_matched(float eta) { return abs(eta - 1.0f) < kIndexMatchedEpsilon; }

// OpenPBR's specular_weight scales the normal-incidence reflectance F0 of the interface; the
// index that has that F0 keeps reflection and refraction consistent (their sum stays 1).
HIPR_FN float ior_with_specular_weight(float ior, float weight) {
  const float flipped = ior < 1.0f ? 1.0f : 0.0f;
  const float n = ior < 1.0f ? 1.0f / max(ior, 1.0e-4f) : ior;
  const float r0 = (n - 1.0f) / (n + 1.0f);
  const float s = sqrt(clamp(weight, 0.0f, 1.0e4f) * r0 * r0);
  const float r = min(s, 0.99f);
  const float weighted = (1.0f + r) / (1.0f - r);
  return flipped > 0.0f ? 1.0f / weighted : weighted;
}

// Refraction of wo through the microfacet m (wo.m > 0) into the far side; false on total
// internal reflection. Written out (not GLSL's refract) so its TIR test is exactly the one of
// fresnel_dielectric.
HIPR_FN bool refract_through(vec3 wo, vec3 m, float eta, OUT(vec3) wi) {
  const float cos_o = dot(wo, m);
  const float sin2_t = (1.0f - cos_o * cos_o) / (eta * eta);
  wi = vec3(0.0f);
  if (sin2_t >= 1.0f) return false;
  const float cos_t = sqrt(1.0f - sin2_t);
  wi = normalize(-wo / eta + (cos_o / eta - cos_t) * m);
  return true;
}

// The half vector of a refraction pair (on the wo side, +Z hemisphere); false if the pair
// cannot come from one microfacet.
HIPR_FN bool refraction_half_vector(vec3 wo, vec3 wi, float eta, OUT(vec3) m) {
  m = wo + eta * wi;
  if (dot(m, m) <= 1.0e-12f) return false;
  m = normalize(m);
  if (m.z < 0.0f) m = -m;
  return dot(wo, m) > 0.0f && dot(wi, m) < 0.0f;
}

// Jacobian |dm/dwi| of refraction: |wi.m| / (wi.m + wo.m / eta)^2.
HIPR_FN float refraction_jacobian(vec3 wo, vec3 wi, vec3 m, float eta) {
  const float denom = dot(wi, m) + dot(wo, m) / eta;
  return abs(dot(wi, m)) / max(denom * denom, 1.0e-20f);
}

// Microfacet refraction f * |cos_i| for Fresnel transmittance `transmittance` at wo.m; the
// radiance scaling 1/eta^2 is left out (it cancels for paths that enter and leave an object,
// and keeps the lobe's albedo the energy that passes).
HIPR_FN float ggx_refraction_eval_cos(vec3 wo, vec3 wi, vec3 m, float eta, vec2 alpha, float transmittance) {
  const float denom = dot(wi, m) + dot(wo, m) / eta;
  if (denom * denom <= 1.0e-20f) return 0.0f;
  return transmittance * ggx_d(m, alpha) * ggx_g2(wo, wi, alpha) * abs(dot(wi, m)) * dot(wo, m) /
         (wo.z * denom * denom);
}

// ---- thick interface (closed objects): reflection with F, refraction with 1 - F ----

// f * |cos_i| of both events; wi on either side.
HIPR_FN float dielectric_interface_eval_cos(vec3 wo, vec3 wi, float eta, vec2 alpha) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return 0.0f;
  if (wi.z > 0.0f) {
    const vec3 h = normalize(wo + wi);
    return fresnel_dielectric(dot(wo, h), eta) * ggx_reflection_eval_cos(wo, wi, alpha);
  }
  vec3 m;
  if (index_matched(eta) || !refraction_half_vector(wo, wi, eta, m)) return 0.0f;
  return ggx_refraction_eval_cos(wo, wi, m, eta, alpha, 1.0f - fresnel_dielectric(dot(wo, m), eta));
}

HIPR_FN float dielectric_interface_pdf(vec3 wo, vec3 wi, float eta, vec2 alpha) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return 0.0f;
  if (wi.z > 0.0f) {
    const vec3 h = normalize(wo + wi);
    return fresnel_dielectric(dot(wo, h), eta) * ggx_reflection_pdf(wo, wi, alpha);
  }
  vec3 m;
  if (index_matched(eta) || !refraction_half_vector(wo, wi, eta, m)) return 0.0f;
  return (1.0f - fresnel_dielectric(dot(wo, m), eta)) * ggx_visible_normal_pdf(wo, m, alpha) *
         refraction_jacobian(wo, wi, m, eta);
}

// Reflects with probability F(wo.m), else refracts. Index-matched media pass straight through
// (returns 2: a delta event the caller weights by itself). Returns 0 for no sample, 1 otherwise.
HIPR_FN int dielectric_interface_sample(vec3 wo, float eta, vec2 alpha, vec2 u, float u_choice, OUT(vec3) wi) {
  wi = vec3(0.0f, 0.0f, 1.0f);
  if (index_matched(eta)) {
    wi = -wo;
    return 2;
  }
  const vec3 m = ggx_sample_visible_normal(wo, alpha, u);
  const float f = fresnel_dielectric(dot(wo, m), eta);
  if (u_choice < f) {
    wi = 2.0f * dot(wo, m) * m - wo;
    return wi.z > 0.0f ? 1 : 0;
  }
  if (!refract_through(wo, m, eta, wi)) return 0;
  return wi.z < 0.0f ? 1 : 0;
}

// ---- thin-walled slab: the light that is not reflected leaves on the far side, unbent ----

// Reflectance of a slab of two identical interfaces with Fresnel f, summing the inner
// bounces incoherently: f + (1-f)^2 f / (1 - f^2) = 2f / (1 + f); the rest is transmitted.
HIPR_FN float thin_slab_reflectance(float f) { return 2.0f * f / (1.0f + f); }
HIPR_FN vec3 thin_slab_reflectance(vec3 f) { return 2.0f * f / (vec3(1.0f) + f); }  // per colour (thin film)

HIPR_FN vec3 mirror_through_slab(vec3 w) { return vec3(w.x, w.y, -w.z); }

HIPR_FN float thin_interface_eval_cos(vec3 wo, vec3 wi, float eta, vec2 alpha) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return 0.0f;
  const vec3 wr = wi.z > 0.0f ? wi : mirror_through_slab(wi);
  const vec3 h = normalize(wo + wr);
  const float r = thin_slab_reflectance(fresnel_dielectric(dot(wo, h), eta));
  return (wi.z > 0.0f ? r : 1.0f - r) * ggx_reflection_eval_cos(wo, wr, alpha);
}

HIPR_FN float thin_interface_pdf(vec3 wo, vec3 wi, float eta, vec2 alpha) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return 0.0f;
  const vec3 wr = wi.z > 0.0f ? wi : mirror_through_slab(wi);
  const vec3 h = normalize(wo + wr);
  const float r = thin_slab_reflectance(fresnel_dielectric(dot(wo, h), eta));
  return (wi.z > 0.0f ? r : 1.0f - r) * ggx_reflection_pdf(wo, wr, alpha);
}

HIPR_FN int thin_interface_sample(vec3 wo, float eta, vec2 alpha, vec2 u, float u_choice, OUT(vec3) wi) {
  const vec3 m = ggx_sample_visible_normal(wo, alpha, u);
  wi = 2.0f * dot(wo, m) * m - wo;
  if (wi.z <= 0.0f) return 0;
  if (u_choice >= thin_slab_reflectance(fresnel_dielectric(dot(wo, m), eta))) wi = mirror_through_slab(wi);
  return 1;
}

#endif
