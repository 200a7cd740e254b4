#version 460
// HiPR stage 1, first part: the tile state a new edit starts from. Every tile's flags, weight
// and change score restart, except where an earlier edit made a tile active or discovered and
// the tile has not been re-rendered since (its pixels still owe the restart that edit asked
// for): such a tile still shows what an earlier scene looked like, so it keeps its rank (active,
// or discovered with its weight) whatever the new edit changes. Edits in a row (a drag) leave
// no tile behind. A plan for a new focus (no edit) keeps what the display knows of each tile
// (kTileShown, kTileSettled: they belong to the last edit). The focus score always restarts:
// mark_active.comp marks the focus anew at every plan.
// Reads: the accumulation (the owed bit of each tile's first pixel: tiles render whole),
// FrameParams. Writes: per tile the flags, weight, change and focus score stage 1 starts from.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "shared/bindings/visibility.h"
#include "common/dispatch.glsl"

layout(scalar, binding = kCarryAccumulation) readonly buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kCarryTileFlags) buffer TileFlags { uint b_tile_flags[]; };
layout(scalar, binding = kCarryTileWeights) buffer TileWeights { uint64_t b_tile_weights[]; };
layout(scalar, binding = kCarryTileChange) buffer TileChange { uint b_tile_change[]; };
layout(scalar, binding = kCarryTileFocus) writeonly buffer TileFocus { uint b_tile_focus[]; };
layout(push_constant) uniform Push { uint u_mode; };  // kCarryEdit, kCarryEverything or kCarryRefocus

void main() {
  const uint tile = dispatch_index();
  if (tile >= u_frame.tileCount) return;
  const uvec2 origin = tile_origin(tile);
  const bool owed = (b_accum[origin.y * u_frame.width + origin.x].count & kPixelOwed) != 0u;
  const uint ranked = b_tile_flags[tile] & (kTileActive | kTileDiscovered);
  const bool carried = owed && ranked != 0u;
  const uint everything = u_mode == kCarryEverything ? kTileActive : 0u;
  const uint kept = u_mode == kCarryRefocus ? b_tile_flags[tile] & (kTileShown | kTileSettled) : 0u;
  // A carried tile keeps its change score, so it stays a seed; its focus score restarts.
  const uint scored = carried && b_tile_change[tile] != 0u ? kTileScored : 0u;
  b_tile_flags[tile] = everything | kept | (carried ? ranked | scored : 0u);
  b_tile_focus[tile] = 0u;
  if (!carried) {
    b_tile_weights[tile] = 0ul;
    b_tile_change[tile] = 0u;
  }
}
