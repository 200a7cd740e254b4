#include "render/material_packing.h"
#include "shaders/shared/abi.h"

namespace hipr {

// The public flags and texture sentinel are the kernels' own values.
static_assert(kNoTexture == abi::kInvalidIndex);
static_assert(kMaterialDoubleSided == abi::kMaterialDoubleSided &&
              kMaterialThinWalled == abi::kMaterialThinWalled &&
              kMaterialIgnoreTextureAlpha == abi::kMaterialIgnoreTextureAlpha);
static_assert(kTextureSrgb == abi::kTextureSrgb && kTextureNearest == abi::kTextureNearest &&
              kTextureClampU == abi::kTextureClampU && kTextureClampV == abi::kTextureClampV &&
              kTextureMirrorU == abi::kTextureMirrorU && kTextureMirrorV == abi::kTextureMirrorV &&
              kTextureUv1 == abi::kTextureUv1);
// Field by field below: a field added to one struct and not the other changes a size.
static_assert(sizeof(MaterialParameters) == sizeof(abi::MaterialBlock));

abi::MaterialBlock pack_material(const MaterialParameters& p) {
  abi::MaterialBlock b{};
  b.base_color = p.base_color;
  b.base_weight = p.base_weight;
  b.base_metalness = p.base_metalness;
  b.base_diffuse_roughness = p.base_diffuse_roughness;
  b.specular_weight = p.specular_weight;
  b.specular_roughness = p.specular_roughness;
  b.specular_color = p.specular_color;
  b.specular_ior = p.specular_ior;
  b.specular_anisotropy = p.specular_anisotropy;
  b.specular_rotation = p.specular_rotation;
  b.transmission_weight = p.transmission_weight;
  b.transmission_depth = p.transmission_depth;
  b.transmission_color = p.transmission_color;
  b.transmission_dispersion_scale = p.transmission_dispersion_scale;
  b.transmission_dispersion_abbe_number = p.transmission_dispersion_abbe_number;
  b.subsurface_weight = p.subsurface_weight;
  b.subsurface_color = p.subsurface_color;
  b.subsurface_radius = p.subsurface_radius;
  b.coat_weight = p.coat_weight;
  b.coat_roughness = p.coat_roughness;
  b.coat_ior = p.coat_ior;
  b.coat_darkening = p.coat_darkening;
  b.coat_color = p.coat_color;
  b.fuzz_weight = p.fuzz_weight;
  b.fuzz_color = p.fuzz_color;
  b.fuzz_roughness = p.fuzz_roughness;
  b.thin_film_weight = p.thin_film_weight;
  b.thin_film_thickness = p.thin_film_thickness;
  b.thin_film_ior = p.thin_film_ior;
  b.thin_film_thickness_min = p.thin_film_thickness_min;
  b.emission_luminance = p.emission_luminance;
  b.emission_color = p.emission_color;
  b.geometry_opacity = p.geometry_opacity;
  b.alpha_cutoff = p.alpha_cutoff;
  b.flags = p.flags;
  b.normal_scale = p.normal_scale;
  b.coat_normal_scale = p.coat_normal_scale;
  b.base_color_texture = p.base_color_texture;
  b.metallic_roughness_texture = p.metallic_roughness_texture;
  b.normal_texture = p.normal_texture;
  b.emission_texture = p.emission_texture;
  b.transmission_texture = p.transmission_texture;
  b.clearcoat_texture = p.clearcoat_texture;
  b.clearcoat_roughness_texture = p.clearcoat_roughness_texture;
  b.clearcoat_normal_texture = p.clearcoat_normal_texture;
  b.sheen_color_texture = p.sheen_color_texture;
  b.sheen_roughness_texture = p.sheen_roughness_texture;
  b.specular_texture = p.specular_texture;
  b.specular_color_texture = p.specular_color_texture;
  b.iridescence_texture = p.iridescence_texture;
  b.iridescence_thickness_texture = p.iridescence_thickness_texture;
  b.anisotropy_texture = p.anisotropy_texture;
  return b;
}

}  // namespace hipr
