// OpenPBR's metal: GGX reflection with the F82-tint Fresnel (base_color at normal incidence,
// specular_color bending the edge), plus the multiple-scattering term of Kulla & Conty (2017)
// from the generated E / E_avg tables, so a white metal keeps its energy at any roughness.
// A thin film on top changes the single-scattering Fresnel (thin_film_metal.glsl), not the
// multiple-scattering term.
// Local frame (n = +Z), wo.z > 0, reflection only. Shared with C++.
#ifndef HIPR_METAL_GLSL
#define HIPR_METAL_GLSL

#include "energy_tables.glsl"
#include "fresnel.glsl"
#include "lambert.glsl"
#include "microfacet.glsl"
#include "thin_film_metal.glsl"

// Energy single scattering misses toward wo: the share of the lobe sampled as the
// (cosine-shaped) multiple-scattering term.
HIPR_FN float metal_ms_fraction(vec3 wo, vec2 alpha) {
  return clamp(1.0f - ggx_energy(wo.z, ggx_alpha_for_tables(alpha)), 0.0f, 1.0f);
}

// f_ms * cos_i, with the Fresnel of the hemispherical average (Schlick's average through F0;
// the F82 tint is left out of it).
HIPR_FN vec3 metal_ms_eval_cos(vec3 f0, vec2 alpha, vec3 wo, vec3 wi) {
  const float e_avg = ggx_energy_average(ggx_alpha_for_tables(alpha));
  if (e_avg >= 1.0f) return vec3(0.0f);
  const vec3 f_avg = f0 + (vec3(1.0f) - f0) * (1.0f / 21.0f);
  const vec3 f_ms = f_avg * f_avg * e_avg / (vec3(1.0f) - f_avg * (1.0f - e_avg));
  const float shape = metal_ms_fraction(wo, alpha) * metal_ms_fraction(wi, alpha) / (kPi * (1.0f - e_avg));
  return f_ms * (shape * ggx_isotropy(alpha) * wi.z);
}

// film = (thin_film_weight, thin_film_ior, thickness in nm, index of the medium above the film).
HIPR_FN vec3 metal_eval_cos(vec3 f0, vec3 tint, vec4 film, vec2 alpha, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
  const vec3 h = normalize(wo + wi);
  return metal_fresnel(f0, tint, film, dot(wo, h)) * ggx_reflection_eval_cos(wo, wi, alpha) +
         metal_ms_eval_cos(f0, alpha, wo, wi);
}

HIPR_FN float metal_pdf(vec2 alpha, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const float q = metal_ms_fraction(wo, alpha);
  return (1.0f - q) * ggx_reflection_pdf(wo, wi, alpha) + q * lambert_pdf(wi.z);
}

// u_choice picks the multiple-scattering term with probability metal_ms_fraction.
HIPR_FN bool metal_sample(vec2 alpha, vec3 wo, vec2 u, float u_choice, OUT(vec3) wi) {
  if (u_choice < metal_ms_fraction(wo, alpha)) {
    wi = lambert_sample_local(u);
    return true;
  }
  const vec3 m = ggx_sample_visible_normal(wo, alpha, u);
  wi = 2.0f * dot(wo, m) * m - wo;
  return wi.z > 0.0f;
}

#endif
