#pragma once
// glTF textureInfo objects -> Scene::textures (how a material reads an image) and Scene::images
// (decoded texels, one per glTF image however many references sample it).
#include <tiny_gltf.h>

#include <map>
#include <set>
#include <string>

#include "hipr/scene.h"

namespace hipr::gltf {

// A glTF textureInfo as the loader needs it, from the core structs or from extension JSON.
struct TextureReference {
  int index = -1;
  int texcoord = 0;
  const tinygltf::Value* transform = nullptr;  // its KHR_texture_transform object, if any
};

TextureReference texture_reference(const tinygltf::TextureInfo& info);
TextureReference texture_reference(const tinygltf::NormalTextureInfo& info);
// `extension` is a material extension object; `key` names a textureInfo inside it.
TextureReference texture_reference(const tinygltf::Value& extension, const char* key);

class TextureTable {
 public:
  TextureTable(const tinygltf::Model& model, Scene& scene) : m_model(model), m_scene(scene) {}
  // Returns the Scene::textures index, or kInvalidIndex when the reference names no texture.
  // Equal references share one entry; entries on the same image share its texels.
  uint32_t get(const TextureReference& reference, bool srgb, const std::string& what);
  // The scene the entries go into (for textures derived from others: gltf_spec_gloss.h).
  Scene& scene() { return m_scene; }

 private:
  uint32_t image_for(const tinygltf::Texture& source, int texture, const std::string& what);

  const tinygltf::Model& m_model;
  Scene& m_scene;
  std::map<int, uint32_t>
      m_images;  // glTF image index (-1 - texture for a fallback) -> Scene::images
  std::set<uint32_t> m_fallbacks;  // Scene::images that are the magenta checker
};

}  // namespace hipr::gltf
