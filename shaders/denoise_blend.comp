#version 460
// The display denoiser's last kernel: how much of the filtered value each pixel shows. The
// filter trades noise for bias (a shading gradient averaged over its footprint): where the
// pixel's own estimate is precise, the bias is the larger error. As hipr's display rules weigh a
// stale estimate against a fresh one (resolve_display.comp), over the 11 x 11 pixels whose
// keys mix with its own (keys_mix), with r the shown value and f the filtered one (luminances
// of radiance), each pixel weighed as relMSE weighs errors, w = 1 / (r^2 + 0.01), as the
// display rules do:
//   D = sum w (f - r)^2   (E[D] ~ B + V: the filter's squared bias, and r's noise)
//   V = sum w Var(r)
// (In radiance, not in the demodulated values the filter works on: there a dark texel's noise,
// divided by its small albedo, outweighed its whole window and let the filter blur bright detail.
// Var(r) is the radiance's too, as denoise_prepare.comp gives it: from the channels' own spreads
// on 32 samples or more, where a white highlight on a coloured base is not read as noisier than
// it is.)
// and the pixel shows r + a (f - r), a = min(1, V / D): the mix whose expected error is least
// when f's own noise is small next to r's. A precise pixel (V = 0) shows r as it is; a 2-spp
// pixel, whose noise dwarfs any bias, shows f. (f and r are correlated, so V / D over-weighs f
// a little; the window keeps a from following one pixel's noise.) On 32 samples or more, a is
// at most the same ratio for the pixel alone (own_weight).
// What is mixed in is f scaled to the window's own mean, 1 + s (R / F - 1), R and F the window's
// sums of r and f, s = G / (G + Var R) with G = (R - F)^2: how far the difference stands out
// of R's noise. The a-trous passes weigh a neighbour by how alike its value is, and a few
// samples are skewed (most paths miss the light, a few find it): the many dim pixels take little
// from the rare bright ones, and the filtered image is darker than its samples (the Cornell
// box's walls 2-4 % at 4 spp, its small block's dark face 24 %). R is unbiased; the ratio of
// two sums of about a hundred pixels is close to its limit, and where a firefly makes R differ,
// its variance makes s small. The correction is for what the pixel took from its neighbours:
// it is scaled by their mean samples over the pixel's own (at most 1), so a precise pixel among
// noisy ones, which the filter left as it was, keeps its value.
// A pixel the filter keeps shows what denoise_prepare.comp chose (its value, or the environment's
// mean over its footprint).
// Reads: the guides, keys, samples and the variance of each shown value, the display, the last
// a-trous pass's output. Writes: this frame's denoised radiance (denoise_temporal.comp steadies it)
// and each pixel's DisplayTexel::screenNoise (the display rules read it at the next step).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

#include "common/frame.glsl"
#include "common/denoise.glsl"

// Declared before dispatch.glsl: its gl_WorkGroupSize is this size only after the declaration.
layout(local_size_x = kDenoiseBlendTileWidth * kDenoiseBlendTileHeight) in;
#include "common/dispatch.glsl"

layout(scalar, binding = kDenoiseGuides) readonly buffer Guides { DenoiseGuide b_guides[]; };
layout(scalar, binding = kDenoiseDisplay) buffer Display { DisplayTexel b_display[]; };  // writes screenNoise
layout(scalar, binding = kDenoiseKeys) readonly buffer Keys { uint b_keys[]; };
layout(scalar, binding = kDenoiseInput) readonly buffer Filtered { vec4 b_filtered[]; };
layout(scalar, binding = kDenoiseVariance) readonly buffer Variance { vec2 b_variance[]; };
layout(scalar, binding = kDenoiseSamples) readonly buffer Samples { uint b_samples[]; };
layout(scalar, binding = kDenoiseFrame) writeonly buffer ThisFrame { vec3 b_frame[]; };
layout(push_constant, scalar) uniform Push { DenoisePush u_push; };

const int kWindowRadius = 5;
// Fewer samples behind a value leave its variance too rough for own_weight to judge by.
const float kTrustedSamples = 32.0;
// Beyond this the window's sums differ by a firefly, not by the weights' lean.
const float kMaxMeanRatio = 2.0;

// A workgroup is a tile of pixels (kDenoiseBlendTileWidth x kDenoiseBlendTileHeight). What each
// pixel adds to a window depends on that pixel alone, so the tile and its margin compute it once
// into shared memory and every window sums from there (121 reads of the guides, display and
// filtered values per pixel were most of this kernel).
const ivec2 kTile = ivec2(kDenoiseBlendTileWidth, kDenoiseBlendTileHeight);
const ivec2 kSpan = kTile + 2 * kWindowRadius;
const int kPlaces = kSpan.x * kSpan.y;
const uint kOutside = 0xffffffffu;  // the key of a place past the image's edge: equal to none
shared uint s_keys[kPlaces];
shared vec3 s_weighed[kPlaces];  // w (f - r)^2, w Var(r), Var(r)
shared vec3 s_sums[kPlaces];     // r, f, samples

bool inside(ivec2 q) { return q.x >= 0 && q.y >= 0 && q.x < int(u_push.width) && q.y < int(u_push.height); }

void load(int slot, ivec2 q) {
  uint key = kOutside;
  if (inside(q)) {
    const uint i = uint(q.y) * u_push.width + uint(q.x);
    key = b_keys[i];
    if (key != kDenoiseKept) {  // a kept pixel is read by no neighbour
      const DenoiseGuide guide = b_guides[i];
      const vec3 albedo = unpack_albedo(guide.albedo);
      const vec3 shown = b_display[i].shown;
      const float r = denoise_luminance(demodulated(shown, guide) * albedo);
      const float f = denoise_luminance(b_filtered[i].rgb * albedo);
      const float l = denoise_luminance(shown);
      const float w = 1.0 / (l * l + 0.01);
      const float variance = b_variance[i].y;
      s_weighed[slot] = vec3(w * (f - r) * (f - r), w * variance, variance);
      s_sums[slot] = vec3(r, f, float(b_samples[i]));
    }
  }
  s_keys[slot] = key;
}

// The share of the shown value's variance `raw` the pixel's mix (1 - a) r + a f keeps, f's
// variance `filtered` as the a-trous passes carried it: ((1 - a)^2 raw + a^2 filtered) / raw,
// r and f taken as independent (f holds a little of r: the share is somewhat low where the
// filter found few neighbours) and the temporal history's further steadying left out. 1 for a
// value the filter gives no variance to.
float screen_noise(float a, float raw, float filtered) {
  if (!(raw > 0.0) || isinf(raw) || !(filtered >= 0.0) || isinf(filtered)) return 1.0;
  const float kept = (1.0 - a) * (1.0 - a) * raw + a * a * filtered;
  return clamp(kept / raw, 0.0, 1.0);
}

// The share of the filtered value whose expected error is least, min(1, V / D): D the squared
// difference of filtered and shown values, V the shown values' noise.
float mix_weight(float noise, float difference) { return difference > noise ? noise / difference : 1.0; }

// The window's rule applied to the pixel alone: at most a = Var / (f - r)^2 of the filtered value
// f, r the shown value. The window's weight counts each pixel as relMSE does, and a few pixels
// the filter moved far (a glint, a clear coat's highlight, a letter of a label) weigh little
// among a hundred it moved within their noise: at 64 spp the window let the filter dim
// ClearCoatTest's highlights to a third although their samples pinned them down. Var is the
// larger of the pixel's own variance and its window's mean: where all of a pixel's samples
// missed a rare bright path (CornellBox's glass and mirror), its own variance is too small, and
// its difference from the filter is its noise, not the filter's bias. Only on kTrustedSamples.
float own_weight(float r, float f, float variance, float samples) {
  return samples < kTrustedSamples ? 1.0 : mix_weight(variance, (f - r) * (f - r));
}

void main() {
  const uint tilesX = (u_push.width + uint(kTile.x) - 1u) / uint(kTile.x);
  const uint group = dispatch_group();
  const ivec2 origin = ivec2(group % tilesX, group / tilesX) * kTile;
  for (uint slot = gl_LocalInvocationIndex; slot < uint(kPlaces); slot += gl_WorkGroupSize.x)
    load(int(slot), origin - kWindowRadius + ivec2(slot % uint(kSpan.x), slot / uint(kSpan.x)));
  barrier();

  const ivec2 local = ivec2(gl_LocalInvocationIndex % uint(kTile.x), gl_LocalInvocationIndex / uint(kTile.x));
  const ivec2 p = origin + local;
  if (!inside(p)) return;
  const uint index = uint(p.y) * u_push.width + uint(p.x);
  const int centre = (local.y + kWindowRadius) * kSpan.x + local.x + kWindowRadius;
  const uint key = s_keys[centre];
  const vec3 shown = b_display[index].shown;
  if (key == kDenoiseKept) {  // what denoise_prepare.comp says it shows, through every pass
    b_frame[index] = b_filtered[index].rgb;
    b_display[index].screenNoise = 1.0;
    return;
  }
  vec3 weighed = vec3(0.0);  // D and V, weighed as relMSE weighs errors; the variance of R
  vec3 sums = vec3(0.0);     // R and F, the window's luminance shown and filtered; its samples
  float count = 0.0;
  for (int dy = -kWindowRadius; dy <= kWindowRadius; ++dy)
    for (int dx = -kWindowRadius; dx <= kWindowRadius; ++dx) {
      const int slot = centre + dy * kSpan.x + dx;
      if (!keys_mix(s_keys[slot], key)) continue;
      weighed += s_weighed[slot];
      sums += s_sums[slot];
      count += 1.0;
    }
  const float difference = weighed.x, noise = weighed.y, rawVariance = weighed.z;
  const float rawSum = sums.x, filteredSum = sums.y;
  const float weight = mix_weight(noise, difference);
  const float gap = (rawSum - filteredSum) * (rawSum - filteredSum);
  const float significance = gap > 0.0 ? gap / (gap + rawVariance) : 0.0;
  const float ratio = filteredSum > 0.0 ? clamp(rawSum / filteredSum, 1.0 / kMaxMeanRatio, kMaxMeanRatio) : 1.0;
  const float ownSamples = s_sums[centre].z;
  const float neighbourSamples = sums.z - ownSamples, neighbours = count - 1.0;
  const float share =
      neighbours > 0.0 ? min(neighbourSamples / (neighbours * max(ownSamples, 1.0)), 1.0) : 0.0;
  const float restore = 1.0 + share * significance * (ratio - 1.0);
  const float own =
      own_weight(s_sums[centre].x, restore * s_sums[centre].y, max(s_weighed[centre].z, rawVariance / count), ownSamples);
  const float mix = min(weight, own);
  const DenoiseGuide guide = b_guides[index];
  const vec3 raw = demodulated(shown, guide);
  const vec3 radiance = remodulated(raw + mix * (restore * b_filtered[index].rgb - raw), guide);
  const bool finite = !(any(isinf(radiance)) || any(isnan(radiance)));
  b_frame[index] = finite ? radiance : shown;
  b_display[index].screenNoise = finite ? screen_noise(mix, b_variance[index].x, b_filtered[index].w) : 1.0;
}
