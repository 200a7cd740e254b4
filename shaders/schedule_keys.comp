#version 460
// HiPR stage 3 sort keys: one 32-bit key per tile, so one ascending radix sort yields the
// whole schedule. Class 0, the active tiles: first those the edit changed, by descending
// stage-1 change score; then focus tiles (docs/method.md#focus) by descending focus score;
// then the rest of the active set (an edit that activates every tile) by distance from the
// seeds, and after a reprojection last of all those whose pixels barely moved (kTileReprojected
// without kTileMoved: what they show is nearly theirs already). Class 1: discovered tiles by
// descending weight W(T). Class 2: the other tiles by distance from the seeds. The seeds are the
// active tiles with a change or focus score; with none (a camera edit and no focus) distances
// are all equal. Ties keep tile-id order because the sort is stable and values start in id
// order.
// Pass 0 (u_pass == 0): per tile, columns to the nearest seed tile in its row.
// Pass 1: keys from flags, scores, weights and the 2D distance (min over rows).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "shared/bindings/schedule.h"
#include "common/dispatch.glsl"

layout(push_constant) uniform Push { uint u_pass; };
layout(scalar, binding = kKeysTileFlags) readonly buffer TileFlags { uint b_tile_flags[]; };
layout(scalar, binding = kKeysTileWeights) readonly buffer TileWeights { uint64_t b_tile_weights[]; };
layout(scalar, binding = kKeysRowDistance) buffer RowDistance { uint b_row_distance[]; };
layout(scalar, binding = kKeysTileChange) readonly buffer TileChange { uint b_tile_change[]; };
layout(scalar, binding = kKeysSortKeys) writeonly buffer Keys { uint b_keys[]; };
layout(scalar, binding = kKeysSortValues) writeonly buffer Values { uint b_values[]; };
layout(scalar, binding = kKeysTileFocus) readonly buffer TileFocus { uint b_tile_focus[]; };

const uint kNone = 0xffffu;

bool seed(uint tile) { return (b_tile_flags[tile] & (kTileActive | kTileScored)) == (kTileActive | kTileScored); }

// Squared distance in tiles to the nearest seed; 0x0fffffff when there is none.
uint seed_distance(uint x, uint y) {
  uint best = 0x0fffffffu;
  for (uint row = 0u; row < u_frame.tilesY; ++row) {
    const uint dx = b_row_distance[row * u_frame.tilesX + x];
    if (dx == kNone) continue;
    const uint dy = uint(abs(int(row) - int(y)));
    best = min(best, dx * dx + dy * dy);
  }
  return best;
}

void main() {
  const uint tile = dispatch_index();
  if (tile >= u_frame.tileCount) return;
  const uint x = tile % u_frame.tilesX;
  const uint y = tile / u_frame.tilesX;
  if (u_pass == 0u) {
    uint best = kNone;
    for (uint i = 0u; i < u_frame.tilesX; ++i)
      if (seed(y * u_frame.tilesX + i)) best = min(best, uint(abs(int(i) - int(x))));
    b_row_distance[tile] = best;
    return;
  }
  const uint flags = b_tile_flags[tile];
  uint key;
  if ((flags & kTileActive) != 0u) {
    if (b_tile_change[tile] != 0u) key = 0x1fffffffu - min(b_tile_change[tile], 0x1fffffffu);
    else if (b_tile_focus[tile] != 0u) key = 0x20000000u | (0x0fffffffu - min(b_tile_focus[tile], 0x0fffffffu));
    else {
      const bool still = (flags & (kTileReprojected | kTileMoved)) == kTileReprojected;
      key = 0x30000000u | (still ? 0x08000000u : 0u) | min(seed_distance(x, y), 0x07ffffffu);
    }
  } else if (b_tile_weights[tile] > 0ul) {
    // Positive float bits order like the numbers; drop one mantissa bit to fit 30 bits.
    const uint bits = floatBitsToUint(float(b_tile_weights[tile]) / kWeightScale) >> 1u;
    key = (1u << 30u) | (0x3fffffffu - min(bits, 0x3fffffffu));
  } else {
    key = (2u << 30u) | seed_distance(x, y);  // no seed at all: all equal, tile-id order
  }
  b_keys[tile] = key;
  b_values[tile] = tile;
}
