#include "render/material_features.h"

namespace hipr {

const std::vector<MaterialFeature>& material_feature_table() {
  using M = abi::MaterialBlock;
  static const std::vector<MaterialFeature> table = {
      {1u << 0, "HIPR_FEATURE_SPECULAR", "specular",
       [](const M& m) { return m.specular_weight > 0.0f && m.base_metalness < 1.0f; }},
      {1u << 1, "HIPR_FEATURE_METAL", "metal", [](const M& m) { return m.base_metalness > 0.0f; }},
      {1u << 2, "HIPR_FEATURE_TRANSMISSION", "transmission", [](const M& m) { return m.transmission_weight > 0.0f; }},
      {1u << 3, "HIPR_FEATURE_SUBSURFACE", "subsurface", [](const M& m) { return m.subsurface_weight > 0.0f; }},
      {1u << 4, "HIPR_FEATURE_COAT", "coat", [](const M& m) { return m.coat_weight > 0.0f; }},
      {1u << 5, "HIPR_FEATURE_FUZZ", "fuzz", [](const M& m) { return m.fuzz_weight > 0.0f; }},
      {1u << 6, "HIPR_FEATURE_THIN_FILM", "thin film", [](const M& m) { return m.thin_film_weight > 0.0f; }},
      {1u << 7, "HIPR_FEATURE_DIFFUSE_ROUGHNESS", "diffuse roughness",
       [](const M& m) { return m.base_diffuse_roughness > 0.0f; }},
      {1u << 8, "HIPR_FEATURE_ANISOTROPY", "anisotropy", [](const M& m) { return m.specular_anisotropy > 0.0f; }},
  };
  return table;
}

uint32_t all_material_features() {
  uint32_t bits = 0;
  for (const MaterialFeature& f : material_feature_table()) bits |= f.bit;
  return bits;
}

uint32_t material_features(const Scene& scene) {
  // Only materials some primitive uses (the loader keeps a default material that may serve none).
  std::vector<bool> used(scene.materials.size(), false);
  for (const Mesh& mesh : scene.meshes)
    for (const MeshPrimitive& primitive : mesh.primitives)
      if (primitive.material < used.size()) used[primitive.material] = true;
  uint32_t bits = 0;
  for (size_t i = 0; i < scene.materials.size(); ++i)
    if (used[i])
      for (const MaterialFeature& f : material_feature_table())
        if (f.used_by(scene.materials[i].params)) bits |= f.bit;
  return bits;
}

vk::ShaderDefines material_feature_defines(uint32_t features) {
  vk::ShaderDefines defines;
  for (const MaterialFeature& f : material_feature_table()) defines.emplace_back(f.define, (features & f.bit) ? "1" : "0");
  return defines;
}

std::vector<std::string> material_feature_names(uint32_t features, bool present) {
  std::vector<std::string> names;
  for (const MaterialFeature& f : material_feature_table())
    if (((features & f.bit) != 0) == present) names.emplace_back(f.name);
  return names;
}

}  // namespace hipr
