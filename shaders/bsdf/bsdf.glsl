// The BSDF interface the integrator calls. Directions are world space and unit length; `wo`
// points away from the surface toward the previous vertex, `wi` toward the next. The lobes
// live in openpbr.glsl (local frame, shared with the C++ tests); this file moves directions
// into the shading frame, keeps shading normals from leaking light through surfaces, and
// reports the lobe class of every sample. A shading point is prepared once (bsdf_point): its
// frame, wo in that frame and the lobes' context serve every eval, pdf and sample there.
#ifndef HIPR_BSDF_GLSL
#define HIPR_BSDF_GLSL

#include "openpbr.glsl"

struct BsdfFrame {
  vec3 shadingNormal;
  vec3 geometricNormal;  // on the side of wo
  vec3 tangent;          // anisotropy direction; any vector not along the normal otherwise
};

// One shading point seen from wo.
struct BsdfPoint {
  OpenPbrParams params;
  OpenPbrContext context;
  vec3 shadingNormal;
  vec3 geometricNormal;
  vec3 tangent;    // orthonormal shading basis: tangent, bitangent, shadingNormal
  vec3 bitangent;
  vec3 wo;         // world
  vec3 woLocal;    // in the shading basis, lifted above the horizon (see bsdf_point)
};

struct BsdfSample {
  vec3 direction;
  vec3 weight;  // f * |cos| / pdf
  float pdf;    // solid angle; 0 = no sample; 1 for a delta event
  uint lobe;
  bool isDelta;  // no density: no MIS with light sampling, and light sampling never finds it
};

vec3 bsdf_to_local(BsdfPoint s, vec3 v) {
  return vec3(dot(v, s.tangent), dot(v, s.bitangent), dot(v, s.shadingNormal));
}

vec3 bsdf_to_world(BsdfPoint s, vec3 v) { return v.x * s.tangent + v.y * s.bitangent + v.z * s.shadingNormal; }

BsdfPoint bsdf_point(OpenPbrParams params, BsdfFrame frame, vec3 wo) {
  BsdfPoint s;
  s.params = params;
  s.shadingNormal = frame.shadingNormal;
  s.geometricNormal = frame.geometricNormal;
  vec3 t = frame.tangent - frame.shadingNormal * dot(frame.shadingNormal, frame.tangent);
  if (dot(t, t) < 1.0e-10) {
    make_basis(frame.shadingNormal, s.tangent, s.bitangent);
  } else {
    s.tangent = normalize(t);
    s.bitangent = cross(frame.shadingNormal, s.tangent);
  }
  s.wo = wo;
  // A shading normal can face slightly away from a wo that the geometric normal accepts; lift
  // wo just above the horizon instead of losing the sample.
  vec3 w = bsdf_to_local(s, wo);
  w.z = max(w.z, 1.0e-4f);
  s.woLocal = normalize(w);
  s.context = openpbr_context(params, s.woLocal);
  return s;
}

// A direction counts only when the geometric and the shading normal agree on its side.
bool bsdf_sides_agree(BsdfPoint s, vec3 wi_world, vec3 wi_local) {
  const float g = dot(wi_world, s.geometricNormal);
  return g > 0.0 ? wi_local.z > 0.0 : (g < 0.0 && wi_local.z < 0.0);
}

// f(wo, wi) * |cos(wi, n_s)|.
vec3 bsdf_eval(BsdfPoint s, vec3 wi) {
  const vec3 wi_local = bsdf_to_local(s, wi);
  if (!bsdf_sides_agree(s, wi, wi_local)) return vec3(0.0);
  return openpbr_eval_cos(s.params, s.context, s.woLocal, wi_local);
}

float bsdf_pdf(BsdfPoint s, vec3 wi) {
  const vec3 wi_local = bsdf_to_local(s, wi);
  if (!bsdf_sides_agree(s, wi, wi_local)) return 0.0;
  return openpbr_pdf(s.params, s.context, s.woLocal, wi_local);
}

BsdfSample bsdf_sample(BsdfPoint s, vec3 u) {
  BsdfSample b;
  b.pdf = 0.0;
  b.weight = vec3(0.0);
  b.isDelta = false;
  const OpenPbrSample ls = openpbr_sample(s.params, s.context, s.woLocal, u.xy, u.z);
  b.lobe = ls.lobe;
  if (!ls.valid) return b;
  if (ls.delta) {  // straight through, exactly: -wo needs no frame
    b.direction = -s.wo;
    b.isDelta = true;
    b.pdf = 1.0;
    b.weight = ls.deltaWeight;
    return b;
  }
  b.direction = bsdf_to_world(s, ls.wi);
  if (!bsdf_sides_agree(s, b.direction, ls.wi)) return b;
  b.pdf = openpbr_pdf(s.params, s.context, s.woLocal, ls.wi);
  if (!(b.pdf > 0.0)) {
    b.pdf = 0.0;
    return b;
  }
  b.weight = openpbr_eval_cos(s.params, s.context, s.woLocal, ls.wi) / b.pdf;
  return b;
}

#endif
