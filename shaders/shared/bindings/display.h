// Set 0 of the viewer's display pass (DisplayPass: display.comp).
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_DISPLAY_H
#define HIPR_BINDINGS_DISPLAY_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kDisplayTexels = 0u;    // per rendered pixel, DisplayPush::sourceStride floats whose first
                                        // three are the radiance: the resolve's display (DisplayTexel,
                                        // `shown` first) or the denoiser's result (vec3)
HIPR_CONST uint kDisplayOverlay = 1u;   // uint RGBA8 per rendered pixel (sRGB, A = coverage)
HIPR_CONST uint kDisplayOutput = 2u;    // uint RGBA8 per window pixel (what the window shows)

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
