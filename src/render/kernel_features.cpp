#include "render/kernel_features.h"

#include "core/error.h"
#include "shaders/shared/abi.h"

namespace hipr {
namespace {

using M = MaterialParameters;

bool has_texture(const M& m) {
  for (uint32_t texture :
       {m.base_color_texture, m.metallic_roughness_texture, m.normal_texture, m.emission_texture,
        m.transmission_texture, m.clearcoat_texture, m.clearcoat_roughness_texture,
        m.clearcoat_normal_texture, m.sheen_color_texture, m.sheen_roughness_texture,
        m.specular_texture, m.specular_color_texture, m.iridescence_texture,
        m.iridescence_thickness_texture, m.anisotropy_texture})
    if (texture != abi::kInvalidIndex) return true;
  return false;
}

// As the kernel decides (surface.glsl: max3(emission_color x emission_luminance) > 0), NaN
// counting as emissive: edits may write any float, and leaving emission out must never change
// what a hit returns.
bool is_emissive(const M& m) {
  for (int c = 0; c < 3; ++c)
    if (!(m.emission_color[c] * m.emission_luminance <= 0.0f)) return true;
  return false;
}

}  // namespace

const std::vector<KernelFeature>& kernel_feature_table() {
  static const std::vector<KernelFeature> table = {
      // Fully metal has no dielectric specular, unless a metallic-roughness texture lowers the
      // metalness.
      {1u << 0, "HIPR_FEATURE_SPECULAR", "specular",
       [](const M& m) {
         return m.specular_weight > 0.0f &&
                (m.base_metalness < 1.0f || m.metallic_roughness_texture != abi::kInvalidIndex);
       },
       nullptr, true},
      {1u << 1, "HIPR_FEATURE_METAL", "metal", [](const M& m) { return m.base_metalness > 0.0f; },
       nullptr, true},
      {1u << 2, "HIPR_FEATURE_TRANSMISSION", "transmission",
       [](const M& m) { return m.transmission_weight > 0.0f; }, nullptr, true},
      {1u << 3, "HIPR_FEATURE_SUBSURFACE", "subsurface",
       [](const M& m) { return m.subsurface_weight > 0.0f; }, nullptr, true},
      {1u << 4, "HIPR_FEATURE_COAT", "coat", [](const M& m) { return m.coat_weight > 0.0f; },
       nullptr, true},
      {1u << 5, "HIPR_FEATURE_FUZZ", "fuzz", [](const M& m) { return m.fuzz_weight > 0.0f; },
       nullptr, true},
      {1u << 6, "HIPR_FEATURE_THIN_FILM", "thin film",
       [](const M& m) { return m.thin_film_weight > 0.0f; }, nullptr, true},
      {1u << 7, "HIPR_FEATURE_DIFFUSE_ROUGHNESS", "diffuse roughness",
       [](const M& m) { return m.base_diffuse_roughness > 0.0f; }, nullptr, true},
      {1u << 8, "HIPR_FEATURE_ANISOTROPY", "anisotropy",
       [](const M& m) { return m.specular_anisotropy > 0.0f; }, nullptr, true},
      // As shading.glsl's material_disperses: a thin-walled slab does not disperse.
      {1u << 16, "HIPR_FEATURE_DISPERSION", "dispersion",
       [](const M& m) {
         return m.transmission_weight > 0.0f && m.transmission_dispersion_scale > 0.0f &&
                (m.flags & abi::kMaterialThinWalled) == 0;
       },
       nullptr, true},
      {1u << 9, "HIPR_FEATURE_TEXTURES", "textures", has_texture, nullptr, false},
      {1u << 10, "HIPR_FEATURE_NORMAL_MAP", "normal maps",
       [](const M& m) {
         return m.normal_texture != abi::kInvalidIndex ||
                m.clearcoat_normal_texture != abi::kInvalidIndex;
       },
       nullptr, false},
      {1u << 11, "HIPR_FEATURE_EMISSION", "emissive triangles", is_emissive, nullptr, false},
      {1u << 12, "HIPR_FEATURE_PUNCTUAL_LIGHTS", "punctual lights", nullptr,
       [](const Scene& s) { return !s.light_nodes().empty(); }, false},
      {1u << 13, "HIPR_FEATURE_ENVIRONMENT", "environment", nullptr,
       [](const Scene& s) { return s.environment.has_value(); }, false},
      {1u << 14, "HIPR_FEATURE_CUTOUT", "opacity cutout",
       [](const M& m) { return !material_is_opaque(m); }, nullptr, false},
      {1u << 15, "HIPR_FEATURE_VOLUME", "volume absorption",
       [](const M& m) {
         return m.transmission_weight > 0.0f && m.transmission_depth > 0.0f &&
                (m.flags & abi::kMaterialThinWalled) == 0;
       },
       nullptr, false},
  };
  return table;
}

uint32_t all_kernel_features() {
  uint32_t bits = 0;
  for (const KernelFeature& f : kernel_feature_table()) bits |= f.bit;
  return bits;
}

uint32_t kernel_features(const Scene& scene) {
  // Only materials some primitive uses (the loader keeps a default material that may serve none).
  std::vector<bool> used(scene.materials.size(), false);
  for (const Mesh& mesh : scene.meshes)
    for (const MeshPrimitive& primitive : mesh.primitives)
      if (primitive.material < used.size()) used[primitive.material] = true;
  uint32_t bits = 0;
  for (const KernelFeature& f : kernel_feature_table()) {
    if (f.scene_needs && f.scene_needs(scene)) bits |= f.bit;
    if (!f.material_needs) continue;
    for (size_t i = 0; i < scene.materials.size() && !(bits & f.bit); ++i)
      if (used[i] && f.material_needs(scene.materials[i].params)) bits |= f.bit;
  }
  return bits;
}

uint32_t kernel_feature_bit(const std::string& define) {
  for (const KernelFeature& f : kernel_feature_table())
    if (define == f.define) return f.bit;
  throw InternalError("no kernel feature " + define);
}

vk::ShaderDefines kernel_feature_defines(uint32_t features) {
  vk::ShaderDefines defines;
  for (const KernelFeature& f : kernel_feature_table())
    defines.emplace_back(f.define, (features & f.bit) ? "1" : "0");
  return defines;
}

}  // namespace hipr
