// OpenPBR's coat as a layer over the base, by albedo scaling on the view side:
//   f = C f_coat + (1 - C E_c(mu_o)) t(mu_o) t(mu_i) D f_base
// with E_c the coat lobe's albedo (a rough dielectric reflection, energy_tables.glsl), t the
// coat's colour on one passage and D the darkening from light the coat reflects back onto an
// absorbing base. A white coat over a white base reflects exactly 1 from every direction;
// scaling by the light side too (reciprocal) loses energy (5.3 % at normal incidence with the
// larger of the two sides, used before). OpenPBR's reference implementation scales by the view
// side by default (docs/openpbr.md). Shared with C++.
#ifndef HIPR_COAT_LAYER_GLSL
#define HIPR_COAT_LAYER_GLSL

#include "dielectric.glsl"
#include "energy_tables.glsl"

// Albedo of the coat lobe seen at cos_o = mu, times the coat weight.
HIPR_FN float coat_layer_energy(float coat, float coat_alpha, float coat_eta, float mu) {
  return coat > 0.0f ? coat * dielectric_reflection_energy(mu, coat_alpha, coat_eta) : 0.0f;
}

// The coat's colour on one passage at cos mu outside: coat_color is what two passages at normal
// incidence leave, so one passage at normal incidence is its square root, and a slanted passage
// (the refracted cosine cos_t inside the coat) is longer by 1 / cos_t (Beer-Lambert).
HIPR_FN vec3 coat_passage_tint(vec3 coat_color, float coat, float coat_eta, float mu) {
  if (coat <= 0.0f || min(coat_color.x, min(coat_color.y, coat_color.z)) >= 1.0f) return vec3(1.0f);
  const float m = clamp(mu, 0.0f, 1.0f);
  const float cos_t = sqrt(max(1.0f - (1.0f - m * m) / (coat_eta * coat_eta), 1.0e-4f));
  const vec3 once = pow(clamp(coat_color, vec3(0.0f), vec3(1.0f)), vec3(0.5f / cos_t));
  return mix(vec3(1.0f), once, coat);
}

// A rough coat blurs what is seen through it: OpenPBR recommends roughening the base's specular
// roughness r under a coat of roughness r_c and weight C to mix(r, min(1, r^4 + 2 r_c^4)^(1/4), C)
// (the variances of the two lobes add, once for each crossing).
HIPR_FN float coat_roughened(float roughness, float coat_roughness, float coat) {
  if (coat <= 0.0f) return roughness;
  const float r2 = roughness * roughness, c2 = coat_roughness * coat_roughness;
  return mix(roughness, sqrt(sqrt(min(1.0f, r2 * r2 + 2.0f * c2 * c2))), clamp(coat, 0.0f, 1.0f));
}

// The index the base's specular reflection sees under a coat (OpenPBR: the coat's index mixed in
// by coat weight replaces the ambient one), for a base seen from outside. eta is the base's index
// with specular_weight already applied (ior_with_specular_weight); the weight is taken off, the
// index made relative to the coat, and the weight applied again, so specular_weight 0 still
// means no specular reflection. A base optically thinner than the coat would totally reflect
// from inside it; the specification inverts the ratio instead, which keeps the reflectance the
// same size.
HIPR_FN float specular_eta_under_coat(float eta, float specular_weight, float coat, float coat_eta) {
  if (coat <= 0.0f || eta < 1.0f || specular_weight <= 0.0f) return eta;
  const float weighted = (eta - 1.0f) / (eta + 1.0f);
  const float r = min(weighted / sqrt(min(specular_weight, 1.0e4f)), 0.99f);
  const float ratio = ((1.0f + r) / (1.0f - r)) / mix(1.0f, coat_eta, coat);
  return ior_with_specular_weight(ratio < 1.0f ? 1.0f / ratio : ratio, specular_weight);
}

#endif
