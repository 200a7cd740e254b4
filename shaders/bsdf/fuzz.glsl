// The fuzz (sheen) lobe of OpenPBR 1.1 on its own, with unit colour: the LTC sheen of Zeltner,
// Burley and Chiang (2022, "Practical Multiple-Scattering Sheen Using Linearly Transformed
// Cosines"), which the specification names. A volumetric layer of fibre-like SGGX microflakes
// (unit density and thickness, white) was simulated and fitted, per view cosine x and
// roughness alpha (= fuzz_roughness), by
//   - its directional albedo R(x, alpha), and
//   - a linearly transformed cosine for the lobe's shape, M^-1 = [[a, 0, b], [0, a, 0], [0, 0, 1]]
//     in a frame whose x axis points along wo's azimuth.
// R comes from our own random walks through that volume (tools/sheen_volume.cpp), tabulated on
// the paper's grid (32 x 32, mu and alpha uniform) and read bilinearly as its table is; a and b
// from the paper's analytic fits of its table (rational functions). docs/openpbr.md compares.
// The LTC keeps z, so the whole distribution lies above the horizon: it integrates to one over
// the hemisphere, it is sampled exactly (a cosine sample pushed through M), and the lobe's albedo
// is exactly R. Like every LTC lobe it is fitted per view direction and not reciprocal.
// Local frame (n = +Z), unit directions. Shared with C++.
#ifndef HIPR_FUZZ_GLSL
#define HIPR_FUZZ_GLSL

#include "../common/sampling.glsl"
#include "energy_tables.glsl"

// As alpha goes to 0 the LTC's a goes to 0: the lobe flattens onto the horizon, where no
// sampler resolves it. Below this the look hardly changes.
const float kFuzzMinRoughness = 0.05f;

HIPR_FN float fuzz_clamp_roughness(float roughness) { return clamp(roughness, kFuzzMinRoughness, 1.0f); }

// The LTC's a and b at x = cos_o, y = alpha: the paper's rational fits of its table.
HIPR_FN float fuzz_ltc_a(float x, float y) { return (2.58126f * x + 0.813703f * y) * y / (1.0f + 0.310327f * x * x + 2.60994f * x * y); }

HIPR_FN float fuzz_ltc_b(float x, float y) {
  return sqrt(max(1.0f - x, 0.0f)) * (y - 1.0f) * y * y * y / (0.0000254053f + 1.71228f * x - 1.71506f * x * y + 1.34174f * y * y);
}

// Albedo of the lobe (unit colour) seen at cos_o = mu: the volume's R.
HIPR_FN float fuzz_energy(float mu, float roughness) {
  return table_2d(kTableFuzzAlbedo, kFuzzTableSize, kFuzzTableSize, fuzz_clamp_roughness(roughness), mu);
}

// The frame of the fit: rotate about z so that wo's azimuth becomes 0 (sign = -1), or back (+1).
HIPR_FN vec3 fuzz_rotate(vec3 v, vec3 wo, float sign) {
  const float r2 = wo.x * wo.x + wo.y * wo.y;
  if (r2 <= 0.0f) return v;
  const float inv = 1.0f / sqrt(r2);
  const float c = wo.x * inv, s = sign * wo.y * inv;
  return vec3(c * v.x - s * v.y, s * v.x + c * v.y, v.z);
}

// Density of the LTC at w (in the fit's frame): D(M^-1 w / |M^-1 w|) |M^-1| / |M^-1 w|^3 with
// D the clamped cosine over pi, which is w.z a^2 / (pi |M^-1 w|^4).
HIPR_FN float fuzz_ltc_density(vec3 w, float a, float b) {
  if (w.z <= 0.0f || a <= 0.0f) return 0.0f;
  const vec3 v = vec3(a * w.x + b * w.z, a * w.y, w.z);
  const float len2 = dot(v, v);
  if (len2 <= 0.0f) return 0.0f;
  const float k = a / len2;
  return w.z * k * k * kInvPi;
}

// Both the pdf of fuzz_sample and, times R, the lobe's f cos.
HIPR_FN float fuzz_pdf(float roughness, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const float x = min(wo.z, 1.0f), y = fuzz_clamp_roughness(roughness);
  return fuzz_ltc_density(fuzz_rotate(wi, wo, -1.0f), fuzz_ltc_a(x, y), fuzz_ltc_b(x, y));
}

// f(wo, wi) cos(wi) for unit fuzz colour; roughness in [0, 1] (clamped as above).
HIPR_FN float fuzz_eval_cos(float roughness, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  return fuzz_energy(wo.z, roughness) * fuzz_pdf(roughness, wo, wi);
}

// A cosine sample pushed through M = [[1/a, 0, -b/a], [0, 1/a, 0], [0, 0, 1]], then rotated to wo.
HIPR_FN vec3 fuzz_sample(float roughness, vec3 wo, vec2 u) {
  const float x = clamp(wo.z, 0.0f, 1.0f), y = fuzz_clamp_roughness(roughness);
  const float a = fuzz_ltc_a(x, y), b = fuzz_ltc_b(x, y);
  const vec3 c = sample_cosine_hemisphere(u);
  const vec3 w = normalize(vec3((c.x - b * c.z) / a, c.y / a, c.z));
  return fuzz_rotate(w, wo, 1.0f);
}

#endif
