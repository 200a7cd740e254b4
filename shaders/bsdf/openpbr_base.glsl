// The OpenPBR base layer (so far): a metal (GGX + F82-tint Fresnel, with Kulla-Conty
// multiple-scattering compensation from tables our own tool computes) mixed by base_metalness
// with a dielectric base, which is GGX specular reflection (Fresnel from specular_ior, scaled
// by specular_weight and specular_color) over a Lambertian diffuse. The diffuse lobe is scaled
// by (1 - F(cos_o)) (1 - F(cos_i)), which keeps it reciprocal and the total albedo <= 1;
// dielectric compensation, transmission, coat, fuzz and thin film come later.
// Local frame (n = +Z); wo.z > 0. Shared with C++.
#ifndef HIPR_OPENPBR_BASE_GLSL
#define HIPR_OPENPBR_BASE_GLSL

#include "fresnel.glsl"
#include "ggx_energy_table.glsl"

// The energy tables: arrays in C++, a storage buffer on the GPU (kBindingBsdfTables), laid out
// as kGgxEnergy followed by kGgxEnergyAverage.
#ifdef __cplusplus
HIPR_FN float ggx_energy_entry(int i) { return kGgxEnergy[i]; }
HIPR_FN float ggx_energy_average_entry(int i) { return kGgxEnergyAverage[i]; }
#else
HIPR_FN float ggx_energy_entry(int i) { return b_bsdf_tables[i]; }
HIPR_FN float ggx_energy_average_entry(int i) { return b_bsdf_tables[kGgxTableSize * kGgxTableSize + i]; }
#endif
#include "lambert.glsl"
#include "microfacet.glsl"

struct BaseParams {
  vec3 baseColor;  // already times base_weight
  float metalness;
  vec3 specularColor;
  float specularWeight;
  float specularIor;
  float alpha;  // GGX roughness parameter
};

// Bilinear lookups of the generated tables: rows by roughness = sqrt(alpha), columns by
// sqrt(mu) (denser near grazing).
HIPR_FN float ggx_energy(float mu, float alpha) {
  const float last = float(kGgxTableSize - 1);
  const float r = clamp(sqrt(alpha), 0.0f, 1.0f) * last;
  const float m = sqrt(clamp(mu, 0.0f, 1.0f)) * last;
  const int r0 = min(int(r), kGgxTableSize - 2);
  const int m0 = min(int(m), kGgxTableSize - 2);
  const float fr = r - float(r0);
  const float fm = m - float(m0);
  const int i = r0 * kGgxTableSize + m0;
  const float low = mix(ggx_energy_entry(i), ggx_energy_entry(i + 1), fm);
  const float high = mix(ggx_energy_entry(i + kGgxTableSize), ggx_energy_entry(i + kGgxTableSize + 1), fm);
  return mix(low, high, fr);
}

HIPR_FN float ggx_energy_average(float alpha) {
  const float r = clamp(sqrt(alpha), 0.0f, 1.0f) * float(kGgxTableSize - 1);
  const int r0 = min(int(r), kGgxTableSize - 2);
  return mix(ggx_energy_average_entry(r0), ggx_energy_average_entry(r0 + 1), r - float(r0));
}

// Energy single scattering misses at cos_o: the share of the metal lobe sampled as the
// (cosine-shaped) multiple-scattering term.
HIPR_FN float metal_ms_fraction(float cos_o, float alpha) { return clamp(1.0f - ggx_energy(cos_o, alpha), 0.0f, 1.0f); }

// Kulla-Conty multiple-scattering term of the metal, f_ms * cos_i, with the Fresnel of the
// hemispherical average (Schlick's average through F0; the F82 tint is left out of it).
HIPR_FN vec3 metal_ms_eval_cos(BaseParams p, float cos_o, float cos_i) {
  const float e_avg = ggx_energy_average(p.alpha);
  if (e_avg >= 1.0f) return vec3(0.0f);
  const vec3 f_avg = p.baseColor + (vec3(1.0f) - p.baseColor) * (1.0f / 21.0f);
  const vec3 f_ms = f_avg * f_avg * e_avg / (vec3(1.0f) - f_avg * (1.0f - e_avg));
  const float shape = (1.0f - ggx_energy(cos_o, p.alpha)) * (1.0f - ggx_energy(cos_i, p.alpha)) /
                      (kPi * (1.0f - e_avg));
  return f_ms * (shape * cos_i);
}

// Sampling probabilities of the three lobes (diffuse, dielectric specular, metal) for wo.
HIPR_FN vec3 base_lobe_probabilities(BaseParams p, float cos_o) {
  const float fs = p.specularWeight > 0.0f ? min(p.specularWeight * fresnel_dielectric(cos_o, p.specularIor), 1.0f) : 0.0f;
  const float diffuse = (1.0f - p.metalness) * luminance(p.baseColor) * (1.0f - fs);
  const float specular = (1.0f - p.metalness) * fs * luminance(p.specularColor);
  const float metal = p.metalness > 0.0f ? p.metalness * luminance(fresnel_f82_tint(p.baseColor, p.specularColor, cos_o)) : 0.0f;
  const float total = diffuse + specular + metal;
  return total > 0.0f ? vec3(diffuse, specular, metal) / total : vec3(0.0f);
}

// f(wo, wi) * cos(wi). Lobes with zero weight cost nothing: a Lambert-only material (no
// specular, no metal) never touches the microfacet code or the tables.
HIPR_FN vec3 base_eval_cos(BaseParams p, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
  vec3 result = vec3(0.0f);
  const bool has_specular = p.specularWeight > 0.0f && p.metalness < 1.0f;
  const bool has_metal = p.metalness > 0.0f;
  float spec = 0.0f;
  vec3 h = vec3(0.0f, 0.0f, 1.0f);
  if (has_specular || has_metal) {
    h = normalize(wo + wi);
    spec = ggx_reflection_eval_cos(wo, wi, p.alpha);
  }
  if (p.metalness < 1.0f) {
    float diffuse = lambert_eval_cos(wi.z);
    vec3 dielectric = vec3(0.0f);
    if (has_specular) {
      const float fo = min(p.specularWeight * fresnel_dielectric(wo.z, p.specularIor), 1.0f);
      const float fi = min(p.specularWeight * fresnel_dielectric(wi.z, p.specularIor), 1.0f);
      const float fh = min(p.specularWeight * fresnel_dielectric(dot(wo, h), p.specularIor), 1.0f);
      diffuse *= (1.0f - fo) * (1.0f - fi);
      dielectric = p.specularColor * (fh * spec);
    }
    result += (1.0f - p.metalness) * (p.baseColor * diffuse + dielectric);
  }
  if (has_metal)
    result += p.metalness * (fresnel_f82_tint(p.baseColor, p.specularColor, dot(wo, h)) * spec +
                             metal_ms_eval_cos(p, wo.z, wi.z));
  return result;
}

HIPR_FN float base_pdf(BaseParams p, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const vec3 w = base_lobe_probabilities(p, wo.z);
  float pdf = w.x * lambert_pdf(wi.z);
  if (w.y + w.z > 0.0f) {
    const float ggx = ggx_reflection_pdf(wo, wi, p.alpha);
    const float q = w.z > 0.0f ? metal_ms_fraction(wo.z, p.alpha) : 0.0f;
    pdf += w.y * ggx + w.z * ((1.0f - q) * ggx + q * lambert_pdf(wi.z));
  }
  return pdf;
}

// Picks a lobe with u_lobe, samples a direction from it; returns the lobe index
// (0 diffuse, 1 dielectric specular, 2 metal) or -1 for no sample.
HIPR_FN int base_sample(BaseParams p, vec3 wo, vec2 u, float u_lobe, OUT(vec3) wi) {
  wi = vec3(0.0f, 0.0f, 1.0f);
  const vec3 w = base_lobe_probabilities(p, wo.z);
  if (w.x + w.y + w.z <= 0.0f || wo.z <= 0.0f) return -1;
  if (u_lobe < w.x) {
    wi = lambert_sample_local(u);
    return 0;
  }
  // Within the metal lobe, the rest of u_lobe picks the multiple-scattering term.
  if (u_lobe >= w.x + w.y && (u_lobe - w.x - w.y) < w.z * metal_ms_fraction(wo.z, p.alpha)) {
    wi = lambert_sample_local(u);
    return 2;
  }
  const vec3 m = ggx_sample_visible_normal(wo, p.alpha, u);
  wi = 2.0f * dot(wo, m) * m - wo;
  if (wi.z <= 0.0f) return -1;
  return u_lobe < w.x + w.y ? 1 : 2;
}

#endif
