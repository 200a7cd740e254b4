#pragma once
// glTF material -> OpenPBR parameter block, and glTF textures -> our RGBA8 texture table.
#include <tiny_gltf.h>

#include "hipr/scene.h"

namespace hipr::gltf {

// Builds scene.textures lazily: one Texture per (glTF texture, colour space) actually used.
class TextureTable {
 public:
  TextureTable(const tinygltf::Model& model, Scene& scene) : m_model(model), m_scene(scene) {}
  // Returns the texture index, or kInvalidIndex when `texture` < 0.
  uint32_t get(int texture, bool srgb, const std::string& what);

 private:
  const tinygltf::Model& m_model;
  Scene& m_scene;
  std::vector<std::pair<int, bool>> m_keys;
  std::vector<uint32_t> m_values;
};

// `file` names the scene in error messages.
Material convert_material(const tinygltf::Material& material, size_t index, TextureTable& textures,
                          const std::string& file);

}  // namespace hipr::gltf
