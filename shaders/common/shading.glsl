// The OpenPBR parameters at a hit, with every texture applied (material_inputs.glsl), as the
// BSDF takes them, plus what the integrator needs besides: emission, the medium behind the
// surface and the anisotropy direction. Features the kernel was compiled without become
// constants here (features.glsl), so the compiler drops their code.
// Needs surface.glsl, material_inputs.glsl and dispersion.glsl.
#ifndef HIPR_SHADING_GLSL
#define HIPR_SHADING_GLSL

struct ShadingParams {
  OpenPbrParams bsdf;
  vec3 emission;    // radiance toward wo leaving the front side (both sides if double-sided), nits
  vec3 absorption;  // Beer-Lambert coefficient (1/m) of the medium behind the surface; 0 for none
  vec3 tangent;     // direction of the larger specular roughness; 0 when isotropic
  bool doubleSided;
};

// Whether a path meeting this material takes one colour channel (common/dispersion.glsl): a
// thick transmissive dielectric with dispersion. (A thin-walled slab bends every wavelength back
// as it was: it does not disperse.)
bool material_disperses(uint material) {
  return HIPR_FEATURE_DISPERSION != 0 && HIPR_FEATURE_TRANSMISSION != 0 &&
         b_materials[material].transmission_dispersion_scale > 0.0 && b_materials[material].transmission_weight > 0.0 &&
         (b_materials[material].flags & kMaterialThinWalled) == 0u;
}

// Seen from the side the ray arrived on: a ray inside a transmissive solid sees the inverse
// index, and neither coat nor fuzz (they are on the outside). `channel`: the colour channel the
// path carries (kNoChannel for all three), whose wavelength a dispersive material refracts.
ShadingParams shading_params(SurfaceHit hit, vec3 wo, uint channel) {
  const uint material = hit.material;
  ShadingParams s;
  vec3 baseColor = b_materials[material].base_color;
  const uint baseTexture = hipr_texture_slot(b_materials[material].base_color_texture);
  if (baseTexture != kInvalidIndex) baseColor *= sample_material_texture(baseTexture, hit).rgb;
  float metalness = b_materials[material].base_metalness;
  float roughness = b_materials[material].specular_roughness;
  const uint mrTexture = hipr_texture_slot(b_materials[material].metallic_roughness_texture);
  if (mrTexture != kInvalidIndex) {
    const vec4 mr = sample_material_texture(mrTexture, hit);  // glTF packing: G roughness, B metalness
    roughness *= mr.g;
    metalness *= mr.b;
  }
  const uint flags = b_materials[material].flags;
  const bool thin = (flags & kMaterialThinWalled) != 0u;
  OpenPbrParams p;
  p.baseColor = baseColor * b_materials[material].base_weight;
  p.metalness = HIPR_FEATURE_METAL != 0 ? clamp(metalness, 0.0, 1.0) : 0.0;
  p.diffuseRoughness =
      HIPR_FEATURE_DIFFUSE_ROUGHNESS != 0 ? clamp(b_materials[material].base_diffuse_roughness, 0.0, 1.0) : 0.0;
  p.specularColor = material_specular_color(hit);
  p.specularWeight = material_specular_weight(hit);
  float anisotropy = 0.0;
  s.tangent = vec3(0.0);
  if (HIPR_FEATURE_ANISOTROPY != 0 && b_materials[material].specular_anisotropy > 0.0) {
    const MaterialAnisotropy a = material_anisotropy(hit);
    anisotropy = a.strength;
    s.tangent = a.direction;
  }
  p.alpha = ggx_alpha_anisotropic(clamp(roughness, 0.0, 1.0), anisotropy);
  float baseIor = max(b_materials[material].specular_ior, 1.0);
  if (channel != kNoChannel && material_disperses(material))
    baseIor = dispersed_ior(baseIor,
                            b_materials[material].transmission_dispersion_scale /
                                b_materials[material].transmission_dispersion_abbe_number,
                            dispersion_wavelength(channel));
  const float ior = ior_with_specular_weight(baseIor, p.specularWeight);
  p.eta = HIPR_FEATURE_SPECULAR != 0 || HIPR_FEATURE_TRANSMISSION != 0 ? ((thin || hit.frontFacing) ? ior : 1.0 / ior) : 1.0;
  p.transmission = HIPR_FEATURE_TRANSMISSION != 0 ? clamp(material_transmission_weight(hit), 0.0, 1.0) : 0.0;
  const vec3 transmissionColor = b_materials[material].transmission_color;
  const float depth = b_materials[material].transmission_depth;
  const bool volume = HIPR_FEATURE_VOLUME != 0 && !thin && depth > 0.0 && p.transmission > 0.0;
  p.transmissionColor = volume ? vec3(1.0) : transmissionColor;
  s.absorption = volume ? -log(clamp(transmissionColor, vec3(1.0e-6), vec3(1.0))) / depth : vec3(0.0);
  p.thinWalled = thin;
  p.subsurface = HIPR_FEATURE_SUBSURFACE != 0 ? clamp(b_materials[material].subsurface_weight, 0.0, 1.0) : 0.0;
  p.subsurfaceColor = b_materials[material].subsurface_color;
  const bool inside = !thin && !hit.frontFacing && p.transmission > 0.0;
  p.coat = HIPR_FEATURE_COAT != 0 && !inside ? clamp(material_coat_weight(hit), 0.0, 1.0) : 0.0;
  p.coatColor = b_materials[material].coat_color;
  const float coatRoughness = clamp(material_coat_roughness(hit), 0.0, 1.0);
  p.coatAlpha = p.coat > 0.0 ? ggx_alpha(coatRoughness) : 1.0;
  if (p.coat > 0.0) p.alpha = ggx_alpha_anisotropic(coat_roughened(clamp(roughness, 0.0, 1.0), coatRoughness, p.coat), anisotropy);
  p.coatEta = max(b_materials[material].coat_ior, 1.0);
  p.coatDarkening = clamp(b_materials[material].coat_darkening, 0.0, 1.0);
  p.fuzz = HIPR_FEATURE_FUZZ != 0 && !inside ? clamp(b_materials[material].fuzz_weight, 0.0, 1.0) : 0.0;
  p.fuzzColor = p.fuzz > 0.0 ? material_fuzz_color(hit) : vec3(0.0);
  p.fuzzRoughness = p.fuzz > 0.0 ? clamp(material_fuzz_roughness(hit), 0.0, 1.0) : 1.0;
  p.thinFilm = HIPR_FEATURE_THIN_FILM != 0 ? clamp(material_thin_film_weight(hit), 0.0, 1.0) : 0.0;
  p.thinFilmThickness = p.thinFilm > 0.0 ? max(material_thin_film_thickness(hit), 0.0) : 0.0;  // nanometres
  p.thinFilmIor = max(b_materials[material].thin_film_ior, 1.0);
  s.bsdf = p;
  s.doubleSided = (flags & kMaterialDoubleSided) != 0u;
  s.emission = (hit.frontFacing || s.doubleSided) ? material_emission(material, hit.uvs, dot(hit.geometricNormal, wo))
                                                  : vec3(0.0);
  return s;
}

#endif
