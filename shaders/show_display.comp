#version 460
// Writes what the screen shows at the pixels of the tiles resolve_display.comp just judged and
// of the tiles around them whose pixels' windows reach into them (all marked kTileReshow there):
// by the tile's gate and, where the display rule weighs, by the rule's sums over the 9 x 9
// pixels around each pixel (kDisplayWindowRadius), not over its tile, so that no tile grid shows.
// The rules: resolve_display.comp.
// Dispatch: per schedule entry as resolve_display.comp, times the (2 reach + 1)^2 tiles around
// it (show_reach); workgroup g shows neighbour g % that of entry g / that, if it is the first to
// clear the tile's kTileReshow (each tile once).
// Reads:  the tile list, tile flags, judgements, per-pixel accumulation, display texels, the
//         G-buffer, the difference records, FrameParams.
// Writes: the display texels of the marked tiles' pixels; clears their kTileReshow.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;  // == kWorkgroupSize; one workgroup per (entry, neighbour)

#include "common/frame.glsl"
#include "common/display_resolve.glsl"
#include "common/dispatch.glsl"

// A tile is shown in blocks of kBlock x kBlock pixels (one per invocation); each block first
// gathers the rule's terms of its pixels and of the window radius around them into shared memory.
const uint kBlock = 8u;
const uint kRegion = kBlock + 2u * kDisplayWindowRadius;  // the block with its windows' margins
shared bool s_owner;                            // this workgroup cleared the tile's kTileReshow
shared vec2 s_blend[kRegion * kRegion];         // blend pixels: w (f - s)^2, its noise
shared vec2 s_change[kRegion * kRegion];        // changed difference pixels: w (C' - s)^2, its noise

uint tile_of(uvec2 pixel) { return (pixel.y / u_frame.tileSize) * u_frame.tilesX + pixel.x / u_frame.tileSize; }

// The rule's terms of the pixel at `at` (zero where it takes no part: outside the image, no
// fresh sample, a changed surface, one fresh sample, an unchanged or too bright difference pixel),
// as resolve_display.comp sums them over a tile; difference terms with the regression weight of
// the pixel's own tile.
void gather(uint slot, ivec2 at) {
  vec2 blend = vec2(0.0), change = vec2(0.0);
  if (at.x >= 0 && at.y >= 0 && at.x < int(u_frame.width) && at.y < int(u_frame.height)) {
    const uint index = uint(at.y) * u_frame.width + uint(at.x);
    const PixelAccum accum = b_accum[index];
    if (has_fresh_samples(accum)) {
      const uint n = accum.count & kPixelCountMask;
      const DisplayTexel texel = b_display[index];
      if (!resurfaced(index, texel)) {
        const uint c = differenced_samples(texel, n);
        if (c > 0u) {
          const DifferenceRecord record = b_difference[index];
          if (record_judges(record))
            change = change_terms(record, texel, accum.sum / float(n), c, b_judgements[tile_of(uvec2(at))].regression);
        } else if (n >= 2u) {
          blend = blend_terms(accum, n, texel);
        }
      }
    }
  }
  s_blend[slot] = blend;
  s_change[slot] = change;
}

// The sums over the window around the block's pixel `local` (in block coordinates), each pixel
// weighted by a tent, (r + 1 - |dx|) (r + 1 - |dy|): the pixels nearest count most, so a window
// straddling the edge of a change leans to the pixel's own side, and its effective size
// (sum k)^2 / sum k^2 is 54 pixels for r = 4, about a tile's 64.
vec2 window_sum(uvec2 local, bool change) {
  const int r = int(kDisplayWindowRadius);
  vec2 sum = vec2(0.0);
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const uint slot = (local.y + uint(dy + r)) * kRegion + local.x + uint(dx + r);
      const float weight = float((r + 1 - abs(dx)) * (r + 1 - abs(dy)));
      sum += weight * (change ? s_change[slot] : s_blend[slot]);
    }
  return sum;
}

// The fresh estimate's weight at a blend pixel of a tile in `state`.
float pixel_alpha(uint state, uvec2 local) {
  if (state == kJudgeStale) return 0.0;
  if (state != kJudgeWeighed) return 1.0;
  const vec2 sums = window_sum(local, false);  // D, V
  if (u_push.rule == kDisplaySwitch) return sums_overflowed(sums.x, sums.y) || sums.x > u_push.threshold * sums.y ? 1.0 : 0.0;
  return change_weight(sums.x, sums.y);
}

// Samples behind the mix (1 - a) C + a f, as if the two were independent (a count for the
// next edit's settling and noise terms), within [min(n, stale count), stale count].
uint mixed_samples(float a, uint n, uint staleSamples) {
  const float variance = (1.0 - a) * (1.0 - a) / float(max(staleSamples, 1u)) + a * a / float(n);
  const float samples = variance > 0.0 ? 1.0 / variance : float(staleSamples);
  return clamp(uint(samples), min(n, staleSamples), max(staleSamples, 1u));
}

// Difference rule: a changed pixel shows X = s + b (C' - s), C' = C + a (f - C), a its tile's
// regression weight, b judged over its window; an unchanged one (C = s exactly) or one with a
// sample too bright to judge shows s.
void show_difference(inout DisplayTexel texel, uint index, uvec2 local, vec3 regression, vec3 fresh, uint n, uint c) {
  const DifferenceRecord record = b_difference[index];
  float shrink = 0.0;
  if (record_judges(record)) {
    const vec2 sums = window_sum(local, true);  // Dd, Vd
    shrink = change_weight(sums.x, sums.y);
  }
  texel.shown = shrink == 0.0 ? texel.stale
                              : max(texel.stale + shrink * (corrected_estimate(record, texel.stale, fresh, c, regression) - texel.stale), vec3(0.0));
  texel.shownSamples = mixed_samples(shrink * (regression.x + regression.y + regression.z) / 3.0, n, texel.staleSamples);
  texel.shownRecord = current_record(index);
  texel.flags = (texel.flags & ~kShownGrouped) | kShownCurrent;
}

void show_pixel(uint index, uvec2 local, TileJudgement judgement) {
  const PixelAccum accum = b_accum[index];
  if (!has_fresh_samples(accum)) return;
  const uint n = accum.count & kPixelCountMask;
  const vec3 fresh = accum.sum / float(n);
  DisplayTexel texel = b_display[index];
  const bool surfaceChanged = resurfaced(index, texel);
  const uint c = differenced_samples(texel, n);
  if (judgement.state != kJudgeSettled && !surfaceChanged && c > 0u) {
    show_difference(texel, index, local, judgement.regression, fresh, n, c);
    b_display[index] = texel;
    return;
  }
  const float alpha = surfaceChanged ? 1.0 : pixel_alpha(judgement.state, local);
  if (alpha == 0.0) return;  // the pixel keeps what it shows
  texel.flags &= ~kShownGrouped;  // what is shown now is not the stale estimate alone
  if (alpha == 1.0) {
    texel.shown = fresh;
    texel.shownSamples = n;
    texel.shownRecord = current_record(index);
    texel.flags |= kShownCurrent;
  } else {
    texel.shown = mix(texel.stale, fresh, alpha);
    texel.shownSamples = texel.staleSamples;
    texel.shownRecord = texel.staleRecord;
    // Of the edited scene when the stale estimate is (relit).
    texel.flags = (texel.flags & kStaleCurrent) != 0u ? texel.flags | kShownCurrent : texel.flags & ~kShownCurrent;
  }
  b_display[index] = texel;
}

void main() {
  const uint reach = show_reach(u_push.rule), side = 2u * reach + 1u;
  const uint group = dispatch_group();
  const uint entry = group / (side * side);
  if (entry >= u_push.tileCount) return;
  const uint centre = u_push.listOffset == kInvalidIndex ? entry : b_tiles[u_push.listOffset + entry];
  const uint k = group % (side * side);
  const ivec2 at = ivec2(centre % u_frame.tilesX, centre / u_frame.tilesX) + ivec2(k % side, k / side) - int(reach);
  // Uniform per workgroup, as are s_owner and the judgement after the barrier.
  if (at.x < 0 || at.y < 0 || at.x >= int(u_frame.tilesX) || at.y >= int(u_frame.tilesY)) return;
  const uint tile = uint(at.y) * u_frame.tilesX + uint(at.x);
  const uint lane = gl_LocalInvocationIndex;
  if (lane == 0u) s_owner = (atomicAnd(b_tile_flags[tile], ~kTileReshow) & kTileReshow) != 0u;
  barrier();
  if (!s_owner) return;
  const TileJudgement judgement = b_judgements[tile];
  if (judgement.state == kJudgeNone) return;

  const uvec2 origin = tile_origin(tile);
  const uvec2 tileEnd = min(origin + u_frame.tileSize, uvec2(u_frame.width, u_frame.height));
  // Settled and stale-gated tiles need no window (their blend pixels show f or keep s); the
  // difference rule's pixels need one unless the tile is settled.
  const bool windows = judgement.state == kJudgeWeighed || (u_push.rule == kDisplayDifference && judgement.state != kJudgeSettled);
  const uint blocks = (u_frame.tileSize + kBlock - 1u) / kBlock;
  for (uint block = 0u; block < blocks * blocks; ++block) {
    const uvec2 blockOrigin = origin + uvec2(block % blocks, block / blocks) * kBlock;
    if (windows) {
      barrier();  // the previous block is done with the shared terms
      for (uint slot = lane; slot < kRegion * kRegion; slot += gl_WorkGroupSize.x)
        gather(slot, ivec2(blockOrigin) + ivec2(slot % kRegion, slot / kRegion) - int(kDisplayWindowRadius));
      barrier();
    }
    const uvec2 local = uvec2(lane % kBlock, lane / kBlock);
    const uvec2 pixel = blockOrigin + local;
    if (all(lessThan(pixel, tileEnd))) show_pixel(pixel.y * u_frame.width + pixel.x, local, judgement);
  }
}
