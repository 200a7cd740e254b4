// Set 0 of HiPR stage 3 (SchedulePass): schedule_keys.comp and radix_sort.comp.
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_SCHEDULE_H
#define HIPR_BINDINGS_SCHEDULE_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

// schedule_keys.comp
HIPR_CONST uint kKeysTileFlags = 0u;    // uint per tile: kTileActive | kTileDiscovered
HIPR_CONST uint kKeysTileWeights = 1u;  // uint64 per tile: discovery weight x kWeightScale
HIPR_CONST uint kKeysRowDistance = 2u;  // uint per tile: columns to the nearest seed tile in its row
HIPR_CONST uint kKeysTileChange = 3u;   // uint per tile: stage 1's change score
HIPR_CONST uint kKeysSortKeys = 4u;     // uint keys (the sort's ping buffer)
HIPR_CONST uint kKeysSortValues = 5u;   // uint values: tile ids
HIPR_CONST uint kKeysTileFocus = 6u;    // uint per tile: stage 1's focus score
// radix_sort.comp (RadixSorter)
HIPR_CONST uint kSortKeys = 0u;         // uint keys, ping
HIPR_CONST uint kSortValues = 1u;       // uint values, ping
HIPR_CONST uint kSortKeysAlt = 2u;      // pong
HIPR_CONST uint kSortValuesAlt = 3u;    // pong
HIPR_CONST uint kSortHistogram = 4u;    // uint [digit][workgroup] counts, then offsets

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
