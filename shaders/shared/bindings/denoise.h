// Set 0 of the display denoiser (DenoisePass: denoise_guides.comp, denoise_keys.comp,
// denoise_prepare.comp, denoise_atrous.comp, denoise_blend.comp, denoise_temporal.comp).
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernels' GLSL layouts and by their C++ pass.
#ifndef HIPR_BINDINGS_DENOISE_H
#define HIPR_BINDINGS_DENOISE_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kDenoiseGuides = 0u;        // DenoiseGuide per pixel (guides: written; else read)
HIPR_CONST uint kDenoiseDisplay = 1u;       // DisplayTexel per pixel: what the screen shows (read)
HIPR_CONST uint kDenoiseAccumulation = 2u;  // PixelAccum per pixel: the samples' variance (read)
HIPR_CONST uint kDenoiseKeys = 3u;          // uint per pixel: kDenoise* key (keys writes)
HIPR_CONST uint kDenoiseInput = 4u;         // vec4 per pixel: demodulated radiance, its variance
HIPR_CONST uint kDenoiseOutput = 5u;        // vec4 per pixel: the same after a pass
HIPR_CONST uint kDenoiseResult = 6u;        // vec3 per pixel: the denoised radiance shown (temporal writes)
HIPR_CONST uint kDenoiseSamples = 7u;       // uint per pixel: samples behind the value (prepare writes)
HIPR_CONST uint kDenoiseVariance = 8u;      // vec2 per pixel: the shown value's variance, demodulated and as radiance (prepare writes)
HIPR_CONST uint kDenoiseGeometry = 9u;      // uvec2 per pixel: a guide's normal and distance (guides write)
HIPR_CONST uint kDenoiseFrame = 10u;        // vec3 per pixel: this frame's filtered radiance (blend writes)
HIPR_CONST uint kDenoiseHistory = 11u;      // uvec2 per pixel: key and samples last shown (temporal)
HIPR_CONST uint kDenoiseShownNoise = 12u;   // 6 uints per pixel: a shown value's luminance bits, variance, samples; the noise prior (prepare)

// denoise_blend.comp's workgroup: a tile of pixels whose windows' sums are read from shared
// memory. 16 x 8 (and the windows' margin: 26 x 18 places of 28 bytes, 13 KB) keeps within what
// every Vulkan device allows (128 invocations, 16 KB of shared memory).
HIPR_CONST uint kDenoiseBlendTileWidth = 16u;
HIPR_CONST uint kDenoiseBlendTileHeight = 8u;

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
