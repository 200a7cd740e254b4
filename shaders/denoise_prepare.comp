#version 460
// The display denoiser's second kernel (after denoise_keys.comp): what each pixel shows, less its
// surface's emission and demodulated by its albedo (common/denoise.glsl), with the variance of
// its luminance.
// Reads: the guides, the display (shown value, its samples and scene state), the accumulation
// (sum, sum of squares, count), the keys. Writes: the input of the first a-trous pass (vec4:
// demodulated radiance, variance; a kept pixel: the radiance it shows, kept_value), the variance
// again and as the variance of the radiance's luminance (for denoise_blend.comp and
// denoise_temporal.comp, which weigh radiance) and the samples behind each value.
//
// The variance is the shown value's own: with hipr's display state (DenoisePush::displayState),
// a pixel showing the edited scene takes its samples' variance over the samples behind what it
// shows (DisplayTexel::shownSamples: more than its fresh samples where a converged stale estimate
// still weighs). Without it (the ablation: a denoiser that knows only the accumulation), the
// accumulation's own count. A pixel still showing its stale estimate takes the variance of the
// samples that made it (sample_variance). One showing a value that holds more than its fresh
// samples (the stale estimate kept, or mixed with them) pools their variance with the noise prior
// (pooled_with_prior): one sample's variance measured on at least kPriorSamples samples of the
// surface it sees, the last time it had them (before the edit), kept in kDenoiseShownNoise.
// One with fewer than kShortHistory samples behind it,
// the spatial variance of its 3 x 3 neighbours whose keys mix: the variance of two samples is a
// guess with one degree of freedom, and a pair that happened to agree (a new shadow's pixel,
// both samples dark) was taken as precise and its speckle kept. An outline pixel (guide_outline)
// with fewer than kOutlineSamples takes at least that spatial variance: its samples agreeing
// (all on the background beside its surface) is chance, not precision. A value still shown after its
// samples left the accumulation (the converged image a restart shows until its first pass is
// done, whose pixels then hold one sample of the new pass) keeps the variance and samples it was
// last filtered with (kDenoiseShownNoise, matched by the shown luminance's bits): taken from its
// neighbours it was filtered as one sample's value, and the converged image blurred step by step
// while it stayed on screen. The environment seen directly is shown as it is (its only noise is
// antialiasing).
// Keys (which neighbours a pixel may mix with) are denoise_keys.comp's, written before this runs.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/denoise.glsl"
#include "common/dispatch.glsl"

layout(scalar, binding = kDenoiseGuides) readonly buffer Guides { DenoiseGuide b_guides[]; };
layout(scalar, binding = kDenoiseDisplay) readonly buffer Display { DisplayTexel b_display[]; };
layout(scalar, binding = kDenoiseAccumulation) readonly buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kDenoiseKeys) readonly buffer Keys { uint b_keys[]; };
layout(scalar, binding = kDenoiseInput) writeonly buffer Input { vec4 b_input[]; };
layout(scalar, binding = kDenoiseSamples) writeonly buffer Samples { uint b_samples[]; };
layout(scalar, binding = kDenoiseVariance) writeonly buffer Variance { vec2 b_variance[]; };
// What the prepare kernel keeps of a pixel from one run to the next.
struct ShownNoise {
  uvec3 last;   // the shown value's luminance bits, its variance (bits) and samples, as last filtered
  uvec3 prior;  // the noise prior: one sample's variance (bits), the samples it was measured on
                // and the surface (guide record) they saw
};
layout(scalar, binding = kDenoiseShownNoise) buffer ShownNoiseBuffer { ShownNoise b_shown_noise[]; };
layout(push_constant, scalar) uniform Push { DenoisePush u_push; };

const uint kShortHistory = 3u;          // fewer samples behind a value: their own variance is not used
const uint kPriorSamples = 16u;         // fewer samples: their variance is no prior for later ones
const uint kOutlineSamples = 16u;       // fewer behind an outline pixel: its neighbours' variance too
const uint kOwnColourSamples = 32u;     // fewer: the value's variance as radiance by its albedo's luminance

float demodulated_luminance(uint index) {
  return denoise_luminance(demodulated(b_display[index].shown, b_guides[index]));
}

// The samples behind what is shown, as far as the variance knows them (1: a spatial estimate).
uint samples_behind(DisplayTexel texel, uint n) { return u_push.displayState != 0u ? max(texel.shownSamples, n) : n; }

// Whether the pixel shows its stale estimate relit (relight.comp): the edited scene's value from
// the samples of the scene before the edit, each light group's share scaled.
bool shows_relit(DisplayTexel texel) {
  const uint relit = kShownGrouped | kStaleCurrent;
  return u_push.displayState != 0u && (texel.flags & relit) == relit;
}

// One sample's variance of the demodulated luminance, from the n samples in the pixel's
// accumulation, or -1 where the pixel cannot tell (fewer than two samples). Whose samples: a pixel
// showing the scene since the edit has its fresh ones; one still showing its stale estimate has
// the samples that made it, in the accumulation until its next visit drops them (owed:
// mark_owed.comp); a relit pixel has those too, each channel's spread scaled as the relight
// scaled its value (the sums of squares do not keep the light groups apart). Taken from its
// neighbours instead, as a pixel without samples, a converged relit image was filtered as noise
// wherever its shading varied (cornell_sphere's ceiling light dimmed: relMSE over the first unit
// 1.13x that of full + denoise, which shows the image before the edit).
//
// `toRadiance` is what turns that variance into the variance of the radiance's luminance: the
// squared ratio of the channels' spreads before and after demodulation. The albedo's luminance
// squared, which the kernels take otherwise, holds for grey light only: a white highlight on a
// blue base, demodulated, is mostly red and green, and read its noise 2.6x too high.
float sample_variance(uint index, DisplayTexel texel, vec3 albedo, out uint n, out float toRadiance) {
  const PixelAccum accum = b_accum[index];
  n = accum.count & kPixelCountMask;
  toRadiance = 0.0;
  const bool owedShown = (accum.count & kPixelOwed) != 0u && shows_current(texel, u_push.displayState);
  if (n < 2u || (owedShown && !shows_relit(texel))) return -1.0;
  const vec3 mean = accum.sum / float(n);
  vec3 spread = sqrt(max(accum.sumSquares - float(n) * mean * mean, vec3(0.0)) / float(n - 1u)) / albedo;
  if (owedShown) spread *= mix(vec3(1.0), texel.shown / max(mean, vec3(1e-30)), greaterThan(mean, vec3(0.0)));
  // The channels' noise is of the same paths: their deviations add up in the luminance.
  const float deviation = denoise_luminance(spread);
  const float reflected = denoise_luminance(spread * albedo);
  toRadiance = deviation > 0.0 ? (reflected / deviation) * (reflected / deviation) : 0.0;
  return deviation * deviation;
}

// The variance of the luminance over the 3 x 3 neighbours with the pixel's key.
float spatial_variance(uvec2 pixel, uint key, float own) {
  float sum = 0.0, squares = 0.0;
  uint count = 0u;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const ivec2 q = ivec2(pixel) + ivec2(dx, dy);
      if (any(lessThan(q, ivec2(0))) || q.x >= int(u_push.width) || q.y >= int(u_push.height)) continue;
      const uint neighbour = uint(q.y) * u_push.width + uint(q.x);
      if (!keys_mix(b_keys[neighbour], key)) continue;
      const float l = demodulated_luminance(neighbour);
      sum += l;
      squares += l * l;
      count += 1u;
    }
  if (count < 2u) return own * own;
  const float mean = sum / float(count);
  return max(squares / float(count) - mean * mean, 0.0) * float(count) / float(count - 1u);
}

// What a pixel the filter keeps shows: its value, but for one whose footprint the guide saw
// see only the environment (denoise_guides.comp) and that has fewer samples than the guide's
// kFootprintLookups lookups, the environment's mean over the footprint: what its samples
// converge to, known better than they tell it. Unless its own samples say otherwise: a sliver of
// a surface (a cushion's rim) can lie between the guide's rays, and a sample that found it is
// far from the environment's mean. The pixel's samples of the scene as it is now (not owed)
// must then agree with the environment's mean within four standard errors (the environment's
// spread over the footprint, over the samples and over the lookups) and spread no more than four
// times the environment's own spread.
vec3 kept_value(uint index) {
  const vec3 shown = b_display[index].shown;
  vec3 environment;
  float deviation;
  if (u_push.strength <= 0.0 || !footprint_environment(b_guides[index], environment, deviation)) return shown;
  const PixelAccum accum = b_accum[index];
  const uint n = accum.count & kPixelCountMask;
  if (n >= kFootprintLookups || (accum.count & kPixelOwed) != 0u) return shown;
  if (n == 0u) return environment;  // nothing rendered yet since the start, nothing to disagree
  const vec3 mean = accum.sum / float(n);
  // Half's rounding of the mean, and a floor for an environment of one colour.
  const float margin = 1.0e-3 * denoise_luminance(environment) + kFootprintDeviationFloor;
  const float error = abs(denoise_luminance(mean) - denoise_luminance(environment));
  if (error > 4.0 * deviation * sqrt(1.0 / float(n) + 1.0 / float(kFootprintLookups)) + margin) return shown;
  if (n >= 2u) {
    const vec3 spread = sqrt(max(accum.sumSquares - float(n) * mean * mean, vec3(0.0)) / float(n - 1u));
    if (denoise_luminance(spread) > 4.0 * deviation + margin) return shown;
  }
  return environment;
}

// Whether the pixel's noise prior may stand for the noise of what it shows: measured on enough
// samples of the surface the pixel sees now.
bool prior_applies(uvec3 prior, uint index) {
  return prior.y >= kPriorSamples && prior.z == b_guides[index].record;
}

// One sample's variance of a value that holds more than its n fresh samples (a converged stale
// estimate kept, or mixed with a few fresh samples: DisplayTexel::shownSamples > n), pooled with
// the prior measured on the samples of the scene before the edit: a pair of samples' own variance
// has one degree of freedom, and where paths rarely meet what the edit changed (a moved sphere
// seen in a closed box's walls) it mostly misses the rare bright paths, so the kept value was
// taken as precise and shown unfiltered (CornellBox's sphere move: the denoised display grew
// worse as hipr re-rendered). -1 without a prior or where the fresh samples are as many.
float pooled_with_prior(uvec3 prior, uint index, DisplayTexel texel, float perSample, uint n) {
  if (u_push.displayState == 0u || !shows_current(texel, u_push.displayState) || texel.shownSamples <= n || n >= prior.y ||
      !prior_applies(prior, index))
    return -1.0;
  const float fresh = perSample >= 0.0 ? float(n - 1u) : 0.0;
  const float old = float(prior.y - 1u);
  return (fresh * max(perSample, 0.0) + old * uintBitsToFloat(prior.x)) / (fresh + old);
}

void main() {
  const uint index = dispatch_index();
  if (index >= u_push.width * u_push.height) return;
  const uvec2 pixel = uvec2(index % u_push.width, index / u_push.width);
  const vec3 albedo = unpack_albedo(b_guides[index].albedo);
  const DisplayTexel texel = b_display[index];
  const vec3 radiance = demodulated(texel.shown, b_guides[index]);
  const uint key = b_keys[index];
  ShownNoise kept = b_shown_noise[index];
  uint behind = 1u;
  if (key == kDenoiseKept) {
    b_input[index] = vec4(kept_value(index), 0.0);
    b_samples[index] = behind;
    b_variance[index] = vec2(0.0);
    b_shown_noise[index].last = uvec3(0u);
    return;
  }
  const uint shownBits = floatBitsToUint(denoise_luminance(radiance));
  uint n;
  float ownToRadiance;
  const float perSample = sample_variance(index, texel, albedo, n, ownToRadiance);
  bool ownColour = false;  // the variance is the pixel's samples', on kOwnColourSamples or more
  if (perSample >= 0.0 && n >= kPriorSamples && !isinf(perSample) && !isnan(perSample))
    kept.prior = uvec3(floatBitsToUint(perSample), n, b_guides[index].record);
  const float pooled = pooled_with_prior(kept.prior, index, texel, perSample, n);
  float variance = -1.0;
  bool fromNeighbours = false;
  if (perSample >= 0.0) {
    behind = samples_behind(texel, n);
    variance = perSample / float(behind);
    ownColour = n >= kOwnColourSamples && ownToRadiance > 0.0;
  }
  if (pooled >= 0.0) {
    ownColour = false;
    behind = texel.shownSamples;
    variance = pooled / float(behind);
  } else if (variance < 0.0 && !shows_current(texel, u_push.displayState) && kept.last.x == shownBits && kept.last.z >= kShortHistory) {
    variance = uintBitsToFloat(kept.last.y);
    behind = kept.last.z;
  } else if (variance < 0.0 || behind < kShortHistory) {
    variance = spatial_variance(pixel, key, denoise_luminance(radiance));
    fromNeighbours = true;
  }
  // An outline pixel's samples fall on its surface or on the environment beside it: a few that
  // agree (all on the dark background) tell nothing of that mix. Below kOutlineSamples its
  // variance is at least that of its neighbours of the same key (the surface's other pixels
  // beside an edge), unless it is already theirs.
  if (!fromNeighbours && guide_outline(b_guides[index]) && behind < kOutlineSamples)
    variance = max(variance, spatial_variance(pixel, key, denoise_luminance(radiance)));
  variance = isinf(variance) || isnan(variance) ? 0.0 : variance;
  kept.last = uvec3(shownBits, floatBitsToUint(variance), behind);
  b_shown_noise[index] = kept;
  b_input[index] = vec4(radiance, variance);
  b_samples[index] = behind;
  const float a = denoise_luminance(albedo);
  b_variance[index] = vec2(variance, ownColour ? variance * ownToRadiance : variance * a * a);
}
