// Set 0 of the G-buffer pass (visibility.comp) and of HiPR stage 1 (ActiveTilesPass:
// carry_tiles.comp and mark_active.comp; LightReachPass: light_reach.comp; ReprojectPass:
// reproject_display.comp).
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_VISIBILITY_H
#define HIPR_BINDINGS_VISIBILITY_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

// visibility.comp
HIPR_CONST uint kVisibilityGBuffer = 0u;         // GBufferTexel per pixel (written)
// mark_active.comp
HIPR_CONST uint kMarkActiveGBuffer = 0u;         // GBufferTexel per pixel, this scene state
HIPR_CONST uint kMarkActivePrevious = 1u;        // GBufferTexel per pixel, before the edit
HIPR_CONST uint kMarkActiveChangedRecords = 2u;  // uint per GeometryRecord: kRecordChanged, focus weight
HIPR_CONST uint kMarkActiveTileFlags = 3u;       // uint per tile: kTileActive is set here
HIPR_CONST uint kMarkActiveTileChange = 4u;      // uint per tile: how much of it stage 1 saw change
HIPR_CONST uint kMarkActiveDisplay = 5u;         // DisplayTexel per pixel: which surface the screen shows
HIPR_CONST uint kMarkActiveFocusDiscs = 6u;      // FocusDisc[kMaxFocusDiscs]: screen discs of the focus
HIPR_CONST uint kMarkActiveTileFocus = 7u;       // uint per tile: summed focus weight of its pixels
HIPR_CONST uint kMarkActivePixelLead = 8u;       // one bit per pixel: it leads after the edit (set or cleared here)
// light_reach.comp
HIPR_CONST uint kReachGBuffer = 0u;     // GBufferTexel per pixel, this scene state
HIPR_CONST uint kReachLights = 1u;      // Light[2 x kMaxReachLights]: each changed light before, then after
HIPR_CONST uint kReachDisplay = 2u;     // DisplayTexel per pixel: what the screen shows now
HIPR_CONST uint kReachTileFlags = 3u;   // uint per tile: kTileActive | kTileScored are set here
HIPR_CONST uint kReachTileChange = 4u;  // uint per tile: the reached pixels' scores are added
// reproject_display.comp
HIPR_CONST uint kReprojectGBuffer = 0u;          // GBufferTexel per pixel, the new view
HIPR_CONST uint kReprojectPrevious = 1u;         // GBufferTexel per pixel, the view before
HIPR_CONST uint kReprojectPreviousDisplay = 2u;  // DisplayTexel per pixel: the display at the edit (a copy)
HIPR_CONST uint kReprojectDisplay = 3u;          // DisplayTexel per pixel: rewritten for the new view
// carry_tiles.comp
HIPR_CONST uint kCarryAccumulation = 0u;  // PixelAccum per pixel: the owed bit
HIPR_CONST uint kCarryTileFlags = 1u;     // uint per tile: rewritten for the new edit
HIPR_CONST uint kCarryTileWeights = 2u;   // uint64 per tile: kept where carried, else 0
HIPR_CONST uint kCarryTileChange = 3u;    // uint per tile: kept where carried, else 0
HIPR_CONST uint kCarryTileFocus = 4u;     // uint per tile: 0 (the focus is marked anew at every plan)
// carry_tiles.comp's push constant: what the new plan is for.
HIPR_CONST uint kCarryEdit = 0u;        // an edit stage 1 can localize
HIPR_CONST uint kCarryEverything = 1u;  // an edit no G-buffer localizes: every tile active
HIPR_CONST uint kCarryRefocus = 2u;     // no edit, a new focus: the display's tile state is kept

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
