#include "scene/gltf_textures.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/log.h"

namespace hipr::gltf {
namespace {

// A checkerboard so a missing texture is obvious in the image, never silently black.
Image fallback_image(const std::string& name) {
  Image t;
  t.name = name + " (missing image)";
  t.width = t.height = 8;
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 8; ++x) {
      const bool magenta = ((x / 2) + (y / 2)) % 2 == 0;
      t.rgba8.insert(t.rgba8.end(),
                     {uint8_t(magenta ? 255 : 0), 0, uint8_t(magenta ? 255 : 0), 255});
    }
  return t;
}

uint32_t wrap_flags(int wrap, uint32_t clamp_bit, uint32_t mirror_bit) {
  if (wrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return clamp_bit;
  if (wrap == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return mirror_bit;
  return 0;
}

bool to_rgba8(const tinygltf::Image& image, std::vector<uint8_t>& out) {
  const size_t pixels = size_t(image.width) * size_t(image.height);
  const int comps = image.component;
  const int bytes = image.bits / 8;
  if (image.width <= 0 || image.height <= 0 || comps < 1 || comps > 4 ||
      (bytes != 1 && bytes != 2) || image.image.size() < pixels * size_t(comps) * size_t(bytes))
    return false;
  out.resize(pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    uint8_t c[4] = {0, 0, 0, 255};
    for (int k = 0; k < comps; ++k) {
      const size_t at = (i * size_t(comps) + size_t(k)) * size_t(bytes);
      // 16-bit PNG data is stored little-endian by stb; keep the high byte.
      c[k] = bytes == 1 ? image.image[at] : image.image[at + 1];
    }
    if (comps == 1) c[1] = c[2] = c[0];  // grey
    if (comps == 2) {
      c[3] = c[1];
      c[1] = c[2] = c[0];
    }  // grey + alpha
    std::copy(c, c + 4, out.begin() + std::ptrdiff_t(i * 4));
  }
  return true;
}

float number(const tinygltf::Value& object, const char* key, float fallback) {
  if (!object.IsObject() || !object.Has(key) || !object.Get(key).IsNumber()) return fallback;
  const double d = object.Get(key).GetNumberAsDouble();
  return std::isfinite(d) ? float(d) : fallback;
}

glm::vec2 pair(const tinygltf::Value& object, const char* key, glm::vec2 fallback) {
  if (!object.Has(key) || !object.Get(key).IsArray() || object.Get(key).ArrayLen() != 2)
    return fallback;
  const tinygltf::Value& v = object.Get(key);
  const glm::vec2 p{float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble())};
  return std::isfinite(p.x) && std::isfinite(p.y) ? p : fallback;
}

template <typename Info>
TextureReference core_reference(const Info& info) {
  TextureReference r;
  r.index = info.index;
  r.texcoord = info.texCoord;
  if (const auto it = info.extensions.find("KHR_texture_transform"); it != info.extensions.end())
    r.transform = &it->second;
  return r;
}

// KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv. The rotation turns UVs
// counter-clockwise in the spec's sense: u' = cos*u + sin*v, v' = -sin*u + cos*v.
void apply_transform(const tinygltf::Value& t, Texture& out, int& texcoord) {
  const glm::vec2 offset = pair(t, "offset", glm::vec2(0.0f));
  const glm::vec2 scale = pair(t, "scale", glm::vec2(1.0f));
  const float rotation = number(t, "rotation", 0.0f);
  const float c = std::cos(rotation), s = std::sin(rotation);
  out.uv_transform_u = {c * scale.x, s * scale.y, offset.x};
  out.uv_transform_v = {-s * scale.x, c * scale.y, offset.y};
  if (t.Has("texCoord") && t.Get("texCoord").IsInt()) texcoord = t.Get("texCoord").GetNumberAsInt();
}

}  // namespace

TextureReference texture_reference(const tinygltf::TextureInfo& info) {
  return core_reference(info);
}
TextureReference texture_reference(const tinygltf::NormalTextureInfo& info) {
  return core_reference(info);
}

TextureReference texture_reference(const tinygltf::Value& extension, const char* key) {
  TextureReference r;
  if (!extension.Has(key) || !extension.Get(key).IsObject()) return r;
  const tinygltf::Value& info = extension.Get(key);
  if (info.Has("index") && info.Get("index").IsInt()) r.index = info.Get("index").GetNumberAsInt();
  if (info.Has("texCoord") && info.Get("texCoord").IsInt())
    r.texcoord = info.Get("texCoord").GetNumberAsInt();
  if (info.Has("extensions") && info.Get("extensions").Has("KHR_texture_transform"))
    r.transform = &info.Get("extensions").Get("KHR_texture_transform");
  return r;
}

namespace {

// The image a texture shows: a WebP, AVIF or DDS source (EXT_texture_webp, EXT_texture_avif,
// MSFT_texture_dds; gltf_image_decode.h) before the core `source`, which is then the file's
// fallback. A KTX2 source (KHR_texture_basisu) has no packaged decoder: the fallback is used, and
// without one the file cannot be shown as its author meant, which is an error rather than a guess.
// An extension's image that could not be decoded (a DDS format hipr does not decode, a broken
// WebP) gives way to the fallback too, where there is one: that is what the fallback is for.
int image_source(const tinygltf::Model& model, const tinygltf::Texture& source, int texture,
                 const std::string& what) {
  for (const char* extension : {"EXT_texture_webp", "EXT_texture_avif", "MSFT_texture_dds"}) {
    const auto it = source.extensions.find(extension);
    if (it == source.extensions.end() || !it->second.Has("source") ||
        !it->second.Get("source").IsInt())
      continue;
    const int index = it->second.Get("source").GetNumberAsInt();
    const bool decoded = index >= 0 && size_t(index) < model.images.size() &&
                         !model.images[size_t(index)].image.empty();
    if (decoded || source.source < 0) return index;
  }
  if (source.source < 0 && source.extensions.count("KHR_texture_basisu"))
    throw InputError(what + ": texture " + std::to_string(texture) +
                     " is only in KTX2/Basis Universal (KHR_texture_basisu), which hipr cannot "
                     "decode: export it with a PNG, JPEG or WebP fallback");
  return source.source;
}

}  // namespace

uint32_t TextureTable::image_for(const tinygltf::Texture& source, int texture,
                                 const std::string& what) {
  // A broken or missing image gets its own fallback per texture, so the warning names it once.
  const int index = image_source(m_model, source, texture, what);
  const bool has_image = index >= 0 && size_t(index) < m_model.images.size();
  if (index >= 0 && !has_image)
    throw InputError(what + ": texture " + std::to_string(texture) + " references missing image " +
                     std::to_string(index));
  const int key = has_image ? index : -1 - texture;
  if (const auto it = m_images.find(key); it != m_images.end()) return it->second;

  Image image;
  image.name = source.name.empty() ? "texture " + std::to_string(texture) : source.name;
  bool ok = false;
  if (has_image) {
    const tinygltf::Image& decoded = m_model.images[size_t(index)];
    ok = to_rgba8(decoded, image.rgba8);
    image.width = uint32_t(std::max(decoded.width, 0));
    image.height = uint32_t(std::max(decoded.height, 0));
    if (!ok) {
      const std::string where =
          decoded.uri.empty() ? std::to_string(index) : "'" + decoded.uri + "'";
      log::warn(what + ": texture image " + where +
                " could not be read; rendering a magenta checkerboard instead");
    }
  } else {
    log::warn(what + ": texture " + std::to_string(texture) +
              " has no image; rendering a magenta checkerboard instead");
  }
  if (!ok) {
    image = fallback_image(image.name);
    m_fallbacks.insert(uint32_t(m_scene.images.size()));
  }
  image.revision = image_revision(image);
  m_scene.images.push_back(std::move(image));
  m_images[key] = uint32_t(m_scene.images.size() - 1);
  return uint32_t(m_scene.images.size() - 1);
}

uint32_t TextureTable::get(const TextureReference& reference, bool srgb, const std::string& what) {
  const int texture = reference.index;
  if (texture < 0) return kNoTexture;
  if (size_t(texture) >= m_model.textures.size())
    throw InputError(what + " references missing texture " + std::to_string(texture));
  const tinygltf::Texture& source = m_model.textures[size_t(texture)];

  Texture t;
  t.name = source.name.empty() ? "texture " + std::to_string(texture) : source.name;
  t.flags = srgb ? kTextureSrgb : 0u;
  if (source.sampler >= 0) {
    if (size_t(source.sampler) >= m_model.samplers.size())
      throw InputError(what + ": texture " + std::to_string(texture) +
                       " references missing sampler");
    const tinygltf::Sampler& s = m_model.samplers[size_t(source.sampler)];
    t.flags |= wrap_flags(s.wrapS, kTextureClampU, kTextureMirrorU);
    t.flags |= wrap_flags(s.wrapT, kTextureClampV, kTextureMirrorV);
    if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) t.flags |= kTextureNearest;
  }
  int texcoord = reference.texcoord;
  if (reference.transform) apply_transform(*reference.transform, t, texcoord);
  if (texcoord == 1)
    t.flags |= kTextureUv1;
  else if (texcoord != 0)
    log::warn(what + ": texture " + std::to_string(texture) + " reads TEXCOORD_" +
              std::to_string(texcoord) +
              "; only TEXCOORD_0 and TEXCOORD_1 are loaded, TEXCOORD_0 is used");
  t.image = image_for(source, texture, what);
  if (m_fallbacks.count(t.image)) t.flags |= kTextureNearest;  // crisp checker squares

  for (size_t i = 0; i < m_scene.textures.size(); ++i) {
    const Texture& other = m_scene.textures[i];
    if (other.image == t.image && other.flags == t.flags &&
        other.uv_transform_u == t.uv_transform_u && other.uv_transform_v == t.uv_transform_v)
      return uint32_t(i);
  }
  m_scene.textures.push_back(std::move(t));
  return uint32_t(m_scene.textures.size() - 1);
}

}  // namespace hipr::gltf
