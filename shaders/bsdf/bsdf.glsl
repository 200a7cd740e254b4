// The BSDF interface the integrator calls. Directions are world space and unit length; `wo`
// points away from the surface toward the previous vertex, `wi` toward the next.
// The foundation BSDF is the OpenPBR base diffuse lobe (Lambert, base_diffuse_roughness 0);
// the full OpenPBR model replaces the bodies of these functions, not their signatures.
#ifndef HIPR_BSDF_GLSL
#define HIPR_BSDF_GLSL

#include "lambert.glsl"

// Lobe classes every sample reports (HiPR's tile weights depend on them).
const uint kLobeDiffuse = 0u;
const uint kLobeGlossy = 1u;
const uint kLobeSpecular = 2u;
const uint kLobeTransmission = 3u;

struct BsdfParams {
  vec3 baseColor;
  float baseWeight;
};

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

// f(wo, wi) * |cos(wi, n_s)|. Zero when wi leaves through the other side of the geometry, so
// shading normals never let light leak through surfaces.
vec3 bsdf_eval(BsdfParams p, BsdfFrame frame, vec3 wo, vec3 wi) {
  if (dot(wi, frame.geometricNormal) <= 0.0) return vec3(0.0);
  return p.baseWeight * p.baseColor * lambert_eval_cos(dot(wi, frame.shadingNormal));
}

float bsdf_pdf(BsdfParams p, BsdfFrame frame, vec3 wo, vec3 wi) {
  if (dot(wi, frame.geometricNormal) <= 0.0) return 0.0;
  return lambert_pdf(dot(wi, frame.shadingNormal));
}

BsdfSample bsdf_sample(BsdfParams p, BsdfFrame frame, vec3 wo, vec3 u) {
  BsdfSample s;
  s.lobe = kLobeDiffuse;
  s.direction = to_world(lambert_sample_local(u.xy), frame.shadingNormal);
  const float cosTheta = dot(s.direction, frame.shadingNormal);
  s.pdf = lambert_pdf(cosTheta);
  if (s.pdf <= 0.0 || dot(s.direction, frame.geometricNormal) <= 0.0) {
    s.pdf = 0.0;
    s.weight = vec3(0.0);
    return s;
  }
  // f * cos / pdf = albedo exactly for cosine sampling.
  s.weight = p.baseWeight * p.baseColor;
  return s;
}

#endif
