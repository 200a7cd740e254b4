// Set 0 of the display resolve (ResolvePass: resolve_display.comp judges tiles, show_display.comp
// writes their pixels).
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_RESOLVE_H
#define HIPR_BINDINGS_RESOLVE_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kResolveTileList = 0u;      // uint tile ids (the schedule)
HIPR_CONST uint kResolveAccumulation = 1u;  // PixelAccum per pixel (read)
HIPR_CONST uint kResolveTileFlags = 2u;     // uint per tile: kTileShown and kTileSettled are set here
HIPR_CONST uint kResolveDisplay = 3u;       // DisplayTexel per pixel: what the screen shows
HIPR_CONST uint kResolveGBuffer = 4u;       // GBufferTexel per pixel: which surface a pixel shows
HIPR_CONST uint kResolveDifference = 5u;    // DifferenceRecord per pixel (read)
HIPR_CONST uint kResolveJudgements = 6u;    // TileJudgement per tile: written by the judging kernel, read by the showing one

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
