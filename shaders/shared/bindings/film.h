// Set 0 of mark_owed.comp (Film::record_mark_all_owed), sum_samples.comp (Film::total_samples) and
// film_noise.comp (Film::noise).
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

HIPR_CONST uint kNoiseAccumulation = 0u;  // PixelAccum per pixel, read
HIPR_CONST uint kNoisePartials = 1u;      // NoisePartial per workgroup, written

// One workgroup's share of the film's noise estimate (film_noise.comp), summed on the host in
// workgroup order so that the estimate of an image is the same on every run.
struct NoisePartial {
  float relmse;  // the sum of its pixels' expected relMSE terms (summed over RGB, halved)
  uint unknown;  // its pixels whose noise cannot be told: owed, or fewer than two samples
};

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
