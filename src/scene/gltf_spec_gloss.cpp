#include "scene/gltf_spec_gloss.h"

#include <algorithm>
#include <cmath>

namespace hipr::gltf {
namespace {

constexpr const char* kExtension = "KHR_materials_pbrSpecularGlossiness";
constexpr float kDielectricF0 = 0.04f;

struct SpecGloss {
  glm::vec4 diffuse{1.0f};
  glm::vec3 specular{1.0f};
  float glossiness = 1.0f;
};

struct MetalRough {
  glm::vec3 base_color{1.0f};
  float metalness = 0.0f;
  float roughness = 1.0f;
};

float perceived_brightness(glm::vec3 c) {
  return std::sqrt(0.299f * c.r * c.r + 0.587f * c.g * c.g + 0.114f * c.b * c.b);
}

// The metalness m for which a metal/rough surface of that metalness reflects `specular` at
// normal incidence and shows `diffuse` (brightnesses), from the quadratic in m that mixing
// F0 = lerp(0.04, base, m) and diffuse = base (1 - 0.04) (1 - m) gives.
float solve_metalness(float diffuse, float specular, float one_minus_specular_strength) {
  if (specular < kDielectricF0) return 0.0f;
  const float a = kDielectricF0;
  const float b = diffuse * one_minus_specular_strength / (1.0f - kDielectricF0) + specular -
                  2.0f * kDielectricF0;
  const float c = kDielectricF0 - specular;
  const float d = std::max(b * b - 4.0f * a * c, 0.0f);
  return std::clamp((-b + std::sqrt(d)) / (2.0f * a), 0.0f, 1.0f);
}

MetalRough convert(const SpecGloss& s) {
  const glm::vec3 diffuse(s.diffuse);
  const float one_minus = 1.0f - std::max({s.specular.r, s.specular.g, s.specular.b});
  MetalRough out;
  out.metalness =
      solve_metalness(perceived_brightness(diffuse), perceived_brightness(s.specular), one_minus);
  const float m = out.metalness;
  const glm::vec3 from_diffuse =
      diffuse * (one_minus / (1.0f - kDielectricF0) / std::max(1.0f - m, 1e-6f));
  const glm::vec3 from_specular = (s.specular - kDielectricF0 * (1.0f - m)) / std::max(m, 1e-6f);
  out.base_color = glm::clamp(glm::mix(from_diffuse, from_specular, m * m), 0.0f, 1.0f);
  out.roughness = std::clamp(1.0f - s.glossiness, 0.0f, 1.0f);
  return out;
}

SpecGloss factors(const tinygltf::Value& ext) {
  SpecGloss s;
  const auto number = [&](const char* key, float fallback) {
    if (!ext.Has(key) || !ext.Get(key).IsNumber()) return fallback;
    const float v = float(ext.Get(key).GetNumberAsDouble());
    return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : fallback;
  };
  const auto vector = [&](const char* key, int n, glm::vec4 fallback) {
    if (!ext.Has(key) || !ext.Get(key).IsArray() || int(ext.Get(key).ArrayLen()) < n)
      return fallback;
    glm::vec4 v = fallback;
    for (int k = 0; k < n; ++k) {
      const float x = float(ext.Get(key).Get(k).GetNumberAsDouble());
      v[k] = std::isfinite(x) ? std::clamp(x, 0.0f, 1.0f) : fallback[k];
    }
    return v;
  };
  s.diffuse = vector("diffuseFactor", 4, glm::vec4(1.0f));
  s.specular = glm::vec3(vector("specularFactor", 3, glm::vec4(1.0f)));
  s.glossiness = number("glossinessFactor", 1.0f);
  return s;
}

const tinygltf::Value* extension(const tinygltf::Material& m) {
  const auto it = m.extensions.find(kExtension);
  return it == m.extensions.end() || !it->second.IsObject() ? nullptr : &it->second;
}

bool textured(const tinygltf::Value& ext) {
  return texture_reference(ext, "diffuseTexture").index >= 0 ||
         texture_reference(ext, "specularGlossinessTexture").index >= 0;
}

float to_linear(uint8_t v) {
  const float c = float(v) / 255.0f;
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

uint8_t to_srgb8(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return uint8_t(std::lround(s * 255.0f));
}

// The RGBA8 texel of `image` nearest to (u, v) in [0, 1].
glm::u8vec4 texel(const Image& image, float u, float v) {
  const uint32_t x = std::min(uint32_t(u * float(image.width)), image.width - 1);
  const uint32_t y = std::min(uint32_t(v * float(image.height)), image.height - 1);
  const uint8_t* p = &image.rgba8[(size_t(y) * image.width + x) * 4];
  return {p[0], p[1], p[2], p[3]};
}

}  // namespace

void apply_spec_gloss_factors(const tinygltf::Material& m, MaterialParameters& p) {
  const tinygltf::Value* ext = extension(m);
  if (!ext) return;
  const SpecGloss s = factors(*ext);
  p.specular_weight = 1.0f;
  p.specular_color = glm::vec3(1.0f);
  p.specular_ior = 1.5f;
  if (textured(*ext)) {  // the baked images hold the product of factors and texels
    p.base_color = glm::vec3(1.0f);
    p.base_metalness = 1.0f;
    p.specular_roughness = 1.0f;
  } else {
    const MetalRough mr = convert(s);
    p.base_color = mr.base_color;
    p.base_metalness = mr.metalness;
    p.specular_roughness = mr.roughness;
  }
  // Opacity: the diffuse alpha, as alphaMode reads baseColorFactor's.
  if (m.alphaMode == "MASK" || m.alphaMode == "BLEND") p.geometry_opacity = s.diffuse.a;
}

void apply_spec_gloss_textures(const tinygltf::Material& m, MaterialParameters& p,
                               TextureTable& textures, Scene& scene, const std::string& what) {
  const tinygltf::Value* ext = extension(m);
  if (!ext || !textured(*ext)) return;
  const SpecGloss s = factors(*ext);
  const uint32_t diffuse =
      textures.get(texture_reference(*ext, "diffuseTexture"), true, what + " diffuseTexture");
  const uint32_t spec_gloss = textures.get(texture_reference(*ext, "specularGlossinessTexture"),
                                           true, what + " specularGlossinessTexture");
  // The baked images take the size and sampling of the diffuse texture (else the other's).
  const uint32_t layout = diffuse != kNoTexture ? diffuse : spec_gloss;
  const Texture sampling = scene.textures[layout];
  const Image& shape = scene.images[sampling.image];
  Image base, metal_rough;
  base.name = shape.name + " (spec-gloss base colour)";
  metal_rough.name = shape.name + " (spec-gloss metal-rough)";
  for (Image* image : {&base, &metal_rough}) {
    image->width = shape.width;
    image->height = shape.height;
    image->rgba8.assign(size_t(shape.width) * shape.height * 4, 255);
  }
  for (uint32_t y = 0; y < shape.height; ++y)
    for (uint32_t x = 0; x < shape.width; ++x) {
      const float u = (float(x) + 0.5f) / float(shape.width);
      const float v = (float(y) + 0.5f) / float(shape.height);
      SpecGloss texel_values = s;
      if (diffuse != kNoTexture) {
        const glm::u8vec4 t = texel(scene.images[scene.textures[diffuse].image], u, v);
        texel_values.diffuse *=
            glm::vec4(to_linear(t.r), to_linear(t.g), to_linear(t.b), float(t.a) / 255.0f);
      }
      if (spec_gloss != kNoTexture) {
        const glm::u8vec4 t = texel(scene.images[scene.textures[spec_gloss].image], u, v);
        texel_values.specular *= glm::vec3(to_linear(t.r), to_linear(t.g), to_linear(t.b));
        texel_values.glossiness *= float(t.a) / 255.0f;
      }
      const MetalRough mr = convert(texel_values);
      uint8_t* b = &base.rgba8[(size_t(y) * shape.width + x) * 4];
      b[0] = to_srgb8(mr.base_color.r);
      b[1] = to_srgb8(mr.base_color.g);
      b[2] = to_srgb8(mr.base_color.b);
      b[3] = uint8_t(std::lround(std::clamp(texel_values.diffuse.a, 0.0f, 1.0f) * 255.0f));
      uint8_t* r = &metal_rough.rgba8[(size_t(y) * shape.width + x) * 4];
      r[0] = 0;
      r[1] = uint8_t(std::lround(mr.roughness * 255.0f));
      r[2] = uint8_t(std::lround(mr.metalness * 255.0f));
    }
  const auto add = [&](Image image, bool srgb) {
    image.revision = image_revision(image);
    scene.images.push_back(std::move(image));
    Texture t = sampling;
    t.name = scene.images.back().name;
    t.image = uint32_t(scene.images.size() - 1);
    t.flags = srgb ? (t.flags | kTextureSrgb) : (t.flags & ~kTextureSrgb);
    scene.textures.push_back(t);
    return uint32_t(scene.textures.size() - 1);
  };
  p.base_color_texture = add(std::move(base), true);
  p.metallic_roughness_texture = add(std::move(metal_rough), false);
}

}  // namespace hipr::gltf
