#pragma once
// A material's OpenPBR 1.1 surface parameters (names follow the specification), as scenes,
// edits and saved files hold them. The kernels read a packed copy (the GPU layout is private).
// Units follow glTF where OpenPBR's differ: thin_film_thickness(_min) in nanometres,
// specular_rotation in radians (counter-clockwise from the tangent), transmission_depth in
// metres. How glTF fills each field: src/scene/gltf_material_table.cpp.
#include <cstdint>

#include <glm/glm.hpp>

namespace hipr {

// A texture slot that samples nothing.
inline constexpr uint32_t kNoTexture = 0xffffffffu;

// MaterialParameters::flags
inline constexpr uint32_t kMaterialDoubleSided = 1u;
inline constexpr uint32_t kMaterialThinWalled = 2u;
inline constexpr uint32_t kMaterialIgnoreTextureAlpha =
    4u;  // glTF OPAQUE: base colour alpha is not opacity

// Texture::flags
inline constexpr uint32_t kTextureSrgb = 1u;  // texels are sRGB-encoded colour (decoded to linear)
inline constexpr uint32_t kTextureNearest = 2u;  // nearest-texel lookup instead of bilinear
inline constexpr uint32_t kTextureClampU = 4u;
inline constexpr uint32_t kTextureClampV = 8u;
inline constexpr uint32_t kTextureMirrorU = 16u;
inline constexpr uint32_t kTextureMirrorV = 32u;
inline constexpr uint32_t kTextureUv1 = 64u;  // reads TEXCOORD_1 instead of TEXCOORD_0

struct MaterialParameters {
  glm::vec3 base_color;
  float base_weight;
  float base_metalness;
  float base_diffuse_roughness;
  float specular_weight;
  float specular_roughness;
  glm::vec3 specular_color;
  float specular_ior;
  float specular_anisotropy;
  float specular_rotation;
  float transmission_weight;
  float transmission_depth;
  glm::vec3 transmission_color;
  // Dispersion of the transmitting dielectric: its Abbe number is
  // transmission_dispersion_abbe_number / transmission_dispersion_scale (0: none).
  float transmission_dispersion_scale;
  float transmission_dispersion_abbe_number;
  float subsurface_weight;
  glm::vec3 subsurface_color;
  float subsurface_radius;
  float coat_weight;
  float coat_roughness;
  float coat_ior;
  float coat_darkening;
  glm::vec3 coat_color;
  float fuzz_weight;
  glm::vec3 fuzz_color;
  float fuzz_roughness;
  float thin_film_weight;
  float thin_film_thickness;  // at iridescence_thickness_texture G = 1 (or without texture)
  float thin_film_ior;
  float thin_film_thickness_min;  // at iridescence_thickness_texture G = 0
  float emission_luminance;
  glm::vec3 emission_color;
  float geometry_opacity;
  float alpha_cutoff;  // >= 0: opaque where opacity >= cutoff, else absent (MASK); < 0: stochastic
                       // coverage
  uint32_t flags;      // kMaterial* above
  float normal_scale;
  float coat_normal_scale;
  // Texture indices into the TextureInfo table, or kNoTexture. Channels as glTF packs them.
  uint32_t base_color_texture;             // RGB: base_color, A: opacity
  uint32_t metallic_roughness_texture;     // glTF packing: G roughness, B metalness
  uint32_t normal_texture;                 // tangent-space normal map
  uint32_t emission_texture;               // RGB: emission_color multiplier
  uint32_t transmission_texture;           // R: transmission_weight
  uint32_t clearcoat_texture;              // R: coat_weight
  uint32_t clearcoat_roughness_texture;    // G: coat_roughness
  uint32_t clearcoat_normal_texture;       // tangent-space normal of the coat (coat_normal_scale)
  uint32_t sheen_color_texture;            // RGB: fuzz_color
  uint32_t sheen_roughness_texture;        // A: fuzz_roughness
  uint32_t specular_texture;               // A: specular_weight
  uint32_t specular_color_texture;         // RGB: specular_color
  uint32_t iridescence_texture;            // R: thin_film_weight
  uint32_t iridescence_thickness_texture;  // G: thin_film_thickness = mix(min, max, G)
  uint32_t anisotropy_texture;             // RG: direction in tangent space (x2-1), B: strength
};

}  // namespace hipr
