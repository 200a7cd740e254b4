// How an OpenPBR parameter block goes back into glTF:
// 1. Every field the mapping (gltf_material_table.cpp) reads is set to the value that maps to
//    the parameter, clamped to glTF's valid range, unless the file already loads as it.
//    Extensions are added where needed: those that bring in a lobe (transmission, clearcoat,
//    sheen, iridescence, diffuse transmission) only when its weight is non-zero, the others
//    (ior, specular, anisotropy, emissive strength) when a value differs from glTF's default.
//    KHR_materials_volume is never added: thin or thick is a property of the geometry.
// 2. The patched materials are mapped again with the loader's own code (map_material_factors,
//    through tinygltf), and every editable parameter that still differs goes to
//    extras.hipr_openpbr. So the round trip is exact by construction, and an unedited material
//    gets no extras.
#include "scene/gltf_material_writer.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include "core/error.h"
#include "scene/gltf_hipr_extras.h"
#include "scene/gltf_material_table.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_texture_writer.h"
#include "scene/material_parameters.h"

namespace hipr::gltf {
namespace {

using M = MaterialParameters;
constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";
constexpr const char* kVolume = "KHR_materials_volume";
constexpr const char* kDispersion = "KHR_materials_dispersion";

std::vector<float> values(const M& m, size_t offset, int components) {
  std::vector<float> v(static_cast<size_t>(components));
  std::memcpy(v.data(), reinterpret_cast<const char*>(&m) + offset, v.size() * sizeof(float));
  return v;
}

std::vector<float> clamped(std::vector<float> v, float lo, float hi) {
  for (float& x : v) x = std::clamp(x, lo, hi);
  return v;
}

std::vector<float> fallback(const FactorRow& row) {
  return std::vector<float>(&row.fallback.x, &row.fallback.x + row.components);
}

// glTF's schema is narrower than the loader's clamp here (hipr reads any specular weight).
float gltf_max(const FactorRow& row) {
  return std::strcmp(row.key, "specularFactor") == 0 ? 1.0f : row.hi;
}

// The weight whose non-zero value makes an extension worth adding, for those that bring a lobe
// (and change how other parameters map: a clearcoat sets coat_ior 1.5, a sheen fuzz_weight 1).
std::optional<size_t> gate(const std::string& extension) {
  if (extension == "KHR_materials_transmission") return offsetof(M, transmission_weight);
  if (extension == "KHR_materials_clearcoat") return offsetof(M, coat_weight);
  if (extension == "KHR_materials_sheen") return offsetof(M, fuzz_weight);
  if (extension == "KHR_materials_iridescence") return offsetof(M, thin_film_weight);
  if (extension == "KHR_materials_diffuse_transmission") return offsetof(M, subsurface_weight);
  return std::nullopt;
}

// Extensions of the factor table, in table order, that this writer fills row by row.
std::vector<std::string> row_extensions() {
  std::vector<std::string> out;
  for (const FactorRow& row : factor_rows())
    if (row.extension != std::string(kEmissiveStrength) && row.extension != std::string(kVolume) &&
        row.extension != std::string(kDispersion) &&
        std::find(out.begin(), out.end(), row.extension) == out.end())
      out.push_back(row.extension);
  return out;
}

bool has_extension(const Json& m, const std::string& extension) {
  return m.contains("extensions") && m["extensions"].is_object() &&
         m["extensions"].contains(extension);
}

// A volume of positive thickness: glTF's thick material (a thin one has no medium).
bool is_thick(const Json& m) {
  if (!has_extension(m, kVolume)) return false;
  const Json& volume = m["extensions"][kVolume];
  return volume.is_object() && volume.contains("thicknessFactor") &&
         volume["thicknessFactor"].is_number() && volume["thicknessFactor"].get<double>() > 0.0;
}

void write_core(Json& m, const M& t) {
  const std::string mode = m.contains("alphaMode") && m["alphaMode"].is_string()
                               ? m["alphaMode"].get<std::string>()
                               : "OPAQUE";
  edit_object(m, "pbrMetallicRoughness", [&](Json& pbr) {
    // Alpha is geometry_opacity for MASK and BLEND; OPAQUE ignores it, so it stays as it was.
    const std::vector<double> current = json_numbers(pbr, "baseColorFactor");
    const float alpha = (mode == "MASK" || mode == "BLEND") ? t.geometry_opacity
                        : current.size() == 4               ? float(current[3])
                                                            : 1.0f;
    const std::vector<float> wanted = {t.base_color.x, t.base_color.y, t.base_color.z, alpha};
    put_numbers(pbr, "baseColorFactor", wanted, clamped(wanted, 0.0f, 1.0f),
                {1.0f, 1.0f, 1.0f, 1.0f});
    put_number(pbr, "metallicFactor", t.base_metalness, std::clamp(t.base_metalness, 0.0f, 1.0f),
               1.0f);
    put_number(pbr, "roughnessFactor", t.specular_roughness,
               std::clamp(t.specular_roughness, 0.0f, 1.0f), 1.0f);
  });
}

// Emission is emissiveFactor x emissiveStrength. glTF caps the factor at 1, so a brighter
// colour is written as colour / peak with the strength x peak: the same light for any viewer.
void write_emission(Json& m, const M& t) {
  const std::vector<float> color = {t.emission_color.x, t.emission_color.y, t.emission_color.z};
  const bool has_strength = has_extension(m, kEmissiveStrength);
  const bool strength_loads = has_strength
                                  ? loads_as(m["extensions"][kEmissiveStrength], "emissiveStrength",
                                             {t.emission_luminance}, {1.0f})
                                  : t.emission_luminance == 1.0f;
  if (loads_as(m, "emissiveFactor", color, {0.0f, 0.0f, 0.0f}) && strength_loads) return;
  const float peak = std::max({color[0], color[1], color[2], 1.0f});
  const std::vector<float> factor = {color[0] / peak, color[1] / peak, color[2] / peak};
  const float strength = t.emission_luminance * peak;
  put_numbers(m, "emissiveFactor", factor, factor, {0.0f, 0.0f, 0.0f});
  if (!has_strength && strength == 1.0f) return;
  edit_object(m, "extensions", [&](Json& extensions) {
    edit_object(extensions, kEmissiveStrength,
                [&](Json& ext) { put_number(ext, "emissiveStrength", strength, strength, 1.0f); });
  });
}

// glTF's dispersion is 20 / its Abbe number, OpenPBR's Abbe number abbe_number / scale: other
// viewers see the same glass (hipr's own load gets both fields back exactly through extras). glTF
// disperses only inside a volume (the validator warns otherwise): a thin material's dispersion,
// which hipr does not render either, can only go to extras.
void write_dispersion(Json& m, const M& t) {
  if (!is_thick(m)) return;
  const float abbe = t.transmission_dispersion_abbe_number;
  const float dispersion = abbe == 20.0f ? t.transmission_dispersion_scale
                                         : t.transmission_dispersion_scale * 20.0f / abbe;
  if (!has_extension(m, kDispersion) && dispersion == 0.0f) return;
  edit_object(m, "extensions", [&](Json& extensions) {
    edit_object(extensions, kDispersion,
                [&](Json& ext) { put_number(ext, "dispersion", dispersion, dispersion, 0.0f); });
  });
}

void write_extension_rows(Json& m, const M& t) {
  for (const std::string& extension : row_extensions()) {
    std::vector<const FactorRow*> rows;
    for (const FactorRow& row : factor_rows())
      if (row.extension == extension) rows.push_back(&row);
    bool needed = has_extension(m, extension);
    if (!needed && gate(extension)) {
      needed = values(t, *gate(extension), 1)[0] != 0.0f;
    } else if (!needed) {
      for (const FactorRow* row : rows)
        needed = needed || values(t, row->field, row->components) != fallback(*row);
    }
    if (!needed) continue;
    edit_object(m, "extensions", [&](Json& extensions) {
      edit_object(extensions, extension.c_str(), [&](Json& ext) {
        for (const FactorRow* row : rows) {
          const std::vector<float> wanted = values(t, row->field, row->components);
          put_numbers(ext, row->key, wanted, clamped(wanted, row->lo, gltf_max(*row)),
                      fallback(*row));
        }
      });
    });
  }
}

// Absorption of a thick (volume) material; a thin one's transmission colour is its base colour
// in glTF, so an edit of it can only go to extras.
void write_volume(Json& m, const M& t) {
  if (!is_thick(m)) return;
  Json& volume = m["extensions"][kVolume];
  const std::vector<float> color = {t.transmission_color.x, t.transmission_color.y,
                                    t.transmission_color.z};
  constexpr float kInf = std::numeric_limits<float>::infinity();
  if (t.transmission_depth > 0.0f) {
    put_number(volume, "attenuationDistance", t.transmission_depth, t.transmission_depth, kInf);
    put_numbers(volume, "attenuationColor", color, clamped(color, 0.0f, 1.0f), {1.0f, 1.0f, 1.0f});
  } else if (!loads_as(volume, "attenuationDistance", {0.0f}, {kInf})) {
    volume.erase("attenuationDistance");  // infinite distance: no absorption (depth 0)
  }
}

// The editable parameters where `mapped` (what the glTF fields load as) is not `target`. The
// loader refuses extras outside a parameter's range, so such a value is refused here, before
// anything is written (a glTF base colour above 1 can carry one into a derived parameter).
Json openpbr_extras(const M& mapped, const M& target, const std::string& what) {
  Json extras = Json::object();
  for (const MaterialParameter& p : material_parameters()) {
    const std::vector<float> want = values(target, p.offset, p.components);
    if (values(mapped, p.offset, p.components) == want) continue;
    for (float v : want)
      if (!(v >= p.min && v <= p.max))
        throw InputError(what + ": cannot save " + p.name + " = " + std::to_string(v) +
                         ", outside [" + std::to_string(p.min) + ", " + std::to_string(p.max) +
                         "]");
    if (p.components == 1) {
      extras[p.name] = json_number(want[0]);
    } else {
      Json array = Json::array();
      for (float v : want) array.push_back(json_number(v));
      extras[p.name] = std::move(array);
    }
  }
  return extras;
}

// Fields no edit can change must come out of the rewritten material as they went in.
void check_unchanged(const M& mapped, const M& target, const std::string& what) {
  const auto fail = [&](const char* field) {
    throw InternalError(what + ": saving would change its " + field + ", which no edit sets");
  };
  if (mapped.flags != target.flags) fail("flags");
  if (mapped.alpha_cutoff != target.alpha_cutoff) fail("alpha cutoff");
  if (mapped.normal_scale != target.normal_scale) fail("normal scale");
  if (mapped.coat_normal_scale != target.coat_normal_scale) fail("coat normal scale");
  if (mapped.thin_film_thickness_min != target.thin_film_thickness_min)
    fail("thin-film minimum thickness");
}

// What the loader maps each material to, through tinygltf as for a real load.
std::vector<M> map_with_loader(const Json& materials, const std::string& name) {
  const Json doc = {{"asset", {{"version", "2.0"}}}, {"materials", materials}};
  const std::string text = doc.dump();
  tinygltf::TinyGLTF parser;
  tinygltf::Model model;
  std::string err, warn;
  if (!parser.LoadASCIIFromString(&model, &err, &warn, text.data(), unsigned(text.size()), ""))
    throw InternalError(name + ": rewritten materials do not parse: " + err);
  std::vector<M> out;
  for (size_t i = 0; i < model.materials.size(); ++i)
    out.push_back(
        map_material_factors(model.materials[i], name + ": material " + std::to_string(i)));
  return out;
}

}  // namespace

std::vector<std::string> material_extensions_written() {
  std::vector<std::string> out = row_extensions();
  out.push_back(kEmissiveStrength);
  out.push_back(kDispersion);
  return out;
}

// The texture slots of a material the file does not have, as textureInfo objects where the
// loader reads them (gltf_materials.cpp and the extension rows of gltf_material_table.cpp).
void write_texture_references(Json& m, const M& params, TextureWriter& textures) {
  const auto set = [&](Json& owner, const char* key, uint32_t texture) {
    if (texture != kNoTexture) owner[key] = textures.texture_info(texture);
  };
  Json& pbr = m["pbrMetallicRoughness"];
  pbr = Json::object();
  set(pbr, "baseColorTexture", params.base_color_texture);
  set(pbr, "metallicRoughnessTexture", params.metallic_roughness_texture);
  if (pbr.empty()) m.erase("pbrMetallicRoughness");
  set(m, "normalTexture", params.normal_texture);
  if (params.normal_texture != kNoTexture && params.normal_scale != 1.0f)
    m["normalTexture"]["scale"] = json_number(params.normal_scale);
  set(m, "emissiveTexture", params.emission_texture);
  for (const TextureRow& row : texture_rows()) {
    uint32_t texture = 0;
    std::memcpy(&texture, reinterpret_cast<const char*>(&params) + row.field, sizeof texture);
    if (texture != kNoTexture) set(m["extensions"][row.extension], row.key, texture);
  }
}

std::vector<Material> write_new_materials(Json& doc, const std::vector<Material>& materials,
                                          TextureWriter& textures) {
  const size_t count = array_length(doc, "materials");
  if (materials.size() <= count + 1) return materials;
  std::vector<Material> ordered(materials.begin(), materials.begin() + std::ptrdiff_t(count));
  for (size_t i = count + 1; i < materials.size(); ++i) {
    const M& params = materials[i].params;
    Json stub = Json::object();
    stub["name"] = materials[i].name;
    if (params.alpha_cutoff >= 0.0f) {
      stub["alphaMode"] = "MASK";
      stub["alphaCutoff"] = json_number(params.alpha_cutoff);
    } else if (!(params.flags & kMaterialIgnoreTextureAlpha)) {
      stub["alphaMode"] = "BLEND";
    }
    if (params.flags & kMaterialDoubleSided) stub["doubleSided"] = true;
    if (!(params.flags & kMaterialThinWalled)) stub["extensions"][kVolume]["thicknessFactor"] = 1.0;
    write_texture_references(stub, params, textures);
    append_to(doc, "materials", std::move(stub));  // after the textures added their keys
    ordered.push_back(materials[i]);
  }
  ordered.push_back(materials[count]);  // glTF's default
  return ordered;
}

void write_materials(Json& doc, const std::vector<Material>& materials, const std::string& name) {
  const size_t count = array_length(doc, "materials");
  if (materials.size() != count + 1)
    throw InputError(name + ": the scene has " + std::to_string(materials.size()) +
                     " materials but its file " + std::to_string(count) +
                     " (+1 default): the file changed since it was loaded");
  for (size_t i = 0; i < count; ++i) {
    Json& m = doc["materials"][i];
    const M& t = materials[i].params;
    erase_extra(m, kOpenPbrExtras);  // recomputed below from the rewritten fields
    write_core(m, t);
    write_emission(m, t);
    write_extension_rows(m, t);
    write_volume(m, t);
    write_dispersion(m, t);
  }
  if (count > 0) {
    const std::vector<M> mapped = map_with_loader(doc["materials"], name);
    for (size_t i = 0; i < count; ++i) {
      const std::string what =
          name + ": material " + std::to_string(i) + " ('" + materials[i].name + "')";
      check_unchanged(mapped[i], materials[i].params, what);
      Json extras = openpbr_extras(mapped[i], materials[i].params, what);
      if (!extras.empty()) set_extra(doc["materials"][i], kOpenPbrExtras, std::move(extras), what);
    }
  }
  erase_extra(doc, kDefaultMaterialExtras);
  Json extras = openpbr_extras(default_gltf_material_params(), materials.back().params,
                               name + ": the default material");
  if (!extras.empty()) set_extra(doc, kDefaultMaterialExtras, std::move(extras), name);
}

}  // namespace hipr::gltf
