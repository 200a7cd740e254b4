// Set 0 of the viewer's overlay pass (OverlayPass: overlay.comp).
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_OVERLAY_H
#define HIPR_BINDINGS_OVERLAY_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kOverlayGBuffer = 0u;       // GBufferTexel per pixel: the surface seen now
HIPR_CONST uint kOverlayRecords = 1u;       // OverlayRecord per GeometryRecord
HIPR_CONST uint kOverlayTileWeights = 2u;   // uint64 per tile: stage 2's W(T) x kWeightScale
HIPR_CONST uint kOverlayTileFlags = 3u;     // uint per tile (kTileActive)
HIPR_CONST uint kOverlayAccumulation = 4u;  // PixelAccum per pixel (the owed bit of count)
HIPR_CONST uint kOverlayIdBytes = 5u;       // uint[256]: the sRGB byte of an id colour's channel k
HIPR_CONST uint kOverlayMaxWeight = 6u;     // uint64[1]: the largest tile weight (pass 0)
HIPR_CONST uint kOverlayOutput = 7u;        // uint RGBA8 per pixel (DisplayPass's overlay)

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
