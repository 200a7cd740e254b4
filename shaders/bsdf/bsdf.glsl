// The BSDF interface the integrator calls. Directions are world space and unit length; `wo`
// points away from the surface toward the previous vertex, `wi` toward the next. The lobes
// live in openpbr_base.glsl (local frame, shared with the C++ tests); this file moves
// directions into the shading frame and reports the lobe class of every sample.
#ifndef HIPR_BSDF_GLSL
#define HIPR_BSDF_GLSL

#include "openpbr_base.glsl"

// Lobe classes every sample reports (HiPR's tile weights depend on them).
const uint kLobeDiffuse = 0u;
const uint kLobeGlossy = 1u;
const uint kLobeSpecular = 2u;
const uint kLobeTransmission = 3u;

// GGX lobes narrower than this (roughness ~0.1) count as "specular" for HiPR.
const float kSpecularAlpha = 0.01f;

struct BsdfFrame {
  vec3 shadingNormal;
  vec3 geometricNormal;  // on the side of wo
};

struct BsdfSample {
  vec3 direction;
  vec3 weight;  // f * |cos| / pdf
  float pdf;    // solid angle; 0 = no sample
  uint lobe;
};

vec3 bsdf_to_local(BsdfFrame frame, vec3 v) {
  vec3 t, b;
  make_basis(frame.shadingNormal, t, b);
  return vec3(dot(v, t), dot(v, b), dot(v, frame.shadingNormal));
}

// wo as the lobes see it: a shading normal can face slightly away from a wo that the
// geometric normal accepts; lift it just above the horizon instead of losing the sample.
vec3 bsdf_local_wo(BsdfFrame frame, vec3 wo) {
  vec3 w = bsdf_to_local(frame, wo);
  w.z = max(w.z, 1.0e-4f);
  return normalize(w);
}

// f(wo, wi) * |cos(wi, n_s)|. Zero when wi leaves through the other side of the geometry, so
// shading normals never let light leak through surfaces.
vec3 bsdf_eval(BaseParams p, BsdfFrame frame, vec3 wo, vec3 wi) {
  if (dot(wi, frame.geometricNormal) <= 0.0) return vec3(0.0);
  return base_eval_cos(p, bsdf_local_wo(frame, wo), bsdf_to_local(frame, wi));
}

float bsdf_pdf(BaseParams p, BsdfFrame frame, vec3 wo, vec3 wi) {
  if (dot(wi, frame.geometricNormal) <= 0.0) return 0.0;
  return base_pdf(p, bsdf_local_wo(frame, wo), bsdf_to_local(frame, wi));
}

BsdfSample bsdf_sample(BaseParams p, BsdfFrame frame, vec3 wo, vec3 u) {
  BsdfSample s;
  s.pdf = 0.0;
  s.weight = vec3(0.0);
  s.lobe = kLobeDiffuse;
  const vec3 wo_local = bsdf_local_wo(frame, wo);
  vec3 wi_local;
  const int lobe = base_sample(p, wo_local, u.xy, u.z, wi_local);
  if (lobe < 0) return s;
  s.lobe = lobe == 0 ? kLobeDiffuse : (p.alpha < kSpecularAlpha ? kLobeSpecular : kLobeGlossy);
  s.direction = to_world(wi_local, frame.shadingNormal);
  if (dot(s.direction, frame.geometricNormal) <= 0.0) return s;
  s.pdf = base_pdf(p, wo_local, wi_local);
  if (!(s.pdf > 0.0)) {
    s.pdf = 0.0;
    return s;
  }
  s.weight = base_eval_cos(p, wo_local, wi_local) / s.pdf;
  return s;
}

#endif
