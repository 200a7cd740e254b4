#version 460
// Writes what the screen shows at the pixels of the tiles resolve_display.comp just judged and
// of the tiles around them whose pixels' windows reach into them (all marked kTileReshow there):
// by the tile's gate and, where the display rule weighs, by the rule's sums over the 9 x 9
// pixels around each pixel (kDisplayWindowRadius), not over its tile, so that no tile grid shows.
// The rules: resolve_display.comp.
// Dispatch: per schedule entry as resolve_display.comp, times the (2 reach + 1)^2 tiles around
// it (ResolvePush::showReach); workgroup g shows neighbour g % that of entry g / that, if it is the first to
// clear the tile's kTileReshow (each tile once).
// Reads:  the tile list, tile flags, judgements, per-pixel accumulation, display texels, the
//         G-buffer, the difference records, FrameParams.
// Writes: the display texels of the marked tiles' pixels that a tile judged by this resolve
//         (TileJudgement::epoch) lies within the window radius of; clears kTileReshow.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;  // == kWorkgroupSize; one workgroup per (entry, neighbour)

#include "common/frame.glsl"
#include "common/display_resolve.glsl"
#include "common/dispatch.glsl"

// A tile is shown in blocks of kBlock x kBlock pixels (one per invocation); each block first
// gathers the rule's terms of its pixels and of the window radius around them into shared memory,
// then sums each pixel's window in two passes (the tent is separable).
const uint kBlock = 8u;
const uint kRegion = kBlock + 2u * kDisplayWindowRadius;  // the block with its windows' margins
shared bool s_owner;                      // this workgroup cleared the tile's kTileReshow
shared vec4 s_terms[kRegion * kRegion];   // per pixel: blend's w (f - s)^2 and its noise, the
                                          // difference rule's w (C' - s)^2 and its noise
shared vec2 s_screen[kRegion * kRegion];  // per pixel: the two noises as the screen shows them
shared vec4 s_rows[kRegion * kBlock];     // the terms summed along rows, by the tent
shared vec2 s_screen_rows[kRegion * kBlock];

// The rule's terms of the pixel at `at` (zero where it takes no part: outside the image, no
// fresh sample, a changed surface, a relit value, one fresh sample, an unchanged or too bright
// difference pixel),
// as resolve_display.comp sums them over a tile; difference terms with the regression weight
// fitted on the pixel's own tile without it (held_out_regression). `screen`: the two noise
// terms as the screen shows them, times the share the display denoiser left of the pixel's
// noise when it last filtered it (DisplayTexel::screenNoise; 1 unfiltered since the edit). The
// raw noise estimates the change's squared bias (D - V), the screen's weighs it: a fresh
// estimate the screen shows filtered errs by far less than its raw noise, and weighed by that
// the rules kept the old value (a moved block's old shadow) where the filtered new one was
// closer. (Taking the screen's noise out of D too showed noise as change where nothing
// changed. The tiles' own gates, resolve_display.comp, keep the raw noise.)
vec4 gather(ivec2 at, out vec2 screen) {
  screen = vec2(0.0);
  if (at.x < 0 || at.y < 0 || at.x >= int(u_frame.width) || at.y >= int(u_frame.height)) return vec4(0.0);
  const uint index = uint(at.y) * u_frame.width + uint(at.x);
  const PixelAccum accum = b_accum[index];
  if (!has_fresh_samples(accum)) return vec4(0.0);
  const uint n = accum.count & kPixelCountMask;
  const DisplayTexel texel = b_display[index];
  if (resurfaced(index, texel) || keeps_current_stale(texel, n)) return vec4(0.0);
  const uint c = differenced_samples(texel, n);
  if (c == 0u) {
    if (n < 2u) return vec4(0.0);
    const vec2 terms = blend_terms(accum, n, texel);
    screen.x = terms.y * texel.screenNoise;
    return vec4(terms, 0.0, 0.0);
  }
  const DifferenceRecord record = b_difference[index];
  if (!record_judges(record)) return vec4(0.0);
  const vec2 terms = change_terms(record, texel, accum.sum / float(n), c, held_out_regression(b_judgements[tile_of_pixel(uvec2(at))], record));
  screen.y = terms.y * texel.screenNoise;
  return vec4(0.0, 0.0, terms);
}

// The tent's weight at an offset d along one axis, r + 1 - |d|: the pixels nearest count most,
// so a window straddling the edge of a change leans to the pixel's own side; the window's
// effective size (sum k)^2 / sum k^2 is 54 pixels for r = 4, about a tile's 64.
float tent(int d) { return float(int(kDisplayWindowRadius) + 1 - abs(d)); }

// Fills s_terms for the block at `blockOrigin`, then s_rows; the caller reads the columns.
void gather_block(uvec2 blockOrigin) {
  const uint lane = gl_LocalInvocationIndex;
  const int r = int(kDisplayWindowRadius);
  for (uint slot = lane; slot < kRegion * kRegion; slot += gl_WorkGroupSize.x) {
    vec2 screen;
    s_terms[slot] = gather(ivec2(blockOrigin) + ivec2(slot % kRegion, slot / kRegion) - r, screen);
    s_screen[slot] = screen;
  }
  barrier();
  for (uint slot = lane; slot < kRegion * kBlock; slot += gl_WorkGroupSize.x) {
    const uint row = slot / kBlock, x = slot % kBlock;
    vec4 sum = vec4(0.0);
    vec2 screen = vec2(0.0);
    for (int dx = -r; dx <= r; ++dx) {
      const uint at = row * kRegion + x + uint(dx + r);
      sum += tent(dx) * s_terms[at];
      screen += tent(dx) * s_screen[at];
    }
    s_rows[slot] = sum;
    s_screen_rows[slot] = screen;
  }
  barrier();
}

// The tent-weighted sums over the window around the block's pixel `local`: blend's D and V
// (xy), the difference rule's Dd and Vd (zw); in `screen` blend's and the difference rule's
// noise as the screen shows it.
vec4 window_sums(uvec2 local, out vec2 screen) {
  const int r = int(kDisplayWindowRadius);
  vec4 sum = vec4(0.0);
  screen = vec2(0.0);
  for (int dy = -r; dy <= r; ++dy) {
    const uint at = (local.y + uint(dy + r)) * kBlock + local.x;
    sum += tent(dy) * s_rows[at];
    screen += tent(dy) * s_screen_rows[at];
  }
  return sum;
}

// The fresh estimate's weight at a blend pixel of a tile in `state`, its window's D and V in
// `sums`, V as the screen shows it in `screenV`.
float pixel_alpha(uint state, vec2 sums, float screenV) {
  if (state == kJudgeStale) return 0.0;
  if (state != kJudgeWeighed) return 1.0;
  if (u_push.rule == kDisplaySwitch) return sums_overflowed(sums.x, sums.y) || sums.x > u_push.threshold * sums.y ? 1.0 : 0.0;
  return change_weight_on_screen(sums.x, sums.y, screenV);
}

// Samples behind the mix (1 - a) C + a f, as if the two were independent (a count for the
// next edit's settling and noise terms), within [min(n, stale count), stale count].
uint mixed_samples(float a, uint n, uint staleSamples) {
  const float variance = (1.0 - a) * (1.0 - a) / float(max(staleSamples, 1u)) + a * a / float(n);
  const float samples = variance > 0.0 ? 1.0 / variance : float(staleSamples);
  return clamp(uint(samples), min(n, staleSamples), max(staleSamples, 1u));
}

// Difference rule: a changed pixel shows X = s + b (C' - s), C' = C + a (f - C), a fitted on its
// tile's other changed pixels, b judged over its window (Dd, Vd in `sums`); an unchanged one (C = s
// exactly) or one with a sample too bright to judge shows s.
void show_difference(inout DisplayTexel texel, uint index, vec2 sums, float screenV, TileJudgement judgement, vec3 fresh, uint n, uint c) {
  const DifferenceRecord record = b_difference[index];
  const vec3 regression = held_out_regression(judgement, record);
  const float shrink = record_judges(record) ? change_weight_on_screen(sums.x, sums.y, screenV) : 0.0;
  texel.shown = shrink == 0.0 ? texel.stale
                              : max(texel.stale + shrink * (corrected_estimate(record, texel.stale, fresh, c, regression) - texel.stale), vec3(0.0));
  texel.shownSamples = mixed_samples(shrink * (regression.x + regression.y + regression.z) / 3.0, n, texel.staleSamples);
  texel.shownRecord = current_record(index);
  texel.shownNormal = current_normal(index);
  texel.flags = (texel.flags & ~kShownGrouped) | kShownCurrent;
}

// Samples behind the blend (1 - a) s + a f of n fresh samples, 1 / its variance in units of one
// sample's, as if s and f were independent (where they share random numbers and paths they vary
// together, and the mix somewhat more), within [min(n, stale count), stale count]. The denoiser scales the pixel's sample
// variance by it. Counted as the stale estimate's samples, a moved block's new shadow, blended
// at a near 1 from 9 fresh samples, passed for a 64-sample value and kept its speckle.
uint blended_samples(float a, uint n, uint staleSamples) {
  const float variance = (1.0 - a) * (1.0 - a) / float(max(staleSamples, 1u)) + a * a / float(n);
  const float samples = variance > 0.0 ? 1.0 / variance : float(staleSamples);
  return clamp(uint(min(samples, float(max(staleSamples, 1u)))), min(n, staleSamples), max(staleSamples, 1u));
}

// `sums`, `screen`: the window's sums (window_sums), where the tile needs them.
void show_pixel(uint index, vec4 sums, vec2 screen, TileJudgement judgement) {
  const PixelAccum accum = b_accum[index];
  if (!has_fresh_samples(accum)) return;
  const uint n = accum.count & kPixelCountMask;
  const vec3 fresh = accum.sum / float(n);
  DisplayTexel texel = b_display[index];
  const bool surfaceChanged = resurfaced(index, texel);
  // A relit value stays as it is (and with it its light groups: a slider dragged further relights
  // it again).
  if (!surfaceChanged && keeps_current_stale(texel, n)) return;
  const uint c = differenced_samples(texel, n);
  if (judgement.state != kJudgeSettled && !surfaceChanged && c > 0u) {
    show_difference(texel, index, sums.zw, screen.y, judgement, fresh, n, c);
    b_display[index] = texel;
    return;
  }
  const float alpha = surfaceChanged ? 1.0 : pixel_alpha(judgement.state, sums.xy, screen.x);
  if (alpha == 0.0) return;  // the pixel keeps what it shows
  texel.flags &= ~kShownGrouped;  // what is shown now is not the stale estimate alone
  if (alpha == 1.0) {
    texel.shown = fresh;
    texel.shownSamples = n;
    texel.shownRecord = current_record(index);
    texel.shownNormal = current_normal(index);
    texel.flags |= kShownCurrent;
  } else {
    texel.shown = mix(texel.stale, fresh, alpha);
    texel.shownSamples = blended_samples(alpha, n, texel.staleSamples);
    texel.shownRecord = texel.staleRecord;
    texel.shownNormal = texel.staleNormal;
    // Of the edited scene when the stale estimate is (relit).
    texel.flags = (texel.flags & kStaleCurrent) != 0u ? texel.flags | kShownCurrent : texel.flags & ~kShownCurrent;
  }
  b_display[index] = texel;
}

// Whether a tile this resolve judged lies within the window radius of the pixels [lo, hi): only
// then can what they show have changed (their own tile's gate and regression, or the terms of a
// pixel in their windows).
bool reached(uvec2 lo, uvec2 hi) {
  const ivec2 first = max(ivec2(lo) - int(kDisplayWindowRadius), ivec2(0)) / int(u_frame.tileSize);
  const ivec2 last = min(ivec2(hi) - 1 + int(kDisplayWindowRadius), ivec2(u_frame.width, u_frame.height) - 1) / int(u_frame.tileSize);
  for (int y = first.y; y <= last.y; ++y)
    for (int x = first.x; x <= last.x; ++x)
      if (b_judgements[uint(y) * u_frame.tilesX + uint(x)].epoch == u_push.epoch) return true;
  return false;
}

void main() {
  const uint reach = u_push.showReach, side = 2u * reach + 1u;
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
    if (any(greaterThanEqual(blockOrigin, tileEnd)) || !reached(blockOrigin, min(blockOrigin + kBlock, tileEnd))) continue;
    if (windows) gather_block(blockOrigin);
    const uvec2 local = uvec2(lane % kBlock, lane / kBlock);
    const uvec2 pixel = blockOrigin + local;
    if (all(lessThan(pixel, tileEnd))) {
      vec2 screen = vec2(0.0);
      const vec4 sums = windows ? window_sums(local, screen) : vec4(0.0);
      show_pixel(pixel.y * u_frame.width + pixel.x, sums, screen, judgement);
    }
    barrier();  // the next block's gather overwrites what this one's pixels read
  }
}
