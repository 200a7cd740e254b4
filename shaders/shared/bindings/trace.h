// Set 0 of trace_tiles.comp: TracePass, and with discovery on HiPR stage 2's DiscoveryPass.
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_TRACE_H
#define HIPR_BINDINGS_TRACE_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kTraceTileList = 0u;        // uint tile ids, in the order to render them
HIPR_CONST uint kTraceAccumulation = 1u;    // PixelAccum per pixel
HIPR_CONST uint kTraceStats = 2u;           // RenderStats
HIPR_CONST uint kTraceTileFlags = 3u;       // uint per tile: kTile* flags
HIPR_CONST uint kTraceTileBackground = 4u;  // uint per tile: 1 = its camera rays cannot hit anything
HIPR_CONST uint kTraceGroupSums = 8u;       // vec3 per pixel and light group: the groups' share of `sum`
HIPR_CONST uint kTraceMaterialGroups = 9u;  // uint per material: its emission's light group, or kInvalidIndex
HIPR_CONST uint kTraceDifference = 10u;     // DifferenceRecord per pixel (HIPR_DIFFERENCE 1)
HIPR_CONST uint kTraceDisplay = 11u;        // DisplayTexel per pixel, read: the stale estimate (HIPR_DIFFERENCE 1)
HIPR_CONST uint kTracePixelLead = 12u;      // one bit per pixel (row-major, 32 per uint): it leads after the edit
// Stage 2 only (HIPR_DISCOVERY 1, common/discovery.glsl)
HIPR_CONST uint kTraceGBuffer = 5u;         // GBufferTexel per pixel of the edited scene
HIPR_CONST uint kTraceChangedRecords = 6u;  // uint per GeometryRecord: 1 = in the changed set E
HIPR_CONST uint kTraceTileWeights = 7u;     // uint64 per tile: discovery weight W(T) x kWeightScale

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
