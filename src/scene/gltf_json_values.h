#pragma once
// Reading and writing the numbers of glTF JSON the way the loader reads them (double -> float),
// for the writer: a value is rewritten only when the file does not already load as it, so what
// an edit did not touch keeps the file's own text.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace hipr::gltf {

// Key order is kept, so a saved file reads like its source.
using Json = nlohmann::ordered_json;

// The numbers of object[key] when it is an array of numbers, else empty.
std::vector<double> json_numbers(const Json& object, const char* key);

// The shortest decimal that still loads as `value` (0.05f is written 0.05, not 0.0500000007).
// InputError for infinity or NaN, which JSON cannot hold.
double json_number(float value);

// Sets object[key] to `written` (n numbers; n == 1 writes a number, else an array) unless the
// key already loads as `wanted` or as `written`, or is absent and `absent` (what the loader
// assumes then) equals `wanted` or `written`. `written` differs from `wanted` where glTF's
// valid range is narrower than hipr's (the exact value then goes to extras).
void put_numbers(Json& object, const char* key, const std::vector<float>& wanted,
                 const std::vector<float>& written, const std::vector<float>& absent);
inline void put_number(Json& object, const char* key, float wanted, float written, float absent) {
  put_numbers(object, key, {wanted}, {written}, {absent});
}

// Whether object[key] loads as `values` (absent: `absent` does).
bool loads_as(const Json& object, const char* key, const std::vector<float>& values,
              const std::vector<float>& absent);

// Runs `edit` on a copy of parent[key] (an empty object when absent) and stores the result
// unless it stayed empty and was absent, so nothing appears where nothing was written.
template <typename Edit>
void edit_object(Json& parent, const char* key, Edit&& edit) {
  Json object = parent.contains(key) && parent[key].is_object() ? parent[key] : Json::object();
  edit(object);
  if (!object.empty() || parent.contains(key)) parent[key] = std::move(object);
}

// object[key] as an array, made an empty one where it is absent or something else (a list the
// writer appends to).
Json& array_member(Json& object, const char* key);

// Whether a buffer object is an EXT_meshopt_compression fallback: bytes the extension decodes
// into, which may have no data at all (read by the loader and kept by the GLB writer).
bool is_meshopt_fallback(const Json& buffer);
// Appends `value` to array_member(object, key); returns its index there.
size_t append_to(Json& object, const char* key, Json value);
// The length of object[key] when it is an array, else 0 (how many of a kind the file has).
size_t array_length(const Json& object, const char* key);

// Removes extras[key]; drops `extras` when that leaves it empty.
void erase_extra(Json& owner, const char* key);

// Stores `value` as extras[key]; `what` names the owner in the error thrown when its extras
// are not an object (glTF allows any value there, but then there is no room for ours).
void set_extra(Json& owner, const char* key, Json value, const std::string& what);

}  // namespace hipr::gltf
