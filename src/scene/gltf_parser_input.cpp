#include "scene/gltf_parser_input.h"

#include <nlohmann/json.hpp>

#include <algorithm>

#include "core/error.h"
#include "scene/glb_container.h"
#include "scene/gltf_json_values.h"
#include "scene/gltf_precheck.h"

namespace hipr::gltf {
namespace {

// Four zero bytes: tinygltf refuses both a buffer without data and an empty data: URI.
constexpr const char* kPlaceholderUri = "data:application/octet-stream;base64,AAAAAA==";

bool is_draco(const Json& primitive) {
  return primitive.is_object() && primitive.contains("extensions") &&
         primitive["extensions"].is_object() &&
         primitive["extensions"].contains("KHR_draco_mesh_compression");
}

bool stub_fallbacks(Json& doc, ParserInput& input, const std::string& name) {
  if (!doc.contains("buffers") || !doc["buffers"].is_array()) return false;
  size_t total = 0;
  for (size_t i = 0; i < doc["buffers"].size(); ++i) {
    Json& buffer = doc["buffers"][i];
    if (!is_meshopt_fallback(buffer)) continue;
    if (!buffer.contains("byteLength") || !buffer["byteLength"].is_number_unsigned())
      throw InputError(name + ": buffer " + std::to_string(i) + " has no valid byteLength");
    const size_t length = buffer["byteLength"].get<size_t>();
    total += std::min(length, kMaxDecodedBytes + 1);
    if (total > kMaxDecodedBytes)
      throw InputError(name + ": its compressed buffers decode to more than " +
                       std::to_string(kMaxDecodedBytes >> 30) + " GiB (hipr's limit)");
    input.fallbacks.push_back({i, length});
    buffer["uri"] = kPlaceholderUri;
    buffer["byteLength"] = 4;
  }
  return !input.fallbacks.empty();
}

bool set_aside_draco_indices(Json& doc, ParserInput& input) {
  if (!doc.contains("meshes") || !doc["meshes"].is_array()) return false;
  for (size_t m = 0; m < doc["meshes"].size(); ++m) {
    Json& mesh = doc["meshes"][m];
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
      continue;
    for (size_t p = 0; p < mesh["primitives"].size(); ++p) {
      Json& primitive = mesh["primitives"][p];
      if (!is_draco(primitive) || !primitive.contains("indices") ||
          !primitive["indices"].is_number_integer())
        continue;
      const int64_t accessor = primitive["indices"].get<int64_t>();
      input.draco_indices.push_back(
          {m, p, accessor < 0 || accessor > INT32_MAX ? INT32_MAX : int(accessor)});
      primitive.erase("indices");
    }
  }
  return !input.draco_indices.empty();
}

}  // namespace

ParserInput prepare_parser_input(const std::vector<unsigned char>& bytes, bool glb,
                                 const std::string& name) {
  ParserInput input;
  // Parsed already by precheck_json: this cannot throw for a document that got this far.
  Json doc = Json::parse(json_text(bytes, glb));
  const bool fallbacks = stub_fallbacks(doc, input, name);
  const bool draco = set_aside_draco_indices(doc, input);
  if (!fallbacks && !draco) return input;
  const std::string text = doc.dump();
  input.rewritten =
      glb ? glb_with_json(bytes, text) : std::vector<unsigned char>(text.begin(), text.end());
  return input;
}

}  // namespace hipr::gltf
