#include "image/tonemap.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace hipr {
namespace shader {
using namespace glm;
#include "shaders/common/tone_mappers.glsl"
}  // namespace shader

namespace {

struct MapperName {
  ToneMapper mapper;
  const char* name;
};
constexpr MapperName kNames[] = {{ToneMapper::Clamp, "clamp"},
                                 {ToneMapper::PbrNeutral, "pbr-neutral"},
                                 {ToneMapper::Agx, "agx"},
                                 {ToneMapper::Aces, "aces"}};

static_assert(uint32_t(ToneMapper::Clamp) == shader::kToneClamp &&
                  uint32_t(ToneMapper::PbrNeutral) == shader::kTonePbrNeutral &&
                  uint32_t(ToneMapper::Agx) == shader::kToneAgx &&
                  uint32_t(ToneMapper::Aces) == shader::kToneAces,
              "ToneMapper follows the shaders' constants");

}  // namespace

ToneMapper parse_tone_mapper(const std::string& name) {
  for (const MapperName& entry : kNames)
    if (name == entry.name) return entry.mapper;
  throw InputError("unknown tone mapper '" + name + "' (use clamp, pbr-neutral, agx or aces)");
}

std::string tone_mapper_name(ToneMapper mapper) {
  for (const MapperName& entry : kNames)
    if (entry.mapper == mapper) return entry.name;
  throw InternalError("tone mapper without a name");
}

const std::vector<ToneMapper>& tone_mappers() {
  static const std::vector<ToneMapper> all = {ToneMapper::Clamp, ToneMapper::PbrNeutral,
                                              ToneMapper::Agx, ToneMapper::Aces};
  return all;
}

glm::vec3 tone_map(glm::vec3 exposed, ToneMapper mapper) {
  return shader::tone_map(exposed, uint32_t(mapper));
}

float srgb_encode(float x) {
  x = std::isfinite(x) ? std::clamp(x, 0.0f, 1.0f) : 0.0f;
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

std::vector<uint8_t> tonemap_srgb8(const std::vector<float>& rgb, const DisplayTransform& display) {
  const float scale = std::exp2(display.exposure_ev);
  std::vector<uint8_t> out(rgb.size());
  if (display.tone_mapper == ToneMapper::Clamp) {  // per channel, as it always was
    for (size_t i = 0; i < rgb.size(); ++i)
      out[i] = uint8_t(std::lround(srgb_encode(rgb[i] * scale) * 255.0f));
    return out;
  }
  for (size_t i = 0; i + 2 < rgb.size(); i += 3) {
    const glm::vec3 shown =
        tone_map(glm::vec3(rgb[i], rgb[i + 1], rgb[i + 2]) * scale, display.tone_mapper);
    for (int c = 0; c < 3; ++c)
      out[i + size_t(c)] = uint8_t(std::lround(srgb_encode(shown[c]) * 255.0f));
  }
  return out;
}

std::vector<uint8_t> tonemap_srgb8(const std::vector<float>& rgb, float exposure_ev) {
  return tonemap_srgb8(rgb, DisplayTransform{exposure_ev, ToneMapper::Clamp});
}

}  // namespace hipr
