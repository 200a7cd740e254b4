// Set 0 of relight.comp (RelightPass).
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_RELIGHT_H
#define HIPR_BINDINGS_RELIGHT_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kRelightAccumulation = 0u;  // PixelAccum per pixel (read)
HIPR_CONST uint kRelightGroupSums = 1u;     // vec3 per pixel and light group (read)
HIPR_CONST uint kRelightDisplay = 2u;       // DisplayTexel per pixel
HIPR_CONST uint kRelightStaleGroups = 3u;   // vec3 per pixel and light group: the parts of `stale`

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
