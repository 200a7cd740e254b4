// EON: the energy-preserving Oren-Nayar diffuse lobe of OpenPBR (base_diffuse_roughness),
// after Portsmouth, Kutz and Hill, "EON: A practical energy-preserving rough diffuse BRDF".
// It is Fujii's "qualitative" Oren-Nayar (FON) single scattering plus a Kulla-Conty style
// multiple-scattering term built from FON's closed-form directional albedo, so a white rough
// surface reflects all the light at every roughness and angle. Roughness 0 is exactly Lambert.
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

// f(wo, wi) cos(wi); roughness in [0, 1] (clamped), rho the diffuse albedo colour.
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
  // The multiply-scattered colour: geometric series of bounces between the microfacets that
  // sums to rho^2 E_avg / (1 - rho (1 - E_avg)); it is 1 for a white surface.
  const float e_avg = a * (1.0f + kEonC2 * r);
  const vec3 rho_ms = rho * rho * e_avg / (vec3(1.0f) - rho * (1.0f - e_avg));
  return (single_scattering + rho_ms * (kInvPi * shape)) * wi.z;
}

// Cosine-weighted sampling; the lobe is close enough to cosine-shaped that weights stay
// within a small factor of the albedo.
HIPR_FN float eon_pdf(vec3 wo, vec3 wi) { return wo.z > 0.0f ? max(wi.z, 0.0f) * kInvPi : 0.0f; }

HIPR_FN vec3 eon_sample(vec2 u) { return sample_cosine_hemisphere(u); }

#endif
