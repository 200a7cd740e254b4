// What the display denoiser's kernels share: the guides' packing, luminance, and the buffers of
// set 0 (shared/bindings/denoise.h). The filter itself is denoise_atrous.comp.
#ifndef HIPR_DENOISE_GLSL
#define HIPR_DENOISE_GLSL

#include "shared/bindings/denoise.h"
#include "common/octahedral.glsl"

// The albedo radiance is divided by before filtering and multiplied by after: texture detail
// stays sharp. Floored so that a black surface's noise does not become huge illumination.
const float kDenoiseAlbedoFloor = 0.02;
vec3 unpack_albedo(uint packed) { return max(unpackUnorm4x8(packed).rgb, vec3(kDenoiseAlbedoFloor)); }

// The albedo's alpha says how many things the pixel's rays stop at (denoise_guides.comp): 1, one
// surface; 0, veiled (a stochastic, BLEND, surface lies in front of another or of the
// environment); kGuideOutline, an outline (the centre sees the environment, the footprint the
// guide's surface: veiled too, its value of both).
const float kGuideOutline = 0.25;
bool guide_veiled(DenoiseGuide guide) { return unpackUnorm4x8(guide.albedo).a < 0.5; }
bool guide_outline(DenoiseGuide guide) { return abs(unpackUnorm4x8(guide.albedo).a - kGuideOutline) < 0.125; }

vec3 unpack_emission(DenoiseGuide guide) {
  return vec3(unpackHalf2x16(guide.emissionRG), unpackHalf2x16(guide.emissionB).x);
}

// What the filter works on: the shown radiance less what the surface itself emits (texture
// detail of an emissive map is not noise), divided by the albedo.
vec3 demodulated(vec3 shown, DenoiseGuide guide) { return (shown - unpack_emission(guide)) / unpack_albedo(guide.albedo); }

// The inverse: the filtered value as radiance again.
vec3 remodulated(vec3 value, DenoiseGuide guide) { return max(value * unpack_albedo(guide.albedo) + unpack_emission(guide), vec3(0.0)); }

// A background pixel whose whole footprint sees the environment, as far as the guide's rays
// tell: the environment's mean there and the standard deviation of its luminance
// (denoise_guides.comp), where finite.
bool footprint_environment(DenoiseGuide guide, out vec3 radiance, out float deviation) {
  radiance = unpack_emission(guide);
  deviation = unpackHalf2x16(guide.emissionB).y;
  return guide.record == kInvalidIndex && deviation > 0.0 && !isinf(deviation) && !any(isinf(radiance)) &&
         !any(isnan(radiance));
}

// Whether two pixels' keys (denoise_prepare.comp) let them mix: the same surface, both beside an
// edge or both not, and values of the same scene state, where a value re-rendered without change
// (kDenoiseUnchanged) goes with either. A kept pixel mixes with none.
bool keys_mix(uint a, uint b) {
  if (((a | b) & kDenoiseKept) != 0u) return false;
  const uint state = kDenoiseCurrent | kDenoiseUnchanged;
  return a == b || (((a ^ b) & ~state) == 0u && ((a | b) & kDenoiseUnchanged) != 0u);
}

// Whether a pixel shows the scene since the last edit (always, without hipr's display state:
// DenoisePush::displayState 0).
bool shows_current(DisplayTexel texel, uint displayState) { return displayState == 0u || (texel.flags & kShownCurrent) != 0u; }

float denoise_luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

#endif
