#include "scene/gltf_texture_writer.h"

#include <stb_image_write.h>

#include <cmath>

#include "core/error.h"

namespace hipr::gltf {
namespace {

constexpr int kNearest = 9728, kLinear = 9729;
constexpr int kClamp = 33071, kMirror = 33648, kRepeat = 10497;

int wrap(uint32_t flags, uint32_t clamp, uint32_t mirror) {
  return (flags & clamp) ? kClamp : (flags & mirror) ? kMirror : kRepeat;
}

std::vector<unsigned char> png_of(const Image& image) {
  std::vector<unsigned char> png;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
  };
  if (image.width == 0 || image.height == 0 ||
      image.rgba8.size() != size_t(image.width) * image.height * 4 ||
      !stbi_write_png_to_func(append, &png, int(image.width), int(image.height), 4,
                              image.rgba8.data(), int(image.width * 4)))
    throw InputError("cannot encode image '" + image.name + "' as PNG");
  return png;
}

}  // namespace

size_t TextureWriter::image(uint32_t index) {
  if (const auto it = m_images.find(index); it != m_images.end()) return it->second;
  const Image& source = m_scene.images.at(index);
  const std::vector<unsigned char> png = png_of(source);
  Json image = {{"name", source.name},
                {"bufferView", m_out.add_view(png.data(), png.size(), 0)},
                {"mimeType", "image/png"}};
  return m_images[index] = append_to(m_doc, "images", std::move(image));
}

size_t TextureWriter::sampler(uint32_t flags) {
  const uint32_t key = flags & (kTextureNearest | kTextureClampU | kTextureClampV |
                                kTextureMirrorU | kTextureMirrorV);
  if (const auto it = m_samplers.find(key); it != m_samplers.end()) return it->second;
  Json sampler = {{"magFilter", (key & kTextureNearest) ? kNearest : kLinear},
                  {"wrapS", wrap(key, kTextureClampU, kTextureMirrorU)},
                  {"wrapT", wrap(key, kTextureClampV, kTextureMirrorV)}};
  return m_samplers[key] = append_to(m_doc, "samplers", std::move(sampler));
}

Json TextureWriter::texture_info(uint32_t index) {
  const Texture& t = m_scene.textures.at(index);
  auto it = m_textures.find(index);
  if (it == m_textures.end()) {
    Json texture = {{"sampler", sampler(t.flags)}, {"source", image(t.image)}};
    if (!t.name.empty()) texture["name"] = t.name;
    it = m_textures.emplace(index, append_to(m_doc, "textures", std::move(texture))).first;
  }
  Json info = {{"index", it->second}};
  if (t.flags & kTextureUv1) info["texCoord"] = 1;
  // KHR_texture_transform as the loader reads it (gltf_textures.cpp): u' = (c sx, s sy, ox),
  // v' = (-s sx, c sy, oy).
  const glm::vec3 u = t.uv_transform_u, v = t.uv_transform_v;
  if (u != glm::vec3(1.0f, 0.0f, 0.0f) || v != glm::vec3(0.0f, 1.0f, 0.0f)) {
    const float rotation = std::atan2(-v.x, u.x);
    const float c = std::cos(rotation), s = std::sin(rotation);
    const float sx = c * u.x - s * v.x, sy = s * u.y + c * v.y;
    Json transform = {{"offset", {json_number(u.z), json_number(v.z)}},
                      {"rotation", json_number(rotation)},
                      {"scale", {json_number(sx), json_number(sy)}}};
    info["extensions"]["KHR_texture_transform"] = std::move(transform);
    m_uses_transform = true;
  }
  return info;
}

}  // namespace hipr::gltf
