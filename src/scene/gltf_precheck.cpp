#include "scene/gltf_precheck.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

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
      {"EXT_texture_webp", "WebP images, decoded with libwebp"},
      {"EXT_texture_avif", "AVIF images, decoded with libheif"},
      {"MSFT_texture_dds", "DDS images (BC1-BC5, uncompressed; the top level), decoded by hipr"},
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

namespace {

// A count or index as glTF writes it: a non-negative integer (a float of integral value, as some
// writers print them, too), at most 2^53; nothing for anything else.
std::optional<uint64_t> whole_number(const nlohmann::json& value) {
  if (value.is_number_unsigned()) return value.get<uint64_t>();
  if (value.is_number_float()) {
    const double v = value.get<double>();
    if (v >= 0.0 && v <= 9007199254740992.0 && v == std::floor(v)) return uint64_t(v);
  }
  return std::nullopt;
}

// Every image held in a bufferView lies inside its buffer. tinygltf hands an image's view to the
// image decoder (stb_image, or gltf_image_decode for WebP, AVIF and DDS) as the view claims it,
// without comparing it with the buffer's bytes: a view longer than its buffer had the decoder read
// past the buffer's end (found by fuzzing). A buffer holds exactly its byteLength once tinygltf has
// read it (it refuses a shorter file, data URI or GLB chunk), so the JSON alone tells.
void check_image_views(const nlohmann::json& doc, const std::string& name) {
  if (!doc.contains("images") || !doc["images"].is_array()) return;
  const auto array = [&](const char* kind) -> const nlohmann::json* {
    return doc.contains(kind) && doc[kind].is_array() ? &doc[kind] : nullptr;
  };
  const nlohmann::json* views = array("bufferViews");
  const nlohmann::json* buffers = array("buffers");
  for (size_t i = 0; i < doc["images"].size(); ++i) {
    const nlohmann::json& image = doc["images"][i];
    if (!image.is_object() || !image.contains("bufferView")) continue;
    const std::string what = name + ": image " + std::to_string(i);
    const std::optional<uint64_t> v = whole_number(image["bufferView"]);
    if (!v || !views || *v >= views->size() || !(*views)[*v].is_object())
      throw InputError(what + " names a bufferView that does not exist");
    const nlohmann::json& view = (*views)[*v];
    const std::string view_name = what + "'s bufferView " + std::to_string(*v);
    const std::optional<uint64_t> b =
        view.contains("buffer") ? whole_number(view["buffer"]) : std::nullopt;
    if (!b || !buffers || *b >= buffers->size() || !(*buffers)[*b].is_object())
      throw InputError(view_name + " names a buffer that does not exist");
    const nlohmann::json& buffer = (*buffers)[*b];
    // A meshopt fallback buffer has no bytes of its own until its views are decoded, after the
    // images (gltf_parser_input.h hands tinygltf a 4-byte placeholder for it).
    const nlohmann::json* meshopt = buffer.contains("extensions") &&
                                            buffer["extensions"].is_object() &&
                                            buffer["extensions"].contains("EXT_meshopt_compression")
                                        ? &buffer["extensions"]["EXT_meshopt_compression"]
                                        : nullptr;
    if (meshopt && meshopt->is_object() && meshopt->value("fallback", false) == true)
      throw InputError(view_name + " lies in a meshopt fallback buffer, which holds no image");
    const std::optional<uint64_t> offset =
        view.contains("byteOffset") ? whole_number(view["byteOffset"]) : uint64_t(0);
    const std::optional<uint64_t> length =
        view.contains("byteLength") ? whole_number(view["byteLength"]) : std::nullopt;
    const std::optional<uint64_t> size =
        buffer.contains("byteLength") ? whole_number(buffer["byteLength"]) : std::nullopt;
    if (!offset || !length || !size)
      throw InputError(view_name + " or its buffer has no valid byteOffset or byteLength");
    // (value_or: GCC 12 takes the dereferences below the throw for reads of unset optionals.)
    const uint64_t start = offset.value_or(0), count = length.value_or(0), total = size.value_or(0);
    if (start > total || count > total - start)  // (no sum: it cannot wrap)
      throw InputError(view_name + " runs past the end of its buffer (bytes " +
                       std::to_string(start) + " to " + std::to_string(start + count) + " of " +
                       std::to_string(total) + ")");
  }
}

}  // namespace

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
  check_image_views(doc, name);
}

}  // namespace gltf
}  // namespace hipr
