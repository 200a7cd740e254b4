// The fuzz (sheen) lobe of OpenPBR on its own, with unit colour: the "Charlie" microfiber
// distribution of Estevez and Kulla (2017), D(h) = (2 + 1/r) sin(theta_h)^(1/r) / (2 pi), in a
// microfacet BRDF D G2 / (4 cos_o cos_i) with their fitted Smith Lambda and the
// height-correlated G2 = 1 / (1 + Lambda(o) + Lambda(i)): symmetric in the two directions (so
// reciprocal) and, being a Smith model, it never reflects more than it receives. (Their
// "terminator softening" is left out: it applies to one direction only and breaks
// reciprocity. The simpler visibility of Neubelt and Pettineo reflects up to 1.56 times the
// incoming light at grazing for smooth fuzz, which a furnace would show.)
// Sampled uniformly over the hemisphere: the lobe leans toward the horizon, where cosine
// sampling puts few samples (weights measured up to 18 with cosine sampling, below 3 with
// uniform sampling, 2 to 8 times less variance). Its albedo is tabulated by
// tools/make_ggx_tables.cpp; fuzz_layer.glsl reads that table for layering.
// Local frame (n = +Z), unit directions. Shared with C++.
#ifndef HIPR_FUZZ_GLSL
#define HIPR_FUZZ_GLSL

#include "../common/sampling.glsl"

// As r goes to 0 all fibre normals lie in the surface plane: the normalisation 2 + 1/r grows
// without bound and the lobe shrinks to a sliver at grazing that no sampler resolves.
// OpenPBR's fuzz_roughness is in [0, 1]; below this minimum the look hardly changes.
const float kFuzzMinRoughness = 0.07f;

HIPR_FN float fuzz_clamp_roughness(float roughness) { return clamp(roughness, kFuzzMinRoughness, 1.0f); }

// Estevez and Kulla's fit of the Charlie distribution's Lambda: Lambda(mu) = exp(L(mu)) for
// mu < 1/2, mirrored as exp(2 L(1/2) - L(1 - mu)) above so it reaches 0 at the normal. L's five
// coefficients blend their r = 0 and r = 1 fits with weight (1 - r)^2.
HIPR_FN float fuzz_lambda_l(float x, float r) {
  const float t = (1.0f - r) * (1.0f - r);
  const float a = mix(21.5473f, 25.3245f, t);
  const float b = mix(3.82987f, 3.32435f, t);
  const float c = mix(0.19823f, 0.16801f, t);
  const float d = mix(-1.97760f, -1.27393f, t);
  const float e = mix(-4.32054f, -4.85967f, t);
  return a / (1.0f + b * pow(x, c)) + d * x + e;
}

HIPR_FN float fuzz_lambda(float mu, float r) {
  mu = clamp(mu, 0.0f, 1.0f);
  return mu < 0.5f ? exp(fuzz_lambda_l(mu, r)) : exp(2.0f * fuzz_lambda_l(0.5f, r) - fuzz_lambda_l(1.0f - mu, r));
}

// f(wo, wi) cos(wi) for unit fuzz colour; roughness in [0, 1] (clamped as above).
HIPR_FN float fuzz_eval_cos(float roughness, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const float r = fuzz_clamp_roughness(roughness);
  const vec3 h = normalize(wo + wi);
  // sin^2 from the tangent components: 1 - h.z^2 loses everything near the normal.
  const float sin2_h = h.x * h.x + h.y * h.y;
  const float d = (2.0f + 1.0f / r) * pow(sin2_h, 0.5f / r) * (0.5f * kInvPi);
  const float g2 = 1.0f / (1.0f + fuzz_lambda(wo.z, r) + fuzz_lambda(wi.z, r));
  return d * g2 / (4.0f * wo.z);
}

HIPR_FN float fuzz_pdf(vec3 wo, vec3 wi) { return wo.z > 0.0f && wi.z > 0.0f ? 0.5f * kInvPi : 0.0f; }

HIPR_FN vec3 fuzz_sample(vec2 u) { return sample_uniform_hemisphere(u); }

#endif
