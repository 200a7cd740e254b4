#version 460
// Decides what the screen shows, tile by tile, after a scheduling step or at an edit.
// Reads:  the tile list entries [listOffset, listOffset + tileCount) (filtered by tile flags;
//         listOffset kInvalidIndex: tiles 0 .. tileCount - 1 without the list), per-pixel
//         accumulation (sum, sum of squares, count + owed bit), the tiles' flags, the display
//         texels (stale and shown values, their records), the G-buffer (which surface each pixel
//         sees now), the difference records, FrameParams.
// Writes: the display texels of those tiles' pixels; in their tile flags kTileShown once a tile
//         shows its fresh estimate at weight 1/2 or more, kTileSettled once it shows it alone.
// Rules (ResolvePush::rule):
//  - capture (at an edit): what each pixel shows becomes its stale estimate; with difference
//    records, a pixel with samples since the last edit keeps them as the old scene's samples when
//    what it shows is of that scene (kShownCurrent), so stale estimate and kept samples are of
//    one scene state; a pixel without keeps the older pair it has.
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
//  - difference (docs/method.md#the-difference-estimate): blend, except for pixels whose n fresh
//    samples all have a kept sample of the scene the stale estimate is of (n <= valid): with
//    d_i = new_i - old_i (same random numbers),
//      C  = s + sum_i d_i / n           (unbiased: s and the kept samples estimate the old scene)
//      C' = C + a (f - C)               a per channel = -sum w d (old - s) / sum w (old - s)^2 over
//                                       the tile's changed pixels, clamped to [-1, 1]: how much
//                                       of the old samples' noise the new ones replaced (0: an
//                                       added change, C is best; 1: paths replaced, f is best; a
//                                       recolour by k: 1 - k); the mix with the least variance
//      X  = s + b (C' - s)              b = Bd / (Bd + Vd), Bd = max(Dd - Vd, 0) from Dd = sum
//                                       w (C' - s)^2 and Vd = sum w var(r) / n over the tile,
//                                       r_i = d_i + a (old_i - s) (C' - s is their mean)
//    and shows X. A pixel none of whose differences is non-zero has C = s; one whose weighted
//    sums reached half's range (a sample too bright to judge) keeps X = s. Past the kept samples,
//    and for pixels without (relit, never rendered, or showing an older scene at the capture),
//    blend.
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
layout(scalar, binding = kResolveDifference) buffer Difference { DifferenceRecord b_difference[]; };
layout(push_constant, scalar) uniform Push { ResolvePush u_push; };

#include "common/difference.glsl"

shared float s_fresh_error[64];  // V
shared float s_difference[64];   // D
shared uint s_unrendered[64];    // pixels without a fresh sample
shared uint s_single[64];        // pixels with one fresh sample (no variance yet)
shared uint s_short[64];         // pixels with fewer fresh samples than their stale estimate
shared uint s_resurfaced[64];    // rendered pixels whose surface changed since their stale estimate
shared uint s_judged[64];        // pixels D and V judge (blend's pixels)
shared uint s_differenced[64];   // difference rule: pixels shown by their difference estimate
shared vec3 s_cross[64];         // difference rule: sum of w d (old - s) over changed pixels
shared vec3 s_old[64];           // difference rule: sum of w (old - s)^2 over changed pixels
shared float s_alpha;            // weight of the fresh estimate in what the tile shows (blend's pixels)
shared vec3 s_regression;        // difference rule: the tile's weight a of f against C, per channel
shared float s_change[64];       // difference rule: Dd, sum of w (C' - s)^2
shared float s_change_noise[64]; // difference rule: Vd, sum of w var(r) / c
shared float s_shrink;           // difference rule: the tile's weight b of C' against s
shared bool s_settled;           // the tile shows f alone

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
    DisplayTexel texel = b_display[index];
    // A pixel without samples since the last edit keeps the older pair it has.
    uint valid = texel_valid(texel.flags);
    const PixelAccum accum = b_accum[index];
    if (has_fresh_samples(accum))
      valid = (texel.flags & kShownCurrent) != 0u ? min(accum.count & kPixelCountMask, kDifferenceSamples) : 0u;
    texel.stale = texel.shown;
    texel.staleSamples = texel.shownSamples;
    texel.staleRecord = texel.shownRecord;
    // The light groups of what was shown become those of the stale estimate (relight.comp);
    // what is shown is now of the scene before the edit.
    texel.flags = ((texel.flags & kShownGrouped) != 0u ? kShownGrouped | kStaleGrouped : 0u) |
                  ((u_push.difference != 0u ? valid : 0u) << kDifferenceValidShift);
    b_display[index] = texel;
  }
}

// How many of the pixel's samples have a difference: all n while n <= the kept samples; 0 (no
// difference estimate: blend judges the pixel) without kept samples or past them.
uint differenced_samples(DisplayTexel texel, uint n) {
  return u_push.rule == kDisplayDifference && n <= texel_valid(texel.flags) ? n : 0u;
}

// The difference estimate C of a pixel with c differenced samples.
vec3 difference_estimate(DifferenceRecord record, vec3 stale, uint c) {
  return stale + record_vec3(record, kDifferenceSumHalf) / float(c);
}

// Var(sum_i r_i / c), r_i = d_i + a (old_i - s), weighted as relMSE weighs errors, from the
// record's sums and C' - s = sum_i r_i / c (c >= 2; with one difference the square of r, which
// bounds it from above).
float corrected_noise(DifferenceRecord record, vec3 shift, vec3 stale, uint c, vec3 a) {
  const float squares = record_squares(record) + 2.0 * dot(a, record_sums(record, kDifferenceCrossHalf)) +
                        dot(a * a, record_sums(record, kDifferenceOldHalf));
  if (c < 2u) return max(squares, 0.0);
  return max(squares - float(c) * dot(relmse_weight(stale), shift * shift), 0.0) / float((c - 1u) * c);
}

// C' = C + a (f - C) of a changed pixel with c differenced samples (all of its samples).
vec3 corrected_estimate(DifferenceRecord record, vec3 stale, vec3 fresh, uint c) {
  const vec3 estimate = difference_estimate(record, stale, c);
  return estimate + s_regression * (fresh - estimate);
}

// X = s + b (C' - s) (s itself where no difference is non-zero, or one is too bright to judge).
vec3 difference_display(DifferenceRecord record, vec3 stale, vec3 fresh, uint c) {
  if (!record_judges(record) || s_shrink == 0.0) return stale;
  return max(stale + s_shrink * (corrected_estimate(record, stale, fresh, c) - stale), vec3(0.0));
}

// Samples behind the mix (1 - a) C + a f, as if the two were independent (a count for the
// next edit's settling and noise terms), within [min(n, stale count), stale count].
uint mixed_samples(float a, uint n, uint staleSamples) {
  const float variance = (1.0 - a) * (1.0 - a) / float(max(staleSamples, 1u)) + a * a / float(n);
  const float samples = variance > 0.0 ? 1.0 / variance : float(staleSamples);
  return clamp(uint(samples), min(n, staleSamples), max(staleSamples, 1u));
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

// Difference rule, once the tile's regression weight is known: Dd and Vd over the changed pixels
// shown by their difference estimate, and from them the tile's weight b of C' against s.
void judge_change(uvec2 origin, uint tilePixels) {
  const uint lane = gl_LocalInvocationIndex;
  float change = 0.0, noise = 0.0;
  for (uint local = lane; local < tilePixels; local += gl_WorkGroupSize.x) {
    const uint index = tile_pixel_index(origin, local);
    if (index == kInvalidIndex) continue;
    const PixelAccum accum = b_accum[index];
    if (!has_fresh_samples(accum)) continue;
    const uint n = accum.count & kPixelCountMask;
    const DisplayTexel texel = b_display[index];
    const uint c = differenced_samples(texel, n);
    if (c == 0u || resurfaced(index, texel)) continue;
    const DifferenceRecord record = b_difference[index];
    if (!record_judges(record)) continue;
    const vec3 shift = corrected_estimate(record, texel.stale, accum.sum / float(n), c) - texel.stale;
    change += dot(relmse_weight(texel.stale), shift * shift);
    noise += corrected_noise(record, shift, texel.stale, c, s_regression);
  }
  s_change[lane] = change;
  s_change_noise[lane] = noise;
  barrier();
  for (uint stride = gl_WorkGroupSize.x / 2u; stride > 0u; stride /= 2u) {
    if (lane < stride) {
      s_change[lane] += s_change[lane + stride];
      s_change_noise[lane] += s_change_noise[lane + stride];
    }
    barrier();
  }
  if (lane == 0u) {
    const float dd = s_change[0], vd = s_change_noise[0];
    const float bd = max(dd - vd, 0.0);
    // Sums out of float's range cannot judge noise: the change shows, as blend shows f then.
    s_shrink = isinf(dd) || isnan(dd) || isinf(vd) || isnan(vd) ? 1.0 : (bd > 0.0 ? bd / (bd + vd) : 0.0);
  }
  barrier();
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
  vec3 cross = vec3(0.0), spread = vec3(0.0);
  uint unrendered = 0u, single = 0u, shortOfStale = 0u, resurfacedPixels = 0u, judged = 0u, differenced = 0u;
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
    if (differenced_samples(texel, n) > 0u) {
      const DifferenceRecord record = b_difference[index];
      differenced += 1u;
      if (record_judges(record)) {
        cross += record_sums(record, kDifferenceCrossHalf);
        spread += record_sums(record, kDifferenceOldHalf);
      }
      continue;
    }
    judged += 1u;
    if (n < 2u) {
      single += 1u;
      continue;
    }
    const vec3 mean = accum.sum / float(n);
    const vec3 variance = max(accum.sumSquares - float(n) * mean * mean, vec3(0.0)) / float(n - 1u);
    const vec3 weight = relmse_weight(texel.stale);
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
  s_judged[lane] = judged;
  s_differenced[lane] = differenced;
  s_cross[lane] = cross;
  s_old[lane] = spread;
  barrier();
  for (uint stride = gl_WorkGroupSize.x / 2u; stride > 0u; stride /= 2u) {
    if (lane < stride) {
      s_fresh_error[lane] += s_fresh_error[lane + stride];
      s_difference[lane] += s_difference[lane + stride];
      s_unrendered[lane] += s_unrendered[lane + stride];
      s_single[lane] += s_single[lane + stride];
      s_short[lane] += s_short[lane + stride];
      s_resurfaced[lane] += s_resurfaced[lane + stride];
      s_judged[lane] += s_judged[lane + stride];
      s_differenced[lane] += s_differenced[lane + stride];
      s_cross[lane] += s_cross[lane + stride];
      s_old[lane] += s_old[lane + stride];
    }
    barrier();
  }
  if (lane == 0u) {
    const float alpha = tile_alpha(flags);
    // Pixels shown by their difference estimate show the edited scene: they count as shown, and
    // settle when every pixel caught up in samples.
    const bool differenced = s_differenced[0] > 0u;
    const bool settled = alpha == 1.0 && (!differenced || s_short[0] == 0u || (flags & kTileSettled) != 0u);
    // Immediate shows pixel by pixel: the tile counts once all its pixels are fresh. A tile
    // where a moved surface appeared counts as shown: the change is on screen.
    if (s_unrendered[0] == 0u && (alpha >= 0.5 || s_resurfaced[0] > 0u || (differenced && s_judged[0] == 0u)))
      b_tile_flags[tile] = flags | kTileShown | (settled ? kTileSettled : 0u);
    s_alpha = settled ? 1.0 : alpha;
    s_settled = settled;
    // Per channel (a recolour scales each channel's paths by its own factor k: a = 1 - k).
    const vec3 cross = s_cross[0], spread = s_old[0];
    s_regression = mix(vec3(0.0), clamp(-cross / max(spread, vec3(1e-30)), -1.0, 1.0), greaterThan(spread, vec3(0.0)));
  }
  barrier();
  if (s_differenced[0] > 0u) judge_change(origin, tilePixels);
  const float tileAlpha = s_alpha;
  const bool tileSettled = s_settled;
  if (tileAlpha == 0.0 && s_resurfaced[0] == 0u && s_differenced[0] == 0u) return;
  for (uint local = lane; local < tilePixels; local += gl_WorkGroupSize.x) {
    const uint index = tile_pixel_index(origin, local);
    if (index == kInvalidIndex) continue;
    const PixelAccum accum = b_accum[index];
    if (!has_fresh_samples(accum)) continue;
    const uint n = accum.count & kPixelCountMask;
    const vec3 fresh = accum.sum / float(n);
    DisplayTexel texel = b_display[index];
    const bool surfaceChanged = resurfaced(index, texel);
    const uint c = differenced_samples(texel, n);
    if (!tileSettled && !surfaceChanged && c > 0u) {
      const DifferenceRecord record = b_difference[index];
      // An unchanged pixel: C = s exactly, shown as it is; so is one with a sample too bright to judge.
      const bool changed = record_judges(record);
      texel.shown = difference_display(record, texel.stale, fresh, c);
      const float a = changed ? s_shrink * (s_regression.x + s_regression.y + s_regression.z) / 3.0 : 0.0;
      texel.shownSamples = mixed_samples(a, n, texel.staleSamples);
      texel.shownRecord = current_record(index);
      texel.flags = (texel.flags & ~kShownGrouped) | kShownCurrent;
      b_display[index] = texel;
      continue;
    }
    const float alpha = surfaceChanged ? 1.0 : tileAlpha;
    texel.flags &= ~kShownGrouped;  // what is shown now is not the stale estimate alone
    if (alpha == 1.0) {
      texel.shown = fresh;
      texel.shownSamples = n;
      texel.shownRecord = current_record(index);
      texel.flags |= kShownCurrent;
    } else if (alpha > 0.0) {
      texel.shown = mix(texel.stale, fresh, alpha);
      texel.shownSamples = texel.staleSamples;
      texel.shownRecord = texel.staleRecord;
      // Of the edited scene when the stale estimate is (relit).
      texel.flags = (texel.flags & kStaleCurrent) != 0u ? texel.flags | kShownCurrent : texel.flags & ~kShownCurrent;
    }
    b_display[index] = texel;
  }
}
