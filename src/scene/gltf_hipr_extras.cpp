#include "scene/gltf_hipr_extras.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "core/error.h"
#include "scene/material_parameters.h"

namespace hipr::gltf {
namespace {

// The `count` numbers of `value` (a number when count is 1, else an array of `count`), each
// finite and inside [lo, hi]; InputError naming `what` otherwise.
std::vector<float> numbers(const tinygltf::Value& value, int count, float lo, float hi,
                           const std::string& what) {
  std::vector<float> out;
  if (count == 1 && value.IsNumber()) {
    out.push_back(float(value.GetNumberAsDouble()));
  } else if (count > 1 && value.IsArray() && value.ArrayLen() == size_t(count)) {
    for (int k = 0; k < count; ++k) {
      if (!value.Get(k).IsNumber()) break;
      out.push_back(float(value.Get(k).GetNumberAsDouble()));
    }
  }
  if (out.size() != size_t(count))
    throw InputError(what + (count == 1
                                 ? " must be a number"
                                 : " must be an array of " + std::to_string(count) + " numbers"));
  for (float v : out)
    if (!std::isfinite(v) || v < lo || v > hi)
      throw InputError(what + " holds " + std::to_string(v) + ", outside [" + std::to_string(lo) +
                       ", " + std::to_string(hi) + "]");
  return out;
}

const tinygltf::Value* member(const tinygltf::Value& extras, const char* key,
                              const std::string& what) {
  if (!extras.IsObject() || !extras.Has(key)) return nullptr;
  const tinygltf::Value& value = extras.Get(key);
  if (!value.IsObject()) throw InputError(what + ": extras." + key + " is not an object");
  return &value;
}

}  // namespace

void apply_openpbr_extras(const tinygltf::Value& extras, const char* key,
                          MaterialParameters& params, const std::string& what) {
  const tinygltf::Value* overrides = member(extras, key, what);
  if (!overrides) return;
  for (const std::string& name : overrides->Keys()) {
    const std::string where = what + ": extras." + key + "." + name;
    const MaterialParameter* parameter = find_material_parameter(name);
    if (!parameter) throw InputError(where + " is not an OpenPBR parameter hipr knows");
    const std::vector<float> v =
        numbers(overrides->Get(name), parameter->components, parameter->min, parameter->max, where);
    std::memcpy(reinterpret_cast<char*>(&params) + parameter->offset, v.data(),
                v.size() * sizeof(float));
  }
}

void apply_light_extras(const tinygltf::Value& extras, PunctualLight& light,
                        const std::string& what) {
  const tinygltf::Value* overrides = member(extras, kLightExtras, what);
  if (!overrides) return;
  constexpr float kMax = std::numeric_limits<float>::max();
  for (const std::string& name : overrides->Keys()) {
    const std::string where = what + ": extras." + kLightExtras + "." + name;
    if (name == "color") {
      const std::vector<float> v = numbers(overrides->Get(name), 3, 0.0f, kMax, where);
      light.color = glm::vec3(v[0], v[1], v[2]);
    } else if (name == "intensity") {
      light.intensity = numbers(overrides->Get(name), 1, 0.0f, kMax, where)[0];
    } else {
      throw InputError(where + " is not a light parameter (color, intensity)");
    }
  }
}

void apply_lens_extras(const tinygltf::Value& extras, Camera& camera, const std::string& what) {
  const tinygltf::Value* lens = member(extras, kLensExtras, what);
  if (!lens) return;
  for (const std::string& name : lens->Keys()) {
    const std::string where = what + ": extras." + kLensExtras + "." + name;
    if (name == "aperture_radius")
      camera.aperture_radius = numbers(lens->Get(name), 1, 0.0f, 1e6f, where)[0];
    else if (name == "focus_distance")
      camera.focus_distance = numbers(lens->Get(name), 1, 1e-30f, 1e12f, where)[0];
    else
      throw InputError(where + " is not a lens parameter (aperture_radius, focus_distance)");
  }
}

}  // namespace hipr::gltf
