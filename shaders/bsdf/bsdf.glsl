// The BSDF interface the integrator calls. Directions are world space and unit length; `wo`
// points away from the surface toward the previous vertex, `wi` toward the next. The lobes
// live in openpbr.glsl (local frame, shared with the C++ tests); this file moves directions
// into the shading frame, keeps shading normals from leaking light through surfaces, and
// reports the lobe class of every sample.
#ifndef HIPR_BSDF_GLSL
#define HIPR_BSDF_GLSL

#include "openpbr.glsl"

struct BsdfFrame {
  vec3 shadingNormal;
  vec3 geometricNormal;  // on the side of wo
  vec3 tangent;          // anisotropy direction; any vector not along the normal otherwise
};

struct BsdfSample {
  vec3 direction;
  vec3 weight;  // f * |cos| / pdf
  float pdf;    // solid angle; 0 = no sample; 1 for a delta event
  uint lobe;
  bool isDelta;  // no density: no MIS with light sampling, and light sampling never finds it
};

void bsdf_basis(BsdfFrame frame, out vec3 t, out vec3 b) {
  const vec3 n = frame.shadingNormal;
  t = frame.tangent - n * dot(n, frame.tangent);
  if (dot(t, t) < 1.0e-10) {
    make_basis(n, t, b);
    return;
  }
  t = normalize(t);
  b = cross(n, t);
}

vec3 bsdf_to_local(BsdfFrame frame, vec3 v) {
  vec3 t, b;
  bsdf_basis(frame, t, b);
  return vec3(dot(v, t), dot(v, b), dot(v, frame.shadingNormal));
}

vec3 bsdf_to_world(BsdfFrame frame, vec3 v) {
  vec3 t, b;
  bsdf_basis(frame, t, b);
  return v.x * t + v.y * b + v.z * frame.shadingNormal;
}

// wo as the lobes see it: a shading normal can face slightly away from a wo that the
// geometric normal accepts; lift it just above the horizon instead of losing the sample.
vec3 bsdf_local_wo(BsdfFrame frame, vec3 wo) {
  vec3 w = bsdf_to_local(frame, wo);
  w.z = max(w.z, 1.0e-4f);
  return normalize(w);
}

// A direction counts only when the geometric and the shading normal agree on its side.
bool bsdf_sides_agree(BsdfFrame frame, vec3 wi_world, vec3 wi_local) {
  const float g = dot(wi_world, frame.geometricNormal);
  return g > 0.0 ? wi_local.z > 0.0 : (g < 0.0 && wi_local.z < 0.0);
}

// f(wo, wi) * |cos(wi, n_s)|.
vec3 bsdf_eval(OpenPbrParams p, BsdfFrame frame, vec3 wo, vec3 wi) {
  const vec3 wi_local = bsdf_to_local(frame, wi);
  if (!bsdf_sides_agree(frame, wi, wi_local)) return vec3(0.0);
  return openpbr_eval_cos(p, bsdf_local_wo(frame, wo), wi_local);
}

float bsdf_pdf(OpenPbrParams p, BsdfFrame frame, vec3 wo, vec3 wi) {
  const vec3 wi_local = bsdf_to_local(frame, wi);
  if (!bsdf_sides_agree(frame, wi, wi_local)) return 0.0;
  return openpbr_pdf(p, bsdf_local_wo(frame, wo), wi_local);
}

BsdfSample bsdf_sample(OpenPbrParams p, BsdfFrame frame, vec3 wo, vec3 u) {
  BsdfSample s;
  s.pdf = 0.0;
  s.weight = vec3(0.0);
  s.isDelta = false;
  const vec3 wo_local = bsdf_local_wo(frame, wo);
  const OpenPbrSample ls = openpbr_sample(p, wo_local, u.xy, u.z);
  s.lobe = ls.lobe;
  if (!ls.valid) return s;
  if (ls.delta) {  // straight through, exactly: -wo needs no frame
    s.direction = -wo;
    s.isDelta = true;
    s.pdf = 1.0;
    s.weight = ls.deltaWeight;
    return s;
  }
  s.direction = bsdf_to_world(frame, ls.wi);
  if (!bsdf_sides_agree(frame, s.direction, ls.wi)) return s;
  s.pdf = openpbr_pdf(p, wo_local, ls.wi);
  if (!(s.pdf > 0.0)) {
    s.pdf = 0.0;
    return s;
  }
  s.weight = openpbr_eval_cos(p, wo_local, ls.wi) / s.pdf;
  return s;
}

#endif
