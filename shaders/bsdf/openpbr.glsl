// The OpenPBR 1.1 surface as one BSDF in the local shading frame (n = +Z, x = tangent), wo.z > 0.
// Shared with C++ (tests/openpbr_test.cpp runs these very functions).
//
// Layers, top to bottom, combined by albedo scaling with generated albedo tables:
//   fuzz     LTC sheen (fuzz.glsl), weight F, colour; below it everything is scaled by
//            1 - F E_f(wo) (fuzz_layer.glsl);
//   coat     GGX dielectric reflection (coat_ior, coat_roughness), weight C; everything below is
//            scaled by 1 - C E_c(wo) (coat_layer.glsl), tinted by coat_color along the
//            refracted path on the way in and out, and its reflection darkened by the light the
//            coat reflects back onto an absorbing base (coat_darkening); a rough coat roughens
//            the base's specular (coat_roughened, applied where the parameters are resolved);
//            both layers scale by the view side only, as the specification's albedo scaling
//            and its reference implementation do: exact energy for any white stack, not
//            reciprocal (docs/openpbr.md);
//   base     mix by base_metalness of
//            metal       F82-tint GGX with multiple-scattering compensation (metal.glsl);
//            dielectric  specular reflection (specular_ior modulated by specular_weight and
//                        taken relative to the coat's index, tinted by specular_color,
//                        thin-film iridescence on its Fresnel),
//                        mixed by transmission_weight t with
//                        t:     the transmitting interface, reflection + refraction (or a
//                               thin-walled slab), compensated by 1 / E_rt(wo) so rough glass
//                               keeps its energy; refraction tinted by transmission_color;
//                        1 - t: diffuse (EON, base_diffuse_roughness) under the specular
//                               layer, scaled by
//                               (1 - E_r(wo)) (1 - E_r(wi)) / (1 - E_r,avg), which is reciprocal
//                               and gives exactly 1 for a white Lambertian base;
//            the diffuse is mixed by subsurface_weight with subsurface_color: our approximation
//            of subsurface until a volumetric walk exists (diffuse reflection; thin-walled, half
//            of it is transmitted diffusely to the far side).
// Approximations, documented (docs/openpbr.md): thin film changes the reflected colour but not
// the energy left to the layers below; under a coat it sees the coat's index above it at the
// outside angle (so does the base's reflection); glass under a coat keeps its own index; the coat follows the base's shading normal; anisotropic
// lobes read the isotropic tables at one stand-in alpha (ggx_alpha_for_tables; the larger of
// the two for the diffuse under the specular layer); refraction leaves out the 1/eta^2 radiance
// scaling (it cancels for paths that enter and leave an object).
#ifndef HIPR_OPENPBR_GLSL
#define HIPR_OPENPBR_GLSL

#include "dielectric.glsl"
#include "energy_tables.glsl"
#include "coat_layer.glsl"
#include "eon.glsl"
#include "fuzz_layer.glsl"
#include "lambert.glsl"
#include "metal.glsl"
#include "thin_film.glsl"

// Lobe classes every sample reports (HiPR's tile weights depend on them).
const uint kLobeDiffuse = 0u;
const uint kLobeGlossy = 1u;
const uint kLobeSpecular = 2u;
const uint kLobeTransmission = 3u;

// GGX lobes narrower than this (roughness ~0.1) count as "specular" for HiPR.
const float kSpecularAlpha = 0.01f;

// Resolved parameters at one surface point (textures applied, sidedness decided).
struct OpenPbrParams {
  vec3 baseColor;           // base_color x base_weight
  float metalness;
  float diffuseRoughness;   // base_diffuse_roughness
  vec3 specularColor;
  float specularWeight;     // scales the metal's Fresnel, up to 1 (the dielectric's is folded into eta)
  vec2 alpha;               // specular GGX alpha along tangent and bitangent
  float eta;                // relative index across the base interface seen from wo, specular_weight applied
  float transmission;       // transmission_weight
  vec3 transmissionColor;   // tint of refracted light (white when a volume absorbs instead)
  bool thinWalled;
  float subsurface;         // subsurface_weight
  vec3 subsurfaceColor;
  float coat;               // coat_weight; 0 when wo is not on the coated side
  vec3 coatColor;
  float coatAlpha;
  float coatEta;
  float coatDarkening;
  float fuzz;               // fuzz_weight; 0 when wo is not on the outer side
  vec3 fuzzColor;
  float fuzzRoughness;
  float thinFilm;           // thin_film_weight
  float thinFilmThickness;  // nanometres
  float thinFilmIor;
};

// What eval, pdf and sample need from wo alone.
struct OpenPbrContext {
  float fuzzEnergy;       // F E_f(wo)
  float coatEnergy;       // C E_c(wo)
  vec3 coatTint;          // the coat's colour on the passage toward wo
  vec3 darkening;         // of the base's reflection under the coat
  float specularEta;      // index of the opaque dielectric's reflection, relative to the coat
  float filmAmbient;      // index of the medium above the thin film: 1, or the coat's mixed in
  float specularEnergy;   // E_r(wo) of that reflection, 0 when index-matched
  float specularAverage;  // its cosine-weighted average
  float interfaceEnergy;  // E_rt(wo), or E(wo) for a thin-walled slab: the transmitting interface
  vec4 weights;           // sampling probabilities: coat, metal, dielectric reflection, interface
  float diffuseWeight;    // ... the diffuse lobe
  float fuzzWeight;       // ... and the fuzz (all six sum to 1, or all are 0)
};

HIPR_FN bool specular_reflects(OpenPbrParams p) { return !index_matched(p.eta); }
HIPR_FN bool opaque_specular_reflects(OpenPbrContext c) { return !index_matched(c.specularEta); }

// Diffuse colours reflected to wo's side and transmitted to the far side.
HIPR_FN vec3 diffuse_reflection_color(OpenPbrParams p) {
  return p.baseColor * (1.0f - p.subsurface) + p.subsurfaceColor * (p.subsurface * (p.thinWalled ? 0.5f : 1.0f));
}
HIPR_FN vec3 diffuse_transmission_color(OpenPbrParams p) {
  return p.thinWalled ? p.subsurfaceColor * (0.5f * p.subsurface) : vec3(0.0f);
}

// Share of diffuse samples sent to the far side.
HIPR_FN float diffuse_transmission_probability(OpenPbrParams p) {
  const float t = luminance(diffuse_transmission_color(p));
  return t > 0.0f ? t / (t + luminance(diffuse_reflection_color(p))) : 0.0f;
}

// Light the coat reflects back down meets the base again; an absorbing base loses part of it.
// With K the coat's internal diffuse reflectance and rho the base albedo the base's reflectance
// becomes rho (1 - K) / (1 - K rho) (no change for rho = 1, so white furnaces stay white).
HIPR_FN vec3 coat_darkening(OpenPbrParams p) {
  const float amount = p.coat * p.coatDarkening;
  if (amount <= 0.0f) return vec3(1.0f);
  const float k = 1.0f - (1.0f - dielectric_reflection_energy_average(p.coatAlpha, p.coatEta)) / (p.coatEta * p.coatEta);
  // Light the base transmits is not lost: glass under a clear coat keeps its energy.
  const vec3 rho = mix((1.0f - p.transmission) * diffuse_reflection_color(p) + p.transmission * p.transmissionColor, p.baseColor,
                       p.metalness);
  return mix(vec3(1.0f), (1.0f - k) / (vec3(1.0f) - k * clamp(rho, vec3(0.0f), vec3(1.0f))), amount);
}

// Albedo of the specular layer over the diffuse. The tables are isotropic: an anisotropic lobe
// takes the larger albedo of its two alphas, so the diffuse under it is never overestimated (its
// reflection varies with alpha both ways once total internal reflection is involved).
HIPR_FN float specular_layer_energy(float mu, vec2 alpha, float eta) {
  const float e = dielectric_reflection_energy(mu, alpha.x, eta);
  return alpha.x == alpha.y ? e : max(e, dielectric_reflection_energy(mu, alpha.y, eta));
}
HIPR_FN float specular_layer_energy_average(vec2 alpha, float eta) {
  const float e = dielectric_reflection_energy_average(alpha.x, eta);
  return alpha.x == alpha.y ? e : max(e, dielectric_reflection_energy_average(alpha.y, eta));
}

HIPR_FN OpenPbrContext openpbr_context(OpenPbrParams p, vec3 wo) {
  OpenPbrContext c;
  const float mu_o = wo.z;
  c.fuzzEnergy = p.fuzz > 0.0f ? p.fuzz * fuzz_energy(mu_o, p.fuzzRoughness) : 0.0f;
  c.coatEnergy = coat_layer_energy(p.coat, p.coatAlpha, p.coatEta, mu_o);
  c.coatTint = coat_passage_tint(p.coatColor, p.coat, p.coatEta, mu_o);
  c.darkening = p.coat > 0.0f ? coat_darkening(p) : vec3(1.0f);
  c.specularEta = specular_eta_under_coat(p.eta, p.specularWeight, p.coat, p.coatEta);
  c.filmAmbient = p.coat > 0.0f ? mix(1.0f, p.coatEta, p.coat) : 1.0f;
  const float a = ggx_alpha_for_tables(p.alpha);
  c.specularEnergy = opaque_specular_reflects(c) ? specular_layer_energy(mu_o, p.alpha, c.specularEta) : 0.0f;
  c.specularAverage = opaque_specular_reflects(c) ? specular_layer_energy_average(p.alpha, c.specularEta) : 0.0f;
  c.interfaceEnergy = 1.0f;
  if (p.transmission > 0.0f && specular_reflects(p))
    c.interfaceEnergy = mix(1.0f, max(p.thinWalled ? ggx_energy(mu_o, a) : dielectric_interface_energy(mu_o, a, p.eta), 0.05f),
                            ggx_isotropy(p.alpha));

  // Estimated albedo of each lobe from wo; floors keep a lobe sampled wherever it can be non-zero.
  const float under = (1.0f - c.fuzzEnergy) * (1.0f - c.coatEnergy) * luminance(c.coatTint * c.coatTint * c.darkening);
  const float dielectric = (1.0f - p.metalness) * under;
  c.weights = vec4(0.0f);
  c.weights.x = (1.0f - c.fuzzEnergy) * c.coatEnergy;
  if (p.metalness > 0.0f && p.specularWeight > 0.0f)
    c.weights.y = p.metalness * under *
                  max(luminance(fresnel_f82_tint(p.baseColor, p.specularColor, mu_o)) * min(p.specularWeight, 1.0f), 0.05f);
  if (p.transmission < 1.0f) c.weights.z = dielectric * (1.0f - p.transmission) * c.specularEnergy * luminance(p.specularColor);
  if (p.transmission > 0.0f)
    c.weights.w = dielectric * p.transmission * max(luminance(p.transmissionColor + p.specularColor) * 0.5f, 0.05f);
  c.diffuseWeight = 0.0f;
  if (p.transmission < 1.0f)
    c.diffuseWeight = dielectric * (1.0f - p.transmission) * (1.0f - c.specularEnergy) *
                      luminance(diffuse_reflection_color(p) + diffuse_transmission_color(p));
  c.fuzzWeight = c.fuzzEnergy * luminance(p.fuzzColor);
  const float total = c.weights.x + c.weights.y + c.weights.z + c.weights.w + c.diffuseWeight + c.fuzzWeight;
  if (total > 0.0f) {
    c.weights /= total;
    c.diffuseWeight /= total;
    c.fuzzWeight /= total;
  }
  return c;
}

// The diffuse lobe under the specular layer, f * |cos_i|, either side.
HIPR_FN vec3 diffuse_under_specular_eval_cos(OpenPbrParams p, OpenPbrContext c, vec3 wo, vec3 wi) {
  const float mu_i = abs(wi.z);
  float scale = 1.0f;
  if (c.specularEnergy > 0.0f) {
    const float e_i = specular_layer_energy(mu_i, p.alpha, c.specularEta);
    scale = (1.0f - c.specularEnergy) * (1.0f - e_i) / max(1.0f - c.specularAverage, 1.0e-4f);
  }
  if (wi.z < 0.0f) return diffuse_transmission_color(p) * (scale * lambert_eval_cos(mu_i));
  // The base's own diffuse is EON; the subsurface stand-in stays Lambertian. (EON at roughness
  // 0 is Lambert: the branch only spares the work.)
  if (p.diffuseRoughness <= 0.0f) return diffuse_reflection_color(p) * (scale * lambert_eval_cos(mu_i));
  const vec3 subsurface = diffuse_reflection_color(p) - p.baseColor * (1.0f - p.subsurface);
  return (eon_eval_cos(p.baseColor * (1.0f - p.subsurface), p.diffuseRoughness, wo, wi) +
          subsurface * lambert_eval_cos(mu_i)) * scale;
}

// Fresnel of a dielectric specular reflection at relative index eta, with the thin film's colours;
// `ambient` is the index of the medium above the film (the film's index is taken relative to it,
// as eta already is).
HIPR_FN vec3 specular_fresnel(OpenPbrParams p, float eta, float ambient, float cos_o) {
  if (p.thinFilm > 0.0f)
    return fresnel_with_thin_film(cos_o, eta, p.thinFilm, p.thinFilmIor / ambient, p.thinFilmThickness);
  return vec3(fresnel_dielectric(cos_o, eta));
}

// The base (metal and dielectric) below the coat, f * |cos_i|.
HIPR_FN vec3 openpbr_base_eval_cos(OpenPbrParams p, OpenPbrContext c, vec3 wo, vec3 wi) {
  vec3 result = vec3(0.0f);
  const bool reflection = wi.z > 0.0f;
  if (reflection && p.metalness > 0.0f && p.specularWeight > 0.0f)
    result += (p.metalness * min(p.specularWeight, 1.0f)) *
              metal_eval_cos(p.baseColor, p.specularColor, vec4(p.thinFilm, p.thinFilmIor, p.thinFilmThickness, c.filmAmbient), p.alpha,
                             wo, wi);
  if (p.metalness >= 1.0f) return result;

  vec3 dielectric = vec3(0.0f);
  const float t = p.transmission;
  if (reflection && (opaque_specular_reflects(c) || (t > 0.0f && specular_reflects(p)))) {
    const float cos_h = dot(wo, normalize(wo + wi));
    vec3 amount = vec3(0.0f);
    if (t < 1.0f && opaque_specular_reflects(c)) amount += (1.0f - t) * specular_fresnel(p, c.specularEta, c.filmAmbient, cos_h);
    if (t > 0.0f && specular_reflects(p)) {
      const vec3 f = specular_fresnel(p, p.eta, 1.0f, cos_h);
      amount += (t / c.interfaceEnergy) * (p.thinWalled ? thin_slab_reflectance(f) : f);
    }
    dielectric += p.specularColor * amount * ggx_reflection_eval_cos(wo, wi, p.alpha);
  } else if (!reflection && t > 0.0f && specular_reflects(p)) {
    const float through = p.thinWalled ? thin_interface_eval_cos(wo, wi, p.eta, p.alpha)
                                       : dielectric_interface_eval_cos(wo, wi, p.eta, p.alpha);
    dielectric += p.transmissionColor * (t * through / c.interfaceEnergy);
  }
  if (t < 1.0f) dielectric += (1.0f - t) * diffuse_under_specular_eval_cos(p, c, wo, wi);
  return result + (1.0f - p.metalness) * dielectric;
}

// Scale of everything under the coat for the pair (wo, wi), colour included: light reflected
// by the base crosses the coat twice and is darkened, light refracted through it once.
HIPR_FN vec3 under_coat_scale(OpenPbrParams p, OpenPbrContext c, vec3 wi) {
  if (p.coat <= 0.0f) return vec3(1.0f);
  const vec3 through = c.coatTint * (1.0f - c.coatEnergy);
  return wi.z > 0.0f ? through * coat_passage_tint(p.coatColor, p.coat, p.coatEta, wi.z) * c.darkening : through;
}

// eval, pdf and sample come in two forms: given the context of wo (openpbr_context), so a
// shading point computes it once for all of them, and a form that makes it (tests).

// f(wo, wi) * |cos(wi)|; wi on either side.
HIPR_FN vec3 openpbr_eval_cos(OpenPbrParams p, OpenPbrContext c, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return vec3(0.0f);
  vec3 result = openpbr_base_eval_cos(p, c, wo, wi) * under_coat_scale(p, c, wi);
  if (p.coat > 0.0f && wi.z > 0.0f) {
    const float f = fresnel_dielectric(dot(wo, normalize(wo + wi)), p.coatEta);
    result += vec3(p.coat * f * ggx_reflection_eval_cos(wo, wi, vec2(p.coatAlpha)));
  }
  if (p.fuzz > 0.0f) {
    result *= 1.0f - c.fuzzEnergy;
    // The fuzz lobe, f cos = w E_f(wo) pdf(wi) (fuzz.glsl), its albedo taken from the context.
    if (wi.z > 0.0f) result += (c.fuzzEnergy * fuzz_pdf(p.fuzzRoughness, wo, wi)) * p.fuzzColor;
  }
  return result;
}

HIPR_FN vec3 openpbr_eval_cos(OpenPbrParams p, vec3 wo, vec3 wi) {
  return wo.z > 0.0f ? openpbr_eval_cos(p, openpbr_context(p, wo), wo, wi) : vec3(0.0f);
}

// Solid-angle pdf of openpbr_sample producing wi (delta events excluded).
HIPR_FN float openpbr_pdf(OpenPbrParams p, OpenPbrContext c, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return 0.0f;
  float pdf = 0.0f;
  if (wi.z > 0.0f) {
    if (c.weights.x > 0.0f) pdf += c.weights.x * ggx_reflection_pdf(wo, wi, vec2(p.coatAlpha));
    if (c.weights.y > 0.0f) pdf += c.weights.y * metal_pdf(p.alpha, wo, wi);
    if (c.weights.z > 0.0f) pdf += c.weights.z * ggx_reflection_pdf(wo, wi, p.alpha);
  }
  if (c.weights.w > 0.0f)
    pdf += c.weights.w * (p.thinWalled ? thin_interface_pdf(wo, wi, p.eta, p.alpha)
                                       : dielectric_interface_pdf(wo, wi, p.eta, p.alpha));
  if (c.diffuseWeight > 0.0f) {
    const float q = diffuse_transmission_probability(p);
    const float reflected = p.diffuseRoughness > 0.0f ? eon_pdf(p.diffuseRoughness, wo, wi) : lambert_pdf(wi.z);
    pdf += c.diffuseWeight * (wi.z > 0.0f ? (1.0f - q) * reflected : q * lambert_pdf(-wi.z));
  }
  if (c.fuzzWeight > 0.0f) pdf += c.fuzzWeight * fuzz_pdf(p.fuzzRoughness, wo, wi);
  return pdf;
}

HIPR_FN float openpbr_pdf(OpenPbrParams p, vec3 wo, vec3 wi) {
  return wo.z > 0.0f ? openpbr_pdf(p, openpbr_context(p, wo), wo, wi) : 0.0f;
}

// A sampled direction. A delta event (light passing an index-matched interface unbent) has no
// density: `deltaWeight` is its f |cos| / probability, and eval/pdf never see it.
struct OpenPbrSample {
  vec3 wi;
  uint lobe;
  bool valid;
  bool delta;
  vec3 deltaWeight;
};

HIPR_FN uint reflection_lobe_class(float alpha) { return alpha < kSpecularAlpha ? kLobeSpecular : kLobeGlossy; }

// u picks the direction within a lobe; u_lobe picks the lobe, and what is left of it after the
// pick makes the lobe's own discrete choices (reflect or refract, which side, which term).
HIPR_FN OpenPbrSample openpbr_sample(OpenPbrParams p, OpenPbrContext c, vec3 wo, vec2 u, float u_lobe) {
  OpenPbrSample s;
  s.wi = vec3(0.0f, 0.0f, 1.0f);
  s.lobe = kLobeDiffuse;
  s.valid = false;
  s.delta = false;
  s.deltaWeight = vec3(0.0f);
  if (wo.z <= 0.0f) return s;
  const vec4 w = c.weights;
  float x = u_lobe;
  if (x < w.x) {
    const vec3 m = ggx_sample_visible_normal(wo, vec2(p.coatAlpha), u);
    s.wi = 2.0f * dot(wo, m) * m - wo;
    s.lobe = reflection_lobe_class(p.coatAlpha);
    s.valid = s.wi.z > 0.0f;
    return s;
  }
  x -= w.x;
  if (x < w.y) {
    s.valid = metal_sample(p.alpha, wo, u, x / w.y, s.wi);
    s.lobe = reflection_lobe_class(ggx_alpha_mean(p.alpha));
    return s;
  }
  x -= w.y;
  if (x < w.z) {
    const vec3 m = ggx_sample_visible_normal(wo, p.alpha, u);
    s.wi = 2.0f * dot(wo, m) * m - wo;
    s.lobe = reflection_lobe_class(ggx_alpha_mean(p.alpha));
    s.valid = s.wi.z > 0.0f;
    return s;
  }
  x -= w.z;
  if (x < w.w) {
    const float choice = x / w.w;
    const int result = p.thinWalled ? thin_interface_sample(wo, p.eta, p.alpha, u, choice, s.wi)
                                    : dielectric_interface_sample(wo, p.eta, p.alpha, u, choice, s.wi);
    s.valid = result > 0;
    s.lobe = s.wi.z < 0.0f ? kLobeTransmission : reflection_lobe_class(ggx_alpha_mean(p.alpha));
    if (result == 2) {
      // Index-matched: every bit of the interface's share passes; nothing is reflected.
      s.delta = true;
      s.deltaWeight = under_coat_scale(p, c, s.wi) * p.transmissionColor *
                      ((1.0f - p.metalness) * p.transmission * (1.0f - c.fuzzEnergy) / w.w);
    }
    return s;
  }
  x -= w.w;
  if (x < c.diffuseWeight) {
    // The whole diffuse reflection is sampled as EON samples (their mixture includes the cosine
    // that suits the Lambertian subsurface part; at roughness 0 it is the cosine alone).
    if (x / c.diffuseWeight < diffuse_transmission_probability(p)) {
      s.wi = lambert_sample_local(u);
      s.wi.z = -s.wi.z;
    } else {
      s.wi = p.diffuseRoughness > 0.0f ? eon_sample(p.diffuseRoughness, wo, u) : lambert_sample_local(u);
    }
    s.lobe = kLobeDiffuse;
    s.valid = s.wi.z != 0.0f;
    return s;
  }
  if (c.fuzzWeight <= 0.0f) return s;
  s.wi = fuzz_sample(p.fuzzRoughness, wo, u);
  s.lobe = kLobeDiffuse;  // a broad sheen: HiPR weighs it as diffuse
  s.valid = s.wi.z > 0.0f;
  return s;
}

HIPR_FN OpenPbrSample openpbr_sample(OpenPbrParams p, vec3 wo, vec2 u, float u_lobe) {
  return openpbr_sample(p, openpbr_context(p, wo), wo, u, u_lobe);  // no sample for wo.z <= 0
}

// Emission leaves from under the coat and the fuzz: what they reflect back and the coat's tint
// are taken off. Takes the layers' parameters, not OpenPbrParams, so light sampling can call it
// cheaply.
HIPR_FN vec3 layers_emission_scale(float coat, vec3 coatColor, float coatAlpha, float coatEta, float fuzz,
                                   float fuzzRoughness, float mu_o) {
  vec3 scale = vec3(1.0f);
  if (coat > 0.0f)
    scale = coat_passage_tint(coatColor, coat, coatEta, mu_o) * (1.0f - coat_layer_energy(coat, coatAlpha, coatEta, mu_o));
  scale *= fuzz_layer_scale(fuzz, fuzzRoughness, mu_o);
  return scale;
}

#endif
