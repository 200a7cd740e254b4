#version 460
// HiPR stage 1, second half: a tile is active when a changed element is visible in it now or
// was before the edit (pixels an object left changed too).
// Reads: both G-buffers, the changed-record flags. Writes: kTileActive into the tile flags.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "shared/abi.h"

layout(scalar, binding = kBindingFrame) readonly buffer Frame { FrameParams u_frame; };
layout(scalar, binding = kBindingGBuffer) readonly buffer GBuffer { GBufferTexel b_gbuffer[]; };
layout(scalar, binding = kBindingPreviousGBuffer) readonly buffer Previous { GBufferTexel b_previous[]; };
layout(scalar, binding = kBindingChangedRecords) readonly buffer Changed { uint b_changed_records[]; };
layout(scalar, binding = kBindingTileFlags) buffer TileFlags { uint b_tile_flags[]; };

bool changed(uint record) { return record != kInvalidIndex && b_changed_records[record] != 0u; }

void main() {
  const uint index = gl_GlobalInvocationID.x;
  if (index >= u_frame.width * u_frame.height) return;
  if (!changed(b_gbuffer[index].record) && !changed(b_previous[index].record)) return;
  const uvec2 pixel = uvec2(index % u_frame.width, index / u_frame.width);
  atomicOr(b_tile_flags[(pixel.y / u_frame.tileSize) * u_frame.tilesX + pixel.x / u_frame.tileSize], kTileActive);
}
