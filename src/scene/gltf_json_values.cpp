#include "scene/gltf_json_values.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/error.h"

namespace hipr::gltf {

std::vector<double> json_numbers(const Json& object, const char* key) {
  std::vector<double> out;
  if (!object.is_object() || !object.contains(key) || !object[key].is_array()) return out;
  for (const Json& v : object[key]) {
    if (!v.is_number()) return {};
    out.push_back(v.get<double>());
  }
  return out;
}

double json_number(float value) {
  // JSON has no infinity or NaN (nlohmann would write null); edits never make them, the API might.
  if (!std::isfinite(value))
    throw InputError("cannot save a non-finite number (" + std::to_string(value) + ")");
  // The loader parses a double and rounds it to float: find the shortest text for which that
  // gives `value` back (9 significant digits always do).
  char text[32];
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, double(value));
    const double parsed = std::strtod(text, nullptr);
    if (float(parsed) == value) return parsed;
  }
  return double(value);
}

bool loads_as(const Json& object, const char* key, const std::vector<float>& values,
              const std::vector<float>& absent) {
  if (!object.is_object() || !object.contains(key)) return absent == values;
  const Json& v = object[key];
  if (values.size() == 1) return v.is_number() && float(v.get<double>()) == values[0];
  const std::vector<double> numbers = json_numbers(object, key);
  if (numbers.size() != values.size()) return false;
  for (size_t k = 0; k < values.size(); ++k)
    if (float(numbers[k]) != values[k]) return false;
  return true;
}

void put_numbers(Json& object, const char* key, const std::vector<float>& wanted,
                 const std::vector<float>& written, const std::vector<float>& absent) {
  if (loads_as(object, key, wanted, absent) || loads_as(object, key, written, absent)) return;
  if (written.size() == 1) {
    object[key] = json_number(written[0]);
    return;
  }
  Json array = Json::array();
  for (float v : written) array.push_back(json_number(v));
  object[key] = std::move(array);
}

Json& array_member(Json& object, const char* key) {
  if (!object.contains(key) || !object[key].is_array()) object[key] = Json::array();
  return object[key];
}

size_t append_to(Json& object, const char* key, Json value) {
  Json& array = array_member(object, key);
  array.push_back(std::move(value));
  return array.size() - 1;
}

size_t array_length(const Json& object, const char* key) {
  return object.is_object() && object.contains(key) && object[key].is_array() ? object[key].size()
                                                                              : 0;
}

void erase_extra(Json& owner, const char* key) {
  if (!owner.contains("extras") || !owner["extras"].is_object() || !owner["extras"].contains(key))
    return;
  owner["extras"].erase(key);
  if (owner["extras"].empty()) owner.erase("extras");
}

void set_extra(Json& owner, const char* key, Json value, const std::string& what) {
  if (owner.contains("extras") && !owner["extras"].is_object())
    throw InputError(what + " has extras that are not a JSON object; cannot store extras." + key +
                     " there");
  owner["extras"][key] = std::move(value);
}

bool is_meshopt_fallback(const Json& buffer) {
  if (!buffer.is_object() || !buffer.contains("extensions") || !buffer["extensions"].is_object())
    return false;
  const Json& extensions = buffer["extensions"];
  if (!extensions.contains("EXT_meshopt_compression")) return false;
  const Json& ext = extensions["EXT_meshopt_compression"];
  return ext.is_object() && ext.contains("fallback") && ext["fallback"].is_boolean() &&
         ext["fallback"].get<bool>();
}

}  // namespace hipr::gltf
