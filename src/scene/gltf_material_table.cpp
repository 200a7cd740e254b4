// The one place that says which glTF material field becomes which OpenPBR parameter.
// clang-format off
//
// glTF field                                  -> OpenPBR (MaterialParameters)
// --- core (gltf_materials.cpp) ---
// baseColorFactor.rgb (x baseColorTexture)    -> base_color (base_weight = 1)
// metallicFactor / roughnessFactor (x MR tex) -> base_metalness / specular_roughness
// normalTexture (+ scale)                     -> normal_texture, normal_scale
// emissiveFactor (x emissiveTexture)          -> emission_color (emission_luminance = 1)
// alphaMode OPAQUE                            -> geometry_opacity 1, alpha_cutoff -1, texture
//                                                alpha ignored
// alphaMode MASK                              -> geometry_opacity = baseColorFactor.a,
//                                                alpha_cutoff = alphaCutoff
// alphaMode BLEND                             -> geometry_opacity = baseColorFactor.a,
//                                                alpha_cutoff -1 (stochastic)
//   (opacity = geometry_opacity x baseColorTexture.a in both cases; see shaders/common/cutout.glsl)
// doubleSided                                 -> flags kMaterialDoubleSided
// occlusionTexture                            -> ignored (a path tracer computes occlusion)
// --- extensions (rows below) ---
// KHR_materials_emissive_strength  emissiveStrength -> emission_luminance
// KHR_materials_ior                ior -> specular_ior
// KHR_materials_specular           specularFactor / specularColorFactor -> specular_weight /
//                                  specular_color
// KHR_materials_transmission       transmissionFactor -> transmission_weight
// KHR_materials_volume             attenuationColor / attenuationDistance -> transmission_color /
//                                  transmission_depth (infinite distance: colour 1, depth 0 = no
//                                  absorption); thicknessFactor > 0 clears kMaterialThinWalled;
//                                  thicknessTexture ignored (a path tracer measures thickness by
//                                  tracing)
// no KHR_materials_volume, or thicknessFactor 0 -> kMaterialThinWalled (glTF: such transmission
//                                  is thin); a thin transmissive material's transmission_color =
//                                  baseColorFactor.rgb (glTF tints transmitted light by the base
//                                  colour)
// KHR_materials_clearcoat          clearcoatFactor / clearcoatRoughnessFactor -> coat_weight /
//                                  coat_roughness; coat_ior 1.5, coat_color 1, coat_darkening 0
//                                  (glTF's coat does not darken); clearcoatNormalTexture.scale ->
//                                  coat_normal_scale
// KHR_materials_sheen              sheenColorFactor -> fuzz_color, fuzz_weight = 1 when the colour
//                                  or its texture is non-zero; sheenRoughnessFactor ->
//                                  fuzz_roughness
// KHR_materials_iridescence        iridescenceFactor -> thin_film_weight, iridescenceIor ->
//                                  thin_film_ior, iridescenceThicknessMaximum / Minimum ->
//                                  thin_film_thickness / thin_film_thickness_min (nanometres, as
//                                  glTF; OpenPBR uses um)
// KHR_materials_anisotropy         anisotropyStrength -> specular_anisotropy,
//                                  anisotropyRotation -> specular_rotation (radians, glTF's unit)
// KHR_materials_diffuse_transmission diffuseTransmissionFactor / ColorFactor -> subsurface_weight /
//                                  subsurface_color: with thin walls, OpenPBR's subsurface is
//                                  exactly a diffuse transmission (its textures are not read)
// KHR_materials_dispersion         dispersion -> transmission_dispersion_scale, with
//                                  transmission_dispersion_abbe_number 20: glTF's Abbe number is
//                                  20 / dispersion, OpenPBR's abbe_number / scale. Three
//                                  wavelengths, one per colour channel (common/dispersion.glsl)
// KHR_materials_variants           material sets (gltf_variants.cpp)
// KHR_materials_unlit              gltf_materials.cpp; KHR_materials_pbrSpecularGlossiness:
//                                  gltf_spec_gloss.cpp
// KHR_texture_transform            every textureInfo: see gltf_textures.cpp
// clang-format on
#include "scene/gltf_material_table.h"

#include <limits>

#include "hipr/material.h"

namespace hipr::gltf {

const std::vector<FactorRow>& factor_rows() {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  using M = MaterialParameters;
  const glm::vec3 one(1.0f), zero(0.0f);
  static const std::vector<FactorRow> rows = {
      {"KHR_materials_emissive_strength", "emissiveStrength", offsetof(M, emission_luminance), 1,
       one, 0, kInf},
      {"KHR_materials_ior", "ior", offsetof(M, specular_ior), 1, glm::vec3(1.5f), 1, kInf},
      {"KHR_materials_specular", "specularFactor", offsetof(M, specular_weight), 1, one, 0, kInf},
      {"KHR_materials_specular", "specularColorFactor", offsetof(M, specular_color), 3, one, 0,
       kInf},
      {"KHR_materials_transmission", "transmissionFactor", offsetof(M, transmission_weight), 1,
       zero, 0, 1},
      {"KHR_materials_volume", "attenuationColor", offsetof(M, transmission_color), 3, one, 0, 1},
      {"KHR_materials_volume", "attenuationDistance", offsetof(M, transmission_depth), 1,
       glm::vec3(kInf), 0, kInf},
      {"KHR_materials_clearcoat", "clearcoatFactor", offsetof(M, coat_weight), 1, zero, 0, 1},
      {"KHR_materials_clearcoat", "clearcoatRoughnessFactor", offsetof(M, coat_roughness), 1, zero,
       0, 1},
      {"KHR_materials_sheen", "sheenColorFactor", offsetof(M, fuzz_color), 3, zero, 0, 1},
      {"KHR_materials_sheen", "sheenRoughnessFactor", offsetof(M, fuzz_roughness), 1, zero, 0, 1},
      {"KHR_materials_iridescence", "iridescenceFactor", offsetof(M, thin_film_weight), 1, zero, 0,
       1},
      {"KHR_materials_iridescence", "iridescenceIor", offsetof(M, thin_film_ior), 1,
       glm::vec3(1.3f), 1, kInf},
      {"KHR_materials_iridescence", "iridescenceThicknessMinimum",
       offsetof(M, thin_film_thickness_min), 1, glm::vec3(100.0f), 0, kInf},
      {"KHR_materials_iridescence", "iridescenceThicknessMaximum", offsetof(M, thin_film_thickness),
       1, glm::vec3(400.0f), 0, kInf},
      {"KHR_materials_anisotropy", "anisotropyStrength", offsetof(M, specular_anisotropy), 1, zero,
       0, 1},
      {"KHR_materials_anisotropy", "anisotropyRotation", offsetof(M, specular_rotation), 1, zero,
       -kInf, kInf},
      {"KHR_materials_diffuse_transmission", "diffuseTransmissionFactor",
       offsetof(M, subsurface_weight), 1, zero, 0, 1},
      {"KHR_materials_diffuse_transmission", "diffuseTransmissionColorFactor",
       offsetof(M, subsurface_color), 3, one, 0, 1},
      {"KHR_materials_dispersion", "dispersion", offsetof(M, transmission_dispersion_scale), 1,
       zero, 0, kInf},
  };
  return rows;
}

const std::vector<TextureRow>& texture_rows() {
  using M = MaterialParameters;
  static const std::vector<TextureRow> rows = {
      {"KHR_materials_transmission", "transmissionTexture", offsetof(M, transmission_texture),
       false},
      {"KHR_materials_clearcoat", "clearcoatTexture", offsetof(M, clearcoat_texture), false},
      {"KHR_materials_clearcoat", "clearcoatRoughnessTexture",
       offsetof(M, clearcoat_roughness_texture), false},
      {"KHR_materials_clearcoat", "clearcoatNormalTexture", offsetof(M, clearcoat_normal_texture),
       false},
      {"KHR_materials_sheen", "sheenColorTexture", offsetof(M, sheen_color_texture), true},
      {"KHR_materials_sheen", "sheenRoughnessTexture", offsetof(M, sheen_roughness_texture), false},
      {"KHR_materials_specular", "specularTexture", offsetof(M, specular_texture), false},
      {"KHR_materials_specular", "specularColorTexture", offsetof(M, specular_color_texture), true},
      {"KHR_materials_iridescence", "iridescenceTexture", offsetof(M, iridescence_texture), false},
      {"KHR_materials_iridescence", "iridescenceThicknessTexture",
       offsetof(M, iridescence_thickness_texture), false},
      {"KHR_materials_anisotropy", "anisotropyTexture", offsetof(M, anisotropy_texture), false},
  };
  return rows;
}

}  // namespace hipr::gltf
