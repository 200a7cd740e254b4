#version 460
// Judges, tile by tile, what the screen shows after a scheduling step, or captures at an edit;
// show_display.comp then writes the pixels of the judged tiles and of their neighbours.
// Reads:  the tile list entries [listOffset, listOffset + tileCount) (filtered by tile flags;
//         listOffset kInvalidIndex: tiles 0 .. tileCount - 1 without the list), per-pixel
//         accumulation (sum, sum of squares, count + owed bit), the tiles' flags, the display
//         texels (stale and shown values, their records), the G-buffer (which surface each pixel
//         sees now), the difference records, FrameParams.
// Writes: each tile's TileJudgement (its gate and regression sums; the capture clears it); in
//         the tile flags kTileShown once the tile's own measure shows its fresh estimate at
//         weight 1/2 or more, kTileSettled once it shows it alone, and kTileReshow on the tile
//         and (but for immediate) the tiles around it whose pixels' windows reach into it
//         (ResolvePush::showReach); at a capture the display texels.
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
//    A relit pixel (kStaleCurrent: its stale estimate is already the edited scene's, converged)
//    keeps it until its fresh samples are as many, under every rule but immediate, and judges
//    nothing meanwhile (keeps_current_stale).
//  - difference (docs/method.md#the-difference-estimate): blend, except for pixels whose n fresh
//    samples all have a kept sample of the scene the stale estimate is of (n <= valid): with
//    d_i = new_i - old_i (same random numbers),
//      C  = s + sum_i d_i / n           (unbiased: s and the kept samples estimate the old scene)
//      C' = C + a (f - C)               a per channel = -sum w d (old - s) / sum w (old - s)^2 over
//                                       the tile's other changed pixels (held out: the pixel's
//                                       own samples do not fit it), clamped to [-7, 1]: how much
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
// Weights per pixel: the tile's own sums decide its flags (shown, settled), its gate and its
// regression sums, but the weights that mix what a pixel shows (blend's a, switch's choice,
// the difference rule's b) are judged from the same terms summed over the 9 x 9 pixels around it
// (kDisplayWindowRadius; show_display.comp). A weight that jumps from tile to tile drew the tile
// grid on screen (8-pixel blocks of old shadow beside new); a window that moves with the pixel
// has no grid, and ends where the change ends, not at a tile's edge. (Interpolating the tiles'
// weights or sums between their centres was tried: a noisy unchanged tile then held back the
// change beside it.)
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;  // == kWorkgroupSize; one workgroup per tile

#include "common/frame.glsl"
#include "common/display_resolve.glsl"
#include "common/dispatch.glsl"

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
    texel.staleNormal = texel.shownNormal;
    texel.screenNoise = 1.0;  // what the filter left of the old image's noise says nothing of the new one's
    // The light groups of what was shown become those of the stale estimate (relight.comp);
    // what is shown is now of the scene before the edit.
    texel.flags = ((texel.flags & kShownGrouped) != 0u ? kShownGrouped | kStaleGrouped : 0u) |
                  ((u_push.difference != 0u ? valid : 0u) << kDifferenceValidShift);
    b_display[index] = texel;
  }
}

// The fresh estimate's weight for the tile by its own sums (lane 0 decides after the reduction).
float tile_alpha(uint flags) {
  if (u_push.rule == kDisplayImmediate || (flags & kTileSettled) != 0u) return 1.0;
  if (s_unrendered[0] != 0u) return 0.0;
  if (s_short[0] == 0u) return 1.0;
  if (s_single[0] != 0u) return 0.0;
  const float v = s_fresh_error[0], d = s_difference[0];
  if (sums_overflowed(d, v)) return 1.0;
  if (u_push.rule == kDisplaySwitch) return d > u_push.threshold * v ? 1.0 : 0.0;
  return change_weight(d, v);
}

// The tile's gate for its blend pixels (kJudge*): the rule's weights decide only while every
// pixel has the samples to judge and some pixel is short of its stale estimate's.
uint tile_state(float alpha, bool settled) {
  if (settled) return kJudgeSettled;
  if (alpha == 1.0) return kJudgeFresh;
  if (s_unrendered[0] != 0u || s_single[0] != 0u) return kJudgeStale;
  return kJudgeWeighed;
}

// The tile and the tiles with a pixel whose window reaches into it are shown again (only the
// tile for immediate, which shows each pixel by itself).
void mark_reshow(uint tile) {
  const int reach = int(u_push.showReach);
  const ivec2 at = ivec2(tile % u_frame.tilesX, tile / u_frame.tilesX);
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx) {
      const ivec2 n = at + ivec2(dx, dy);
      if (n.x >= 0 && n.y >= 0 && n.x < int(u_frame.tilesX) && n.y < int(u_frame.tilesY))
        atomicOr(b_tile_flags[uint(n.y) * u_frame.tilesX + uint(n.x)], kTileReshow);
    }
}

void main() {
  const uint group = dispatch_group();
  if (group >= u_push.tileCount) return;
  const uint tile = u_push.listOffset == kInvalidIndex ? group : b_tiles[u_push.listOffset + group];
  // Neighbours may set kTileReshow meanwhile; the other bits are this tile's alone here.
  const uint flags = b_tile_flags[tile] & ~kTileReshow;
  // Uniform per workgroup: every invocation leaves together, before any barrier.
  if ((flags & u_push.requireFlags) != u_push.requireFlags || (flags & u_push.skipFlags) != 0u) return;
  const uvec2 origin = tile_origin(tile);
  const uint tilePixels = u_frame.tileSize * u_frame.tileSize;
  if (u_push.rule == kDisplayCapture) {
    capture(origin, tilePixels);
    if (gl_LocalInvocationIndex == 0u) b_judgements[tile] = TileJudgement(vec3(0.0), vec3(0.0), kJudgeNone, 0u);
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
    if (keeps_current_stale(texel, n)) continue;  // relit: shown as it is, judges nothing
    if (differenced_samples(texel, n) > 0u) {
      const DifferenceRecord record = b_difference[index];
      differenced += 1u;
      if (record_judges(record)) {
        cross += record_sums(record, kDifferenceCross);
        spread += record_sums(record, kDifferenceOld);
      }
      continue;
    }
    judged += 1u;
    if (n < 2u) {
      single += 1u;
      continue;
    }
    const vec2 terms = blend_terms(accum, n, texel);
    difference += terms.x;
    freshError += terms.y;
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
  if (lane != 0u) return;
  const bool anyDifferenced = s_differenced[0] > 0u;
  const float alpha = tile_alpha(flags);
  // Pixels shown by their difference estimate show the edited scene: they count as shown, and
  // settle when every pixel caught up in samples.
  const bool settled = alpha == 1.0 && (!anyDifferenced || s_short[0] == 0u || (flags & kTileSettled) != 0u);
  // Immediate shows pixel by pixel: the tile counts once all its pixels are fresh. A tile
  // where a moved surface appeared counts as shown: the change is on screen.
  if (s_unrendered[0] == 0u && (alpha >= 0.5 || s_resurfaced[0] > 0u || (anyDifferenced && s_judged[0] == 0u)))
    atomicOr(b_tile_flags[tile], kTileShown | (settled ? kTileSettled : 0u));
  b_judgements[tile] = TileJudgement(s_cross[0], s_old[0], tile_state(alpha, settled), u_push.epoch);
  mark_reshow(tile);
}
