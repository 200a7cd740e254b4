// EON: the energy-preserving Oren-Nayar diffuse lobe of OpenPBR (base_diffuse_roughness),
// after Portsmouth, Kutz and Hill, "EON: A practical energy-preserving rough diffuse BRDF".
// It is Fujii's "qualitative" Oren-Nayar (FON) single scattering plus a Kulla-Conty style
// multiple-scattering term built from FON's closed-form directional albedo, so a white rough
// surface reflects all the light at every roughness and angle. Roughness 0 is exactly Lambert.
// Sampled by the paper's clipped LTC mixed with the cosine; eon_pdf is that mixture's exact pdf.
// Local frame (n = +Z), both directions above the surface, unit length. Shared with C++.
#ifndef HIPR_EON_GLSL
#define HIPR_EON_GLSL

#include "../common/sampling.glsl"

// FON's A = 1 / (1 + kEonC1 r), and its albedo averaged over the hemisphere is
// A (1 + kEonC2 r): closed forms of the integrals of FON over the hemisphere.
const float kEonC1 = 0.5f - 2.0f / (3.0f * kPi);
const float kEonC2 = 2.0f / 3.0f - 28.0f / (15.0f * kPi);

HIPR_FN float eon_fon_a(float roughness) { return 1.0f / (1.0f + kEonC1 * roughness); }

// (1 - E_FON(mu)) / (A r): the share of light FON loses at cosine mu, with the roughness
// factored out so roughness 0 gives an exact zero instead of a difference of two near-ones.
// E_FON(mu) = A + (B / pi) G(mu) with B = r A, hence 1 - E_FON = A r (kEonC1 - G / pi).
HIPR_FN float eon_fon_loss(float mu) {
  mu = clamp(mu, 0.0f, 1.0f);
  const float s = sqrt(max(1.0f - mu * mu, 0.0f));
  // The paper's (s / mu)(1 - s^3) term, rewritten with 1 - s = mu^2 / (1 + s) so that it
  // has no 0/0 at grazing.
  const float g = s * (acos(mu) - s * mu) + (2.0f / 3.0f) * (s * mu * (1.0f + s + s * s) / (1.0f + s) - s);
  return max(kEonC1 - g * kInvPi, 0.0f);
}

// Directional albedo of FON with unit rho (what the compensation restores to 1).
HIPR_FN float eon_fon_albedo(float mu, float roughness) {
  return 1.0f - eon_fon_a(roughness) * roughness * eon_fon_loss(mu);
}

// The multiply-scattered colour: the geometric series of bounces between the microfacets,
// rho^2 E_avg / (1 - rho (1 - E_avg)); 1 for a white surface.
HIPR_FN vec3 eon_rho_ms(vec3 rho, float r) {
  const float e_avg = eon_fon_a(r) * (1.0f + kEonC2 * r);
  return rho * rho * e_avg / (vec3(1.0f) - rho * (1.0f - e_avg));
}

// Directional albedo of EON at cosine mu, in closed form: what single scattering keeps plus
// what the compensation adds back (for lobe-selection weights and layering).
HIPR_FN vec3 eon_albedo(vec3 rho, float roughness, float mu) {
  const float r = clamp(roughness, 0.0f, 1.0f);
  const float e = eon_fon_albedo(mu, r);
  return rho * e + eon_rho_ms(rho, r) * (1.0f - e);
}

// f(wo, wi) cos(wi); roughness in [0, 1] (clamped), rho the diffuse albedo colour in [0, 1].
HIPR_FN vec3 eon_eval_cos(vec3 rho, float roughness, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
  const float r = clamp(roughness, 0.0f, 1.0f);
  const float a = eon_fon_a(r);
  // s = cos(phi) sin(theta_o) sin(theta_i); FON divides it by max(cos) only when positive.
  const float s = dot(wo, wi) - wo.z * wi.z;
  const float s_over_t = s > 0.0f ? s / max(wo.z, wi.z) : s;
  const vec3 single_scattering = rho * (kInvPi * a * (1.0f + r * s_over_t));
  // Multiple scattering: the lost energy at both ends, (1 - E(mu_o))(1 - E(mu_i)) / (1 - E_avg),
  // with every factor's A r pulled out: A r appears twice on top and once below.
  const float loss_avg = kEonC1 - kEonC2;
  const float shape = a * r * eon_fon_loss(wo.z) * eon_fon_loss(wi.z) / loss_avg;
  return (single_scattering + eon_rho_ms(rho, r) * (kInvPi * shape)) * wi.z;
}

// Sampling: the single-scattering part by the paper's "clipped linearly transformed cosine"
// (CLTC), the multiple-scattering part (a share 1 - E_FON(mu_o) of a white surface's
// reflection) by the cosine. The LTC is the matrix M = [a 0 b; 0 c 0; d 0 1] (rows) in the
// frame whose x axis is wo's azimuth, with the paper's fitted a..d. M maps a cosine lobe to
// FON's shape; the part of that lobe M would push below the horizon (z' + d x' <= 0) is
// clipped off before sampling, and the pdf renormalised by what is left, so nothing is lost.
// At roughness 0, M is the identity: both are plain cosine sampling.
HIPR_FN vec4 eon_ltc_coefficients(float mu, float r) {
  const float a = 1.0f + r * (0.303392f + (-0.518982f + 0.111709f * mu) * mu + (-0.276266f + 0.335918f * mu) * r);
  const float b = r * (-1.16407f + 1.15859f * mu + (0.150815f - 0.150105f * mu) * r) / (mu * mu * mu - 1.43545f);
  const float c = 1.0f + (0.20013f + (-0.506373f + 0.261777f * mu) * mu) * r;
  const float d = r * (0.540852f + (-1.01625f + 0.475392f * mu) * mu) / (-1.0743f + mu * (0.0725628f + mu));
  return vec4(a, b, c, d);
}

// The azimuthal direction of wo (any one at normal incidence).
HIPR_FN vec2 eon_ltc_axis(vec3 wo) {
  const float len2 = wo.x * wo.x + wo.y * wo.y;
  return len2 > 0.0f ? vec2(wo.x, wo.y) / sqrt(len2) : vec2(1.0f, 0.0f);
}

// Probability of sampling the cosine: the multiple-scattering share, but at least a fifth,
// because the LTC fit misses FON's retro-reflection peak near grazing, and without the floor
// single weights reach 70 times the albedo there (largest variance over roughness and angle
// measured: 0.05 with the floor, 0.29 without, 0.82 for cosine sampling alone).
HIPR_FN float eon_cosine_probability(float mu_o, float r) { return max(1.0f - eon_fon_albedo(mu_o, r), 0.2f); }

// The clipped cosine keeps the projected-disk region where z' > -d x': a half disk on one side
// and a half ellipse of semi-axis 1 / sqrt(1 + d^2) on the other, area pi (1 + vz) / 2.
HIPR_FN float eon_cltc_pdf(vec4 m, vec3 v) {
  const float det_xz = m.x - m.y * m.w;  // a - b d, the xz block's determinant
  // M^-1 v, written out for this sparse M.
  const vec3 u = vec3((v.x - m.y * v.z) / det_xz, v.y / m.z, (m.x * v.z - m.w * v.x) / det_xz);
  const float len2 = dot(u, u);
  const float vz = 1.0f / sqrt(1.0f + m.w * m.w);
  // Cosine pdf of u / |u|, over the clipped area, times the Jacobian |det M^-1| / |u|^3.
  return max(u.z, 0.0f) / (kPi * 0.5f * (1.0f + vz)) / (m.z * det_xz * len2 * len2);
}

HIPR_FN float eon_pdf(float roughness, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const float r = clamp(roughness, 0.0f, 1.0f);
  const float p_cos = eon_cosine_probability(wo.z, r);
  const vec2 x = eon_ltc_axis(wo);
  const vec3 v = vec3(x.x * wi.x + x.y * wi.y, x.x * wi.y - x.y * wi.x, wi.z);
  return p_cos * wi.z * kInvPi + (1.0f - p_cos) * eon_cltc_pdf(eon_ltc_coefficients(wo.z, r), v);
}

HIPR_FN vec3 eon_sample(float roughness, vec3 wo, vec2 u) {
  const float r = clamp(roughness, 0.0f, 1.0f);
  const float p_cos = eon_cosine_probability(wo.z, r);
  if (u.x < p_cos) return sample_cosine_hemisphere(vec2(u.x / p_cos, u.y));
  u.x = (u.x - p_cos) / (1.0f - p_cos);
  const vec4 m = eon_ltc_coefficients(wo.z, r);
  const float vz = 1.0f / sqrt(1.0f + m.w * m.w);
  // A uniform point of the unit disk, its x squeezed affinely (so still uniform) from the
  // chord [-w, w] onto the kept chord: [-w, vz w] on the side where d x' < 0 (sign s).
  const float radius = sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  const float y = radius * sin(phi);
  const float w = sqrt(max(0.0f, 1.0f - y * y));
  const float side = m.w < 0.0f ? 1.0f : -1.0f;
  const float x = side * (0.5f * (1.0f + vz) * (radius * cos(phi) + w) - w);
  const float z = sqrt(max(0.0f, 1.0f - x * x - y * y));
  // The clip boundary maps onto the horizon; rounding must not push a sample below it.
  const vec3 v = normalize(vec3(m.x * x + m.y * z, m.z * y, max(m.w * x + z, 1.0e-6f)));
  // Back from the LTC frame (x along wo's azimuth) to the local frame.
  const vec2 axis = eon_ltc_axis(wo);
  return vec3(axis.x * v.x - axis.y * v.y, axis.y * v.x + axis.x * v.y, v.z);
}

#endif
