#pragma once
#include <cstdint>
#include <vector>

namespace hipr {

// Linear radiance -> 8-bit sRGB: exposure (in stops), clamp to [0,1], sRGB transfer curve.
// A plain clamp keeps regression images exact for LDR scenes; no filmic curve is applied.
std::vector<uint8_t> tonemap_srgb8(const std::vector<float>& rgb, float exposure_ev);
float srgb_encode(float linear);

}  // namespace hipr
