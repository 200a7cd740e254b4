#pragma once
// Linear radiance -> what a screen or a PNG shows: exposure (in stops), a tone mapper
// (shaders/common/tone_mappers.glsl, the very code the viewer's display pass runs), the sRGB
// transfer curve, 8 bits. EXR output stays linear radiance and never passes through here.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace hipr {

// In the order of the shaders' kTone* constants.
enum class ToneMapper : uint32_t {
  Clamp,       // the default of every command: LDR regression images stay exact
  PbrNeutral,  // Khronos PBR Neutral: glTF base colours as authored, highlights rolled off
  Agx,         // AgX (Blender's default view transform since 4.0), Wrensch's fit
  Aces,        // ACES RRT + sRGB ODT, Hill's fit
};

// "clamp", "pbr-neutral", "agx", "aces"; parse throws InputError naming the choices.
ToneMapper parse_tone_mapper(const std::string& name);
std::string tone_mapper_name(ToneMapper mapper);
const std::vector<ToneMapper>& tone_mappers();

struct DisplayTransform {
  float exposure_ev = 0.0f;
  ToneMapper tone_mapper = ToneMapper::Clamp;
};

// One exposed linear colour -> linear display values in [0, 1] (non-finite or negative
// channels count as 0).
glm::vec3 tone_map(glm::vec3 exposed, ToneMapper mapper);

std::vector<uint8_t> tonemap_srgb8(const std::vector<float>& rgb, const DisplayTransform& display);
// Exposure and clamp (the default transform).
std::vector<uint8_t> tonemap_srgb8(const std::vector<float>& rgb, float exposure_ev);
float srgb_encode(float linear);

}  // namespace hipr
