// The display resolve's buffers and what both of its kernels read of them: resolve_display.comp
// judges tiles (captures at an edit), show_display.comp writes their pixels.
#ifndef HIPR_COMMON_DISPLAY_RESOLVE_GLSL
#define HIPR_COMMON_DISPLAY_RESOLVE_GLSL

#include "shared/bindings/resolve.h"

layout(scalar, binding = kResolveTileList) readonly buffer TileList { uint b_tiles[]; };
layout(scalar, binding = kResolveAccumulation) readonly buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kResolveTileFlags) buffer TileFlags { uint b_tile_flags[]; };
layout(scalar, binding = kResolveDisplay) buffer Display { DisplayTexel b_display[]; };
layout(scalar, binding = kResolveGBuffer) readonly buffer GBuffer { GBufferTexel b_gbuffer[]; };
layout(scalar, binding = kResolveDifference) buffer Difference { DifferenceRecord b_difference[]; };
layout(scalar, binding = kResolveJudgements) buffer Judgements { TileJudgement b_judgements[]; };
layout(push_constant, scalar) uniform Push { ResolvePush u_push; };

#include "common/difference.glsl"
#include "common/octahedral.glsl"

// Pixel index of the tile's local-th pixel, or kInvalidIndex outside the image.
uint tile_pixel_index(uvec2 origin, uint local) {
  const uvec2 pixel = origin + uvec2(local % u_frame.tileSize, local / u_frame.tileSize);
  return pixel.x < u_frame.width && pixel.y < u_frame.height ? pixel.y * u_frame.width + pixel.x : kInvalidIndex;
}

// The surface the pixel shows now (kRecordUnknown without a current G-buffer).
uint current_record(uint index) { return u_push.useGBuffer != 0u ? b_gbuffer[index].record : kRecordUnknown; }

// Its geometric normal (kNormalUnknown without a current G-buffer).
uint current_normal(uint index) { return u_push.useGBuffer != 0u ? b_gbuffer[index].normal : kNormalUnknown; }

// The pixel's stale estimate depicts another surface than the pixel shows now: another record,
// or another face of it (a moved block's front face where its side was: kSurfaceTurnCosine).
bool resurfaced(uint index, DisplayTexel texel) {
  if (texel.staleRecord == kRecordUnknown || u_push.useGBuffer == 0u) return false;
  const GBufferTexel now = b_gbuffer[index];
  return texel.staleRecord != now.record || surface_turned(texel.staleNormal, now.normal);
}

bool has_fresh_samples(PixelAccum accum) { return (accum.count & kPixelOwed) == 0u && (accum.count & kPixelCountMask) > 0u; }

// The stale estimate is already an unbiased estimate of the scene since the last edit (relit by
// linearity: relight.comp) with more samples than the pixel's n fresh ones: the weighing rules
// keep it until the fresh count catches up (the gate that ends every schedule on the fresh
// estimate alone) instead of judging it as a possibly wrong value, which let fresh noise through
// wherever D exceeded V by chance. `immediate` shows f as always.
bool keeps_current_stale(DisplayTexel texel, uint n) {
  return u_push.rule != kDisplayImmediate && (texel.flags & kStaleCurrent) != 0u && n < texel.staleSamples;
}

// How many of the pixel's samples have a difference: all n while n <= the kept samples; 0 (no
// difference estimate: blend judges the pixel) without kept samples or past them.
uint differenced_samples(DisplayTexel texel, uint n) {
  return u_push.rule == kDisplayDifference && n <= texel_valid(texel.flags) ? n : 0u;
}

// The difference estimate C of a pixel with c differenced samples.
vec3 difference_estimate(DifferenceRecord record, vec3 stale, uint c) {
  return stale + record_vec3(record, kDifferenceSum) / float(c);
}

// C' = C + a (f - C) of a changed pixel with c differenced samples (all of its samples), a the
// regression weight per channel.
vec3 corrected_estimate(DifferenceRecord record, vec3 stale, vec3 fresh, uint c, vec3 regression) {
  const vec3 estimate = difference_estimate(record, stale, c);
  return estimate + regression * (fresh - estimate);
}

// The regression weight a of f against C per channel, -sum w d (old - s) / sum w (old - s)^2,
// clamped to [kRegressionLow, 1] (0 where no old sample strayed from s). A recolour by k wants
// 1 - k: the bound lets a channel grow up to 8x noise-free (the Cornell wall made blue: 18x in
// blue), while a tile whose paths did not all scale alike (some through the recoloured wall,
// some not) amplifies a stray old sample's noise by at most 7. With -63 such a pixel showed 48x
// its value (CornellBox, one pixel near the floor, relMSE 1.1 -> 6.3 for a step).
const float kRegressionLow = -7.0;
vec3 regression_weight(vec3 cross, vec3 spread) {
  return mix(vec3(0.0), clamp(-cross / max(spread, vec3(1e-30)), kRegressionLow, 1.0), greaterThan(spread, vec3(0.0)));
}

// The regression weight of a changed pixel's C': fitted on its tile's other changed pixels, the
// tile's sums less the pixel's own. Fitted on sums that include the pixel, a pair of samples far
// apart (one path found a bright light its twin missed) pulls a toward the value that cancels its
// own residual: the pixel then shows f's 2-sample noise under a noise estimate (Vd) that no longer
// sees it. A held-out fit cannot follow the pixel's own noise (the SheenChair wood made rougher:
// relMSE over the first unit 1.02x the stale image's with the in-sample fit, 0.91x held out; the
// Cornell edits alike both ways). Others whose spread is lost in the sums' rounding fit nothing
// (a = 0: C, unbiased by itself).
vec3 held_out_regression(TileJudgement judgement, DifferenceRecord record) {
  if (!record_judges(record)) return regression_weight(judgement.cross, judgement.spread);
  const vec3 spread = judgement.spread - record_sums(record, kDifferenceOld);
  const vec3 cross = judgement.cross - record_sums(record, kDifferenceCross);
  return regression_weight(cross, mix(vec3(0.0), spread, greaterThan(spread, 1e-5 * judgement.spread)));
}

// Sums that overflowed (radiance near float's range) cannot judge noise: the fresh estimate is
// the one that converges, so it shows, as it would without a display rule.
bool sums_overflowed(float d, float v) { return isinf(v) || isnan(v) || isinf(d) || isnan(d); }

// The weight B / (B + V') of a change whose squared bias B is estimated from D = B + V in
// expectation, V the raw noise D holds, V' the noise the screen shows of the estimate (V' = V
// unless the display is denoised: DisplayTexel::screenNoise). 0 when B = 0; 1 from overflowed
// sums.
float change_weight_on_screen(float d, float v, float screenV) {
  if (sums_overflowed(d, v)) return 1.0;
  const float b = max(d - v, 0.0);
  return b > 0.0 ? b / (b + screenV) : 0.0;
}

float change_weight(float d, float v) { return change_weight_on_screen(d, v, v); }

// A blend pixel's terms of D and V (n >= 2 fresh samples): w (f - s)^2 and
// w var (1/n - 1/n_s). Var(f - s) with shared random streams: sample i of a pixel draws the same
// random numbers before and after an edit, so where paths miss the change f and s share their
// first n samples' noise (no stale count known: var / n).
vec2 blend_terms(PixelAccum accum, uint n, DisplayTexel texel) {
  const vec3 mean = accum.sum / float(n);
  const vec3 variance = max(accum.sumSquares - float(n) * mean * mean, vec3(0.0)) / float(n - 1u);
  const vec3 weight = relmse_weight(texel.stale);
  const float staleShare = texel.staleSamples > n ? 1.0 / float(texel.staleSamples) : 0.0;
  const vec3 d = mean - texel.stale;
  return vec2(dot(weight, d * d), dot(weight, variance) * (1.0 / float(n) - staleShare));
}

// Var(sum_i r_i / c), r_i = d_i + a (old_i - s), weighted as relMSE weighs errors, from the
// record's sums and C' - s = sum_i r_i / c (c >= 2; with one difference the square of r, which
// bounds it from above).
float corrected_noise(DifferenceRecord record, vec3 shift, vec3 stale, uint c, vec3 a) {
  const float squares = record_squares(record) + 2.0 * dot(a, record_sums(record, kDifferenceCross)) +
                        dot(a * a, record_sums(record, kDifferenceOld));
  if (c < 2u) return max(squares, 0.0);
  return max(squares - float(c) * dot(relmse_weight(stale), shift * shift), 0.0) / float((c - 1u) * c);
}

// A changed difference pixel's terms of Dd and Vd (c differenced samples, regression a):
// w (C' - s)^2 and the noise of C' - s.
vec2 change_terms(DifferenceRecord record, DisplayTexel texel, vec3 fresh, uint c, vec3 a) {
  const vec3 shift = corrected_estimate(record, texel.stale, fresh, c, a) - texel.stale;
  return vec2(dot(relmse_weight(texel.stale), shift * shift), corrected_noise(record, shift, texel.stale, c, a));
}

#endif
