#pragma once
// Textures of materials the file does not have (imported ones) -> glTF: each Scene::images entry
// once, as a PNG of its decoded texels (lossless) in the writer's buffer; a sampler per wrap and
// filter; a texture per Scene::textures entry; and the textureInfo that reads it (texCoord,
// KHR_texture_transform).
#include <cstdint>
#include <map>

#include "hipr/scene.h"
#include "scene/gltf_buffer_writer.h"
#include "scene/gltf_json_values.h"

namespace hipr::gltf {

class TextureWriter {
 public:
  TextureWriter(Json& doc, const Scene& scene, BufferWriter& out)
      : m_doc(doc), m_scene(scene), m_out(out) {}

  // The textureInfo object for Scene::textures[texture], writing what it needs on first use.
  Json texture_info(uint32_t texture);
  // Whether a textureInfo got a KHR_texture_transform (for extensionsUsed).
  bool uses_transform() const { return m_uses_transform; }

 private:
  size_t image(uint32_t image);
  size_t sampler(uint32_t flags);

  Json& m_doc;
  const Scene& m_scene;
  BufferWriter& m_out;
  std::map<uint32_t, size_t> m_images, m_samplers,
      m_textures;  // scene index or flags -> glTF index
  bool m_uses_transform = false;
};

}  // namespace hipr::gltf
