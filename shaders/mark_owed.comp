#version 460
// After an edit every pixel owes a restart: its next visit drops the old samples. Until then
// it keeps showing them (the stale but usually right radiance of the paper).
// Writes: the kPixelOwed bit of every pixel's sample count, and clears kTileShown and
//         kTileSettled of every tile (no tile shows a fresh estimate of the new scene yet).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "shared/bindings/film.h"
#include "common/dispatch.glsl"

layout(scalar, binding = kOwedAccumulation) buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kOwedTileFlags) buffer TileFlags { uint b_tile_flags[]; };

void main() {
  const uint index = dispatch_index();
  if (index < u_frame.tileCount) b_tile_flags[index] &= ~(kTileShown | kTileSettled);  // tiles never outnumber pixels
  if (index >= u_frame.width * u_frame.height) return;
  b_accum[index].count |= kPixelOwed;
}
