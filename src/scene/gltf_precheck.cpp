#include "scene/gltf_precheck.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "core/log.h"
#include "hipr/scene_loader.h"
#include "scene/gltf_sandbox.h"

namespace hipr {

const std::vector<GltfExtension>& gltf_extension_table() {
  static const std::vector<GltfExtension> table = {
      {"KHR_materials_emissive_strength", "emission_luminance (nits) times emissiveFactor"},
      {"KHR_materials_specular", "specular_weight, specular_color (factors and textures)"},
      {"KHR_materials_ior", "specular_ior"},
      {"KHR_materials_transmission", "transmission_weight (factor and texture)"},
      {"KHR_materials_volume",
       "thick (absorbing: transmission_color, transmission_depth) or thin-walled"},
      {"KHR_materials_clearcoat", "coat_weight, coat_roughness, the coat's normal map"},
      {"KHR_materials_sheen", "fuzz_color, fuzz_roughness"},
      {"KHR_materials_iridescence", "thin_film_weight, thin_film_thickness, thin_film_ior"},
      {"KHR_materials_anisotropy", "specular_anisotropy, specular_rotation (and texture)"},
      {"KHR_materials_diffuse_transmission", "subsurface_weight, subsurface_color (thin)"},
      {"KHR_materials_dispersion",
       "transmission_dispersion_scale (Abbe number 20 / dispersion); R, G, B refract apart"},
      {"KHR_materials_unlit",
       "a surface emitting its base colour (1 nit per unit) that reflects nothing"},
      {"KHR_materials_pbrSpecularGlossiness",
       "metalness, base colour and roughness solved from diffuse, specular and glossiness "
       "(per texel into baked textures)"},
      {"KHR_materials_variants",
       "named material sets: --variant, a variant edit, the viewer's Scene panel"},
      {"KHR_texture_transform", "offset, rotation, scale and texCoord of every texture"},
      {"KHR_lights_punctual", "point, spot and directional lights"},
      {"KHR_node_visibility", "hidden nodes (and their subtrees) are not rendered"},
      {"EXT_mesh_gpu_instancing",
       "each instance a child node sharing the mesh (one BLAS, a TLAS entry each), editable "
       "alone or as a group"},
      {"KHR_draco_mesh_compression", "decoded with libdraco at load"},
      {"EXT_meshopt_compression", "decoded with libmeshoptimizer at load (every mode and filter)"},
      {"KHR_mesh_quantization", "integer and normalized attributes, dequantized at load"},
      {"EXT_texture_webp", "WebP images, decoded with OpenImageIO"},
      {"EXT_texture_avif", "AVIF images, decoded with OpenImageIO (libheif)"},
      {"MSFT_texture_dds", "DDS images, decoded with OpenImageIO"},
      {"KHR_texture_basisu",
       "KTX2 images cannot be decoded (no packaged decoder): the fallback image is used"},
      {"KHR_xmp_json_ld", "XMP metadata: not shown, kept as it was when saving"},
  };
  return table;
}

const std::vector<std::string>& supported_gltf_extensions() {
  static const std::vector<std::string> list = [] {
    std::vector<std::string> names;
    for (const GltfExtension& e : gltf_extension_table()) names.push_back(e.name);
    return names;
  }();
  return list;
}

namespace gltf {

void warn_unsupported_extensions(const std::vector<std::string>& used, const std::string& name) {
  const auto& supported = supported_gltf_extensions();
  for (const std::string& ext : used) {
    if (std::find(supported.begin(), supported.end(), ext) != supported.end()) continue;
    log::warn(name + ": glTF extension " + ext + " is not supported; ignored");
  }
}

std::string json_text(const std::vector<unsigned char>& bytes, bool glb) {
  if (!glb) return std::string(bytes.begin(), bytes.end());
  uint32_t length;
  std::memcpy(&length, bytes.data() + 12, 4);
  return std::string(bytes.begin() + 20, bytes.begin() + 20 + std::ptrdiff_t(length));
}

void precheck_json(const std::string& text, const std::string& name) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    std::string why = e.what();
    if (const size_t at = why.find("] "); at != std::string::npos) why = why.substr(at + 2);
    throw InputError(name + ": invalid JSON: " + why);
  }
  if (!doc.is_object()) throw InputError(name + ": invalid glTF: top level is not a JSON object");
  if (!doc.contains("asset") || !doc["asset"].is_object() || !doc["asset"].contains("version") ||
      !doc["asset"]["version"].is_string())
    throw InputError(name + ": invalid glTF: required 'asset.version' is missing");
  const std::string version = doc["asset"]["version"];
  if (version.rfind("2.", 0) != 0)
    throw InputError(name + ": unsupported glTF version " + version + " (only 2.x is supported)");
  if (doc.contains("extensionsRequired") && doc["extensionsRequired"].is_array()) {
    for (const auto& ext : doc["extensionsRequired"]) {
      if (!ext.is_string())
        throw InputError(name + ": invalid glTF: extensionsRequired holds a non-string");
      const auto& supported = supported_gltf_extensions();
      if (std::find(supported.begin(), supported.end(), ext.get<std::string>()) == supported.end())
        throw InputError(name + ": requires unsupported glTF extension " + ext.get<std::string>());
    }
  }
  for (const char* kind : {"buffers", "images"}) {
    if (!doc.contains(kind) || !doc[kind].is_array()) continue;
    for (size_t i = 0; i < doc[kind].size(); ++i) {
      const auto& item = doc[kind][i];
      if (item.is_object() && item.contains("uri") && item["uri"].is_string())
        check_uri(item["uri"], name + ": " + std::string(kind).substr(0, std::strlen(kind) - 1) +
                                   " " + std::to_string(i));
    }
  }
}

}  // namespace gltf
}  // namespace hipr
