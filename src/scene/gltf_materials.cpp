#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "scene/gltf_hipr_extras.h"
#include "scene/gltf_material_table.h"
#include "scene/gltf_spec_gloss.h"

namespace hipr::gltf {
namespace {

glm::vec3 color(const std::vector<double>& values, glm::vec3 fallback) {
  if (values.size() < 3) return fallback;
  const glm::vec3 c{float(values[0]), float(values[1]), float(values[2])};
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(c[k])) return fallback;
  return glm::max(c, glm::vec3(0.0f));
}

const tinygltf::Value* extension(const tinygltf::Material& m, const char* name) {
  const auto it = m.extensions.find(name);
  return it == m.extensions.end() ? nullptr : &it->second;
}

// Reads a row's number or colour (glTF's default when absent or not a number), clamped.
glm::vec3 factor(const tinygltf::Value& ext, const FactorRow& row) {
  glm::vec3 v = row.fallback;
  if (ext.Has(row.key)) {
    const tinygltf::Value& value = ext.Get(row.key);
    if (row.components == 1 && value.IsNumber()) {
      v.x = float(value.GetNumberAsDouble());
    } else if (row.components == 3 && value.IsArray() && value.ArrayLen() >= 3) {
      for (int k = 0; k < 3; ++k) v[k] = float(value.Get(k).GetNumberAsDouble());
    }
    for (int k = 0; k < row.components; ++k)
      if (std::isnan(v[k])) v[k] = row.fallback[k];
  }
  return glm::clamp(v, glm::vec3(row.lo), glm::vec3(row.hi));
}

void apply_factor_rows(const tinygltf::Material& m, MaterialParameters& p) {
  auto* bytes = reinterpret_cast<unsigned char*>(&p);
  for (const FactorRow& row : factor_rows()) {
    const tinygltf::Value* ext = extension(m, row.extension);
    if (!ext) continue;
    const glm::vec3 v = factor(*ext, row);
    std::memcpy(bytes + row.field, &v, sizeof(float) * size_t(row.components));
  }
}

void apply_texture_rows(const tinygltf::Material& m, MaterialParameters& p, TextureTable& textures,
                        const std::string& what) {
  auto* bytes = reinterpret_cast<unsigned char*>(&p);
  for (const TextureRow& row : texture_rows()) {
    const tinygltf::Value* ext = extension(m, row.extension);
    if (!ext) continue;
    const uint32_t index = textures.get(texture_reference(*ext, row.key), row.srgb, what);
    std::memcpy(bytes + row.field, &index, sizeof index);
  }
}

// alphaMode: OPAQUE ignores alpha; MASK thresholds it; BLEND becomes stochastic coverage.
void apply_alpha_mode(const tinygltf::Material& m, MaterialParameters& p, const std::string& what) {
  const auto& factor = m.pbrMetallicRoughness.baseColorFactor;
  const float alpha = factor.size() >= 4 && std::isfinite(factor[3])
                          ? std::clamp(float(factor[3]), 0.0f, 1.0f)
                          : 1.0f;
  p.alpha_cutoff = -1.0f;
  if (m.alphaMode == "MASK") {
    p.geometry_opacity = alpha;
    p.alpha_cutoff = std::isfinite(m.alphaCutoff) ? std::max(float(m.alphaCutoff), 0.0f) : 0.5f;
  } else if (m.alphaMode == "BLEND") {
    p.geometry_opacity = alpha;
  } else if (m.alphaMode.empty() || m.alphaMode == "OPAQUE") {
    p.geometry_opacity = 1.0f;
    p.flags |= kMaterialIgnoreTextureAlpha;
  } else {
    throw InputError(what + " has unknown alphaMode '" + m.alphaMode +
                     "' (expected OPAQUE, MASK or BLEND)");
  }
}

// The rules of gltf_material_table.cpp that are more than a copy.
void apply_extension_rules(const tinygltf::Material& m, MaterialParameters& p) {
  const tinygltf::Value* volume = extension(m, "KHR_materials_volume");
  const bool thick = volume && volume->Has("thicknessFactor") &&
                     volume->Get("thicknessFactor").IsNumber() &&
                     volume->Get("thicknessFactor").GetNumberAsDouble() > 0.0;
  if (!thick) {
    p.flags |= kMaterialThinWalled;
    p.transmission_color = p.base_color;
    p.transmission_depth = 0.0f;
  } else if (!std::isfinite(p.transmission_depth)) {
    p.transmission_color = glm::vec3(1.0f);  // no absorption
    p.transmission_depth = 0.0f;
  }
  if (extension(m, "KHR_materials_clearcoat")) {
    p.coat_ior = 1.5f;
    p.coat_color = glm::vec3(1.0f);
    p.coat_darkening = 0.0f;
    const tinygltf::Value& coat = *extension(m, "KHR_materials_clearcoat");
    if (coat.Has("clearcoatNormalTexture") && coat.Get("clearcoatNormalTexture").Has("scale")) {
      const double scale = coat.Get("clearcoatNormalTexture").Get("scale").GetNumberAsDouble();
      if (std::isfinite(scale)) p.coat_normal_scale = float(scale);
    }
  }
  // A sheen colour texture reference either names a texture or fails the load (TextureTable::get),
  // so its index alone says whether the material has one.
  if (const tinygltf::Value* sheen = extension(m, "KHR_materials_sheen")) {
    const bool textured = texture_reference(*sheen, "sheenColorTexture").index >= 0;
    p.fuzz_weight = (glm::length(p.fuzz_color) > 0.0f || textured) ? 1.0f : 0.0f;
  }
}

// KHR_materials_unlit: the surface shows its base colour whatever the light. A path tracer's
// nearest honest reading is a surface that emits its base colour (factor x texture, one nit per
// unit, as a display shows it at exposure 0) and reflects nothing: seen directly it is exactly
// its colour, and like any emitter it also lights what faces it (dimly: <= 1 nit). The factors
// here (the writer maps files with them), the textures in apply_unlit_textures.
void apply_unlit_factors(MaterialParameters& p) {
  p.emission_color = p.base_color;
  p.emission_luminance = 1.0f;
  p.base_weight = 0.0f;
  p.base_metalness = 0.0f;
  p.specular_weight = 0.0f;
  p.transmission_weight = 0.0f;
  p.subsurface_weight = 0.0f;
  p.coat_weight = 0.0f;
  p.fuzz_weight = 0.0f;
  p.thin_film_weight = 0.0f;
}

void apply_unlit_textures(MaterialParameters& p) {
  p.emission_texture = p.base_color_texture;
  p.metallic_roughness_texture = kNoTexture;
  p.normal_texture = kNoTexture;
}

}  // namespace

MaterialParameters map_material_factors(const tinygltf::Material& m, const std::string& what) {
  MaterialParameters p = default_material_params();
  const auto& pbr = m.pbrMetallicRoughness;
  p.base_color = color(pbr.baseColorFactor, glm::vec3(1.0f));
  p.base_weight = 1.0f;
  p.base_metalness = std::clamp(float(pbr.metallicFactor), 0.0f, 1.0f);
  p.specular_roughness = std::clamp(float(pbr.roughnessFactor), 0.0f, 1.0f);
  p.normal_scale = float(m.normalTexture.scale);
  // Emission in nits: emissiveFactor (colour) x KHR_materials_emissive_strength (luminance).
  p.emission_color = color(m.emissiveFactor, glm::vec3(0.0f));
  p.emission_luminance = 1.0f;
  apply_alpha_mode(m, p, what);
  apply_factor_rows(m, p);
  apply_extension_rules(m, p);
  apply_spec_gloss_factors(m, p);
  if (extension(m, "KHR_materials_unlit")) apply_unlit_factors(p);
  if (m.doubleSided) p.flags |= kMaterialDoubleSided;
  return p;
}

MaterialParameters default_gltf_material_params() {
  // glTF's default material: white-ish, fully rough dielectric.
  MaterialParameters p = default_material_params();
  p.base_color = glm::vec3(1.0f);
  p.specular_roughness = 1.0f;
  return p;
}

Material convert_material(const tinygltf::Material& m, size_t index, TextureTable& textures,
                          const std::string& file) {
  Material out;
  out.name = m.name.empty() ? "material " + std::to_string(index) : m.name;
  const std::string what = file + ": material " + std::to_string(index) + " ('" + out.name + "')";
  MaterialParameters& p = out.params;
  p = map_material_factors(m, what);
  const auto& pbr = m.pbrMetallicRoughness;
  p.base_color_texture = textures.get(texture_reference(pbr.baseColorTexture), true, what);
  p.metallic_roughness_texture =
      textures.get(texture_reference(pbr.metallicRoughnessTexture), false, what);
  p.normal_texture = textures.get(texture_reference(m.normalTexture), false, what);
  p.emission_texture = textures.get(texture_reference(m.emissiveTexture), true, what);
  apply_texture_rows(m, p, textures, what);
  apply_spec_gloss_textures(m, p, textures, textures.scene(), what);
  if (extension(m, "KHR_materials_unlit")) apply_unlit_textures(p);
  // What glTF cannot say, saved by save_scene (gltf_hipr_extras.h), overrides the mapping.
  apply_openpbr_extras(m.extras, kOpenPbrExtras, p, what);
  return out;
}

}  // namespace hipr::gltf
