#version 460
// Sums the film's sample counts over all pixels into one 64-bit total, so that the viewer's mean
// samples per pixel reads 8 bytes back instead of every pixel's accumulation (28 bytes each:
// 58 MB at 1920x1080, once a second).
// Reads: every pixel's sample count (not its owed bit). Adds to: the total (cleared before).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require

layout(local_size_x = 64) in;

#include "shared/bindings/film.h"
#include "common/dispatch.glsl"

layout(push_constant) uniform Push { uint pixelCount; } u_push;
layout(scalar, binding = kSumAccumulation) readonly buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kSumTotal) buffer Total { uint64_t b_total; };

// A workgroup's sum: 64 counts of at most 2^24 samples (--spp's limit) fit 32 bits.
shared uint s_sum;

void main() {
  if (gl_LocalInvocationIndex == 0u) s_sum = 0u;
  barrier();
  const uint index = dispatch_index();
  if (index < u_push.pixelCount) atomicAdd(s_sum, b_accum[index].count & kPixelCountMask);
  barrier();
  if (gl_LocalInvocationIndex == 0u && s_sum != 0u) atomicAdd(b_total, uint64_t(s_sum));
}
