#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/log.h"

namespace hipr::gltf {
namespace {

float number(const tinygltf::Value& object, const char* key, float fallback) {
  if (!object.IsObject() || !object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsNumber()) return fallback;
  const double d = v.GetNumberAsDouble();
  return std::isfinite(d) ? float(d) : fallback;
}

glm::vec3 color(const std::vector<double>& values, glm::vec3 fallback) {
  if (values.size() < 3) return fallback;
  const glm::vec3 c{float(values[0]), float(values[1]), float(values[2])};
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(c[k])) return fallback;
  return glm::max(c, glm::vec3(0.0f));
}

const tinygltf::Value* extension(const tinygltf::Material& m, const char* name) {
  const auto it = m.extensions.find(name);
  return it == m.extensions.end() ? nullptr : &it->second;
}

// A checkerboard so a missing texture is obvious in the image, never silently black.
Texture fallback_texture(const std::string& name, bool srgb) {
  Texture t;
  t.name = name + " (missing image)";
  t.width = t.height = 8;
  t.flags = abi::kTextureNearest | (srgb ? abi::kTextureSrgb : 0u);
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 8; ++x) {
      const bool magenta = ((x / 2) + (y / 2)) % 2 == 0;
      t.rgba8.insert(t.rgba8.end(), {uint8_t(magenta ? 255 : 0), 0, uint8_t(magenta ? 255 : 0), 255});
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
  if (image.width <= 0 || image.height <= 0 || comps < 1 || comps > 4 || (bytes != 1 && bytes != 2) ||
      image.image.size() < pixels * size_t(comps) * size_t(bytes))
    return false;
  out.resize(pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    uint8_t c[4] = {0, 0, 0, 255};
    for (int k = 0; k < comps; ++k) {
      const size_t at = (i * size_t(comps) + size_t(k)) * size_t(bytes);
      // 16-bit PNG data is stored little-endian by stb; keep the high byte.
      c[k] = bytes == 1 ? image.image[at] : image.image[at + 1];
    }
    if (comps == 1) c[1] = c[2] = c[0];                    // grey
    if (comps == 2) { c[3] = c[1]; c[1] = c[2] = c[0]; }   // grey + alpha
    std::copy(c, c + 4, out.begin() + std::ptrdiff_t(i * 4));
  }
  return true;
}

}  // namespace

uint32_t TextureTable::get(int texture, bool srgb, const std::string& what) {
  if (texture < 0) return abi::kInvalidIndex;
  for (size_t i = 0; i < m_keys.size(); ++i)
    if (m_keys[i] == std::make_pair(texture, srgb)) return m_values[i];
  if (size_t(texture) >= m_model.textures.size())
    throw InputError(what + " references missing texture " + std::to_string(texture));
  const tinygltf::Texture& source = m_model.textures[size_t(texture)];

  Texture t;
  t.name = source.name.empty() ? "texture " + std::to_string(texture) : source.name;
  t.flags = srgb ? abi::kTextureSrgb : 0u;
  if (source.sampler >= 0) {
    if (size_t(source.sampler) >= m_model.samplers.size())
      throw InputError(what + ": texture " + std::to_string(texture) + " references missing sampler");
    const tinygltf::Sampler& s = m_model.samplers[size_t(source.sampler)];
    t.flags |= wrap_flags(s.wrapS, abi::kTextureClampU, abi::kTextureMirrorU);
    t.flags |= wrap_flags(s.wrapT, abi::kTextureClampV, abi::kTextureMirrorV);
    if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) t.flags |= abi::kTextureNearest;
  }
  bool ok = false;
  if (source.source >= 0 && size_t(source.source) < m_model.images.size()) {
    const tinygltf::Image& image = m_model.images[size_t(source.source)];
    ok = to_rgba8(image, t.rgba8);
    t.width = uint32_t(std::max(image.width, 0));
    t.height = uint32_t(std::max(image.height, 0));
    if (!ok) {
      const std::string where = image.uri.empty() ? std::to_string(source.source) : "'" + image.uri + "'";
      log::warn(what + ": texture image " + where + " could not be read; rendering a magenta checkerboard instead");
    }
  } else if (source.source >= 0) {
    throw InputError(what + ": texture " + std::to_string(texture) + " references missing image " + std::to_string(source.source));
  } else {
    log::warn(what + ": texture " + std::to_string(texture) + " has no image; rendering a magenta checkerboard instead");
  }
  if (!ok) t = fallback_texture(t.name, srgb);

  m_scene.textures.push_back(std::move(t));
  const uint32_t index = uint32_t(m_scene.textures.size() - 1);
  m_keys.emplace_back(texture, srgb);
  m_values.push_back(index);
  return index;
}

Material convert_material(const tinygltf::Material& m, size_t index, TextureTable& textures,
                          const std::string& file) {
  Material out;
  out.name = m.name.empty() ? "material " + std::to_string(index) : m.name;
  abi::MaterialBlock& p = out.params;
  p = default_material_params();
  const std::string what = file + ": material " + std::to_string(index) + " ('" + out.name + "')";

  const auto& pbr = m.pbrMetallicRoughness;
  p.base_color = color(pbr.baseColorFactor, glm::vec3(1.0f));
  p.base_weight = 1.0f;
  p.base_metalness = std::clamp(float(pbr.metallicFactor), 0.0f, 1.0f);
  p.specular_roughness = std::clamp(float(pbr.roughnessFactor), 0.0f, 1.0f);
  const float alpha = pbr.baseColorFactor.size() >= 4 ? float(pbr.baseColorFactor[3]) : 1.0f;
  p.geometry_opacity = m.alphaMode == "OPAQUE" ? 1.0f : std::clamp(alpha, 0.0f, 1.0f);
  p.base_color_texture = textures.get(pbr.baseColorTexture.index, true, what);
  p.metallic_roughness_texture = textures.get(pbr.metallicRoughnessTexture.index, false, what);
  p.normal_texture = textures.get(m.normalTexture.index, false, what);
  p.normal_scale = float(m.normalTexture.scale);
  p.emission_texture = textures.get(m.emissiveTexture.index, true, what);

  // Emission in nits: emissiveFactor (colour) x KHR_materials_emissive_strength (luminance).
  p.emission_color = color(m.emissiveFactor, glm::vec3(0.0f));
  p.emission_luminance = 1.0f;
  if (const auto* ext = extension(m, "KHR_materials_emissive_strength"))
    p.emission_luminance = std::max(number(*ext, "emissiveStrength", 1.0f), 0.0f);
  if (const auto* ext = extension(m, "KHR_materials_specular")) {
    p.specular_weight = std::max(number(*ext, "specularFactor", 1.0f), 0.0f);
    if (ext->Has("specularColorFactor") && ext->Get("specularColorFactor").IsArray()) {
      const tinygltf::Value& c = ext->Get("specularColorFactor");
      for (int k = 0; k < 3 && size_t(k) < c.ArrayLen(); ++k)
        p.specular_color[k] = std::max(float(c.Get(k).GetNumberAsDouble()), 0.0f);
    }
  }
  if (const auto* ext = extension(m, "KHR_materials_ior")) p.specular_ior = std::max(number(*ext, "ior", 1.5f), 1.0f);
  if (m.doubleSided) p.flags |= abi::kMaterialDoubleSided;
  return out;
}

}  // namespace hipr::gltf
