#version 460
// Decides what the screen shows, tile by tile, after a scheduling step or at an edit.
// Reads:  the tile list entries [listOffset, listOffset + tileCount) (filtered by tile flags;
//         listOffset kInvalidIndex: tiles 0 .. tileCount - 1 without the list), per-pixel
//         accumulation (sum, sum of squares, count + owed bit), the tiles' flags, the display
//         texels (stale and shown values, their records), the G-buffer (which surface each pixel
//         sees now), FrameParams.
// Writes: the display texels of those tiles' pixels; in their tile flags kTileShown once a tile
//         shows its fresh estimate at weight 1/2 or more, kTileSettled once it shows it alone.
// Rules (ResolvePush::rule):
//  - capture (at an edit): what each pixel shows becomes its stale estimate.
//  - immediate: a pixel shows its fresh mean as soon as it has a sample since the last edit.
//  - switch / blend: per tile, with weights w = 1 / (s^2 + 0.01) as relMSE weighs errors
//    (s = stale value, per channel):
//      V = sum w var (1/n - 1/n_s)  (the noise of f - s: f, the fresh mean of n samples, and s,
//                                   the stale one of n_s, share the random numbers of their
//                                   first n samples where paths miss the change)
//      D = sum w (f - s)^2          (E[D] = V + B, B = the stale estimate's squared bias)
//    so B is estimated by max(D - V, 0). `switch` shows f once D > threshold * V (f is then
//    expected closer to the truth: threshold 2 means V < B). `blend` shows s + a (f - s) with
//    a = B / (B + V), the mix with the least expected error (ghosts of large changes fade at
//    once, small changes fade in as their samples grow). Variances need two samples per pixel.
//    A pixel whose visible surface is not the one its stale estimate depicts (the G-buffer's
//    record differs: an object moved in or out, in this edit or an earlier one) shows f at once:
//    its stale value is of the wrong surface. Such pixels stay out of the tile's D and V, which
//    then judge the tile's other pixels.
//    A tile whose pixels all have as many fresh samples as their stale estimate shows f alone
//    under every rule: f is then at least as good, and this is what makes every schedule end on
//    the unbiased image. A tile that shows f alone stays so until the next edit (no flicker).
//    (Before the first edit there is no stale estimate: the scheduler resolves with immediate.)
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;  // == kWorkgroupSize; one workgroup per tile

#include "common/frame.glsl"
#include "shared/bindings/resolve.h"
#include "common/dispatch.glsl"

layout(scalar, binding = kResolveTileList) readonly buffer TileList { uint b_tiles[]; };
layout(scalar, binding = kResolveAccumulation) readonly buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kResolveTileFlags) buffer TileFlags { uint b_tile_flags[]; };
layout(scalar, binding = kResolveDisplay) buffer Display { DisplayTexel b_display[]; };
layout(scalar, binding = kResolveGBuffer) readonly buffer GBuffer { GBufferTexel b_gbuffer[]; };
layout(push_constant, scalar) uniform Push { ResolvePush u_push; };

shared float s_fresh_error[64];  // V
shared float s_difference[64];   // D
shared uint s_unrendered[64];    // pixels without a fresh sample
shared uint s_single[64];        // pixels with one fresh sample (no variance yet)
shared uint s_short[64];         // pixels with fewer fresh samples than their stale estimate
shared uint s_resurfaced[64];    // rendered pixels whose surface changed since their stale estimate
shared float s_alpha;            // weight of the fresh estimate in what the tile shows

uvec2 tile_origin(uint tile) { return uvec2(tile % u_frame.tilesX, tile / u_frame.tilesX) * u_frame.tileSize; }

// Pixel index of the tile's local-th pixel, or kInvalidIndex outside the image.
uint tile_pixel_index(uvec2 origin, uint local) {
  const uvec2 pixel = origin + uvec2(local % u_frame.tileSize, local / u_frame.tileSize);
  return pixel.x < u_frame.width && pixel.y < u_frame.height ? pixel.y * u_frame.width + pixel.x : kInvalidIndex;
}

// The surface the pixel shows now (kRecordUnknown without a current G-buffer).
uint current_record(uint index) { return u_push.useGBuffer != 0u ? b_gbuffer[index].record : kRecordUnknown; }

// The pixel's stale estimate depicts another surface than the pixel shows now.
bool resurfaced(uint index, DisplayTexel texel) {
  return texel.staleRecord != kRecordUnknown && u_push.useGBuffer != 0u && texel.staleRecord != b_gbuffer[index].record;
}

bool has_fresh_samples(PixelAccum accum) { return (accum.count & kPixelOwed) == 0u && (accum.count & kPixelCountMask) > 0u; }

void capture(uvec2 origin, uint tilePixels) {
  for (uint local = gl_LocalInvocationIndex; local < tilePixels; local += gl_WorkGroupSize.x) {
    const uint index = tile_pixel_index(origin, local);
    if (index == kInvalidIndex) continue;
    b_display[index].stale = b_display[index].shown;
    b_display[index].staleSamples = b_display[index].shownSamples;
    b_display[index].staleRecord = b_display[index].shownRecord;
    // The light groups of what was shown become those of the stale estimate (relight.comp).
    b_display[index].grouped = (b_display[index].grouped & kShownGrouped) != 0u ? kShownGrouped | kStaleGrouped : 0u;
  }
}

// The fresh estimate's weight for the tile (lane 0 decides after the reduction).
float tile_alpha(uint flags) {
  if (u_push.rule == kDisplayImmediate || (flags & kTileSettled) != 0u) return 1.0;
  if (s_unrendered[0] != 0u) return 0.0;
  if (s_short[0] == 0u) return 1.0;
  if (s_single[0] != 0u) return 0.0;
  const float v = s_fresh_error[0], d = s_difference[0];
  // Sums that overflowed (radiance near float's range) cannot judge noise: the fresh estimate
  // is the one that converges, so it shows, as it would without a display rule.
  if (isinf(v) || isnan(v) || isinf(d) || isnan(d)) return 1.0;
  if (u_push.rule == kDisplaySwitch) return d > u_push.threshold * v ? 1.0 : 0.0;
  const float b = max(d - v, 0.0);
  return b > 0.0 ? b / (b + v) : 0.0;
}

void main() {
  const uint group = dispatch_group();
  if (group >= u_push.tileCount) return;
  const uint tile = u_push.listOffset == kInvalidIndex ? group : b_tiles[u_push.listOffset + group];
  const uint flags = b_tile_flags[tile];
  // Uniform per workgroup: every invocation leaves together, before any barrier.
  if ((flags & u_push.requireFlags) != u_push.requireFlags || (flags & u_push.skipFlags) != 0u) return;
  const uvec2 origin = tile_origin(tile);
  const uint tilePixels = u_frame.tileSize * u_frame.tileSize;
  if (u_push.rule == kDisplayCapture) {
    capture(origin, tilePixels);
    return;
  }

  const uint lane = gl_LocalInvocationIndex;
  float freshError = 0.0, difference = 0.0;
  uint unrendered = 0u, single = 0u, shortOfStale = 0u, resurfacedPixels = 0u;
  for (uint local = lane; local < tilePixels; local += gl_WorkGroupSize.x) {
    const uint index = tile_pixel_index(origin, local);
    if (index == kInvalidIndex) continue;
    const PixelAccum accum = b_accum[index];
    if (!has_fresh_samples(accum)) {
      unrendered += 1u;
      continue;
    }
    const uint n = accum.count & kPixelCountMask;
    const DisplayTexel texel = b_display[index];
    if (resurfaced(index, texel)) {
      resurfacedPixels += 1u;
      continue;
    }
    if (n < texel.staleSamples) shortOfStale += 1u;
    if (n < 2u) {
      single += 1u;
      continue;
    }
    const vec3 mean = accum.sum / float(n);
    const vec3 variance = max(accum.sumSquares - float(n) * mean * mean, vec3(0.0)) / float(n - 1u);
    const vec3 weight = 1.0 / (texel.stale * texel.stale + 0.01);
    // Var(f - s) with shared random streams: sample i of a pixel draws the same random numbers
    // before and after an edit, so where paths miss the change f and s share their first n
    // samples' noise and Var(f - s) = var (1/n - 1/n_stale) (no stale count known: 1/n).
    const float staleShare = texel.staleSamples > n ? 1.0 / float(texel.staleSamples) : 0.0;
    freshError += dot(weight, variance) * (1.0 / float(n) - staleShare);
    const vec3 d = mean - texel.stale;
    difference += dot(weight, d * d);
  }
  s_fresh_error[lane] = freshError;
  s_difference[lane] = difference;
  s_unrendered[lane] = unrendered;
  s_single[lane] = single;
  s_short[lane] = shortOfStale;
  s_resurfaced[lane] = resurfacedPixels;
  barrier();
  for (uint stride = gl_WorkGroupSize.x / 2u; stride > 0u; stride /= 2u) {
    if (lane < stride) {
      s_fresh_error[lane] += s_fresh_error[lane + stride];
      s_difference[lane] += s_difference[lane + stride];
      s_unrendered[lane] += s_unrendered[lane + stride];
      s_single[lane] += s_single[lane + stride];
      s_short[lane] += s_short[lane + stride];
      s_resurfaced[lane] += s_resurfaced[lane + stride];
    }
    barrier();
  }
  if (lane == 0u) {
    const float alpha = tile_alpha(flags);
    // Immediate shows pixel by pixel: the tile counts once all its pixels are fresh. A tile
    // where a moved surface appeared counts as shown: the change is on screen.
    if (s_unrendered[0] == 0u && (alpha >= 0.5 || s_resurfaced[0] > 0u))
      b_tile_flags[tile] = flags | kTileShown | (alpha == 1.0 ? kTileSettled : 0u);
    s_alpha = alpha;
  }
  barrier();
  const float tileAlpha = s_alpha;
  if (tileAlpha == 0.0 && s_resurfaced[0] == 0u) return;
  for (uint local = lane; local < tilePixels; local += gl_WorkGroupSize.x) {
    const uint index = tile_pixel_index(origin, local);
    if (index == kInvalidIndex) continue;
    const PixelAccum accum = b_accum[index];
    if (!has_fresh_samples(accum)) continue;
    const uint n = accum.count & kPixelCountMask;
    const vec3 fresh = accum.sum / float(n);
    DisplayTexel texel = b_display[index];
    const float alpha = resurfaced(index, texel) ? 1.0 : tileAlpha;
    texel.grouped &= ~kShownGrouped;  // what is shown now is not the stale estimate alone
    if (alpha == 1.0) {
      texel.shown = fresh;
      texel.shownSamples = n;
      texel.shownRecord = current_record(index);
    } else if (alpha > 0.0) {
      texel.shown = mix(texel.stale, fresh, alpha);
      texel.shownSamples = texel.staleSamples;
      texel.shownRecord = texel.staleRecord;
    }
    b_display[index] = texel;
  }
}
