// Maps a 1D dispatch over tiles x pixels to a pixel. Shared by every per-tile kernel.
#ifndef HIPR_TILE_PIXELS_GLSL
#define HIPR_TILE_PIXELS_GLSL

#include "common/dispatch.glsl"

// llvmpipe hands each thread a contiguous range of workgroups: scattering them (stride
// coprime to the group count) gives every thread a share of the expensive tiles.
// Returns false for invocations outside the tile or the image.
bool tile_pixel(uint listOffset, uint tileCount, uint tileStride, uint groupsPerTile, uint requireFlags,
                uint skipFlags, out uvec2 pixel) {
  const uint totalGroups = tileCount * groupsPerTile;
  if (dispatch_group() >= totalGroups) return false;  // past the tiles, in a folded dispatch
  const uint group = uint((uint64_t(dispatch_group()) * uint64_t(tileStride)) % uint64_t(totalGroups));
  const uint listIndex = group / groupsPerTile;
  const uint local = (group % groupsPerTile) * gl_WorkGroupSize.x + gl_LocalInvocationIndex;
  const uint tileSize = u_frame.tileSize;
  if (local >= tileSize * tileSize) return false;
  const uint tile = b_tiles[listOffset + listIndex];
  const uint flags = b_tile_flags[tile];
  if ((flags & requireFlags) != requireFlags || (flags & skipFlags) != 0u) return false;
  pixel = tile_origin(tile) + uvec2(local % tileSize, local / tileSize);
  return pixel.x < u_frame.width && pixel.y < u_frame.height;
}

#endif
