// Set 0 of mark_owed.comp (Film::record_mark_all_owed) and of sum_samples.comp (Film::total_samples).
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_FILM_H
#define HIPR_BINDINGS_FILM_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kOwedAccumulation = 0u;  // PixelAccum per pixel: kPixelOwed is set here
HIPR_CONST uint kOwedTileFlags = 1u;     // uint per tile

HIPR_CONST uint kSumAccumulation = 0u;  // PixelAccum per pixel, read
HIPR_CONST uint kSumTotal = 1u;         // uint64: the sum of every pixel's sample count

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
