#pragma once
// The glTF -> OpenPBR parameter table (see gltf_material_table.cpp for the whole mapping).
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace hipr::gltf {

// A number or colour of a material extension that lands in one MaterialParameters field.
struct FactorRow {
  const char* extension;
  const char* key;
  size_t field;  // offsetof(MaterialParameters, ...): float, or vec3 when components == 3
  int components;
  glm::vec3 fallback;  // glTF's default when the extension is present but the key is not
  float lo, hi;        // valid range; values outside are clamped
};

// A textureInfo of a material extension that lands in one MaterialParameters texture slot.
struct TextureRow {
  const char* extension;
  const char* key;
  size_t field;  // offsetof(MaterialParameters, ..._texture)
  bool srgb;     // colour data (sRGB-encoded) rather than linear numbers
};

const std::vector<FactorRow>& factor_rows();
const std::vector<TextureRow>& texture_rows();

}  // namespace hipr::gltf
