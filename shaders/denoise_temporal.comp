#version 460
// The display denoiser's last kernel: what the screen shows of this frame's filter, steadied by
// what the last frame showed (SVGF ends on a temporal filter of its output too). Each new
// sample changes the filtered image a little everywhere in its footprint, and a view that
// converges sample by sample shimmers; the last frame shown is kept in part:
//   shown = f + k (h - f),  k = min(keep^g, 1 - g / n)
// with f this frame's filter, h the last frame shown (clipped, below), g the samples the pixel
// gained since then and n the samples behind its value now: per sample a share `1 - keep` of the
// new frame (DenoiseSettings::history is `keep`), and never less than the new samples' share of
// all (a view that has just started does not carry its first noisy frames along). A pixel that
// gained no sample keeps the last value shown (its neighbours' samples moved the filter, within
// its noise). The rate is per sample, not per frame: a device that renders many samples a frame
// keeps as much of its history as one that renders one.
// The history is never kept across a change: the pass starts over after an edit, a camera move,
// new settings (DenoisePass: historyReset), and a pixel starts over when its key changes (another
// surface, or the edited scene's value replacing the stale one), when it has fewer samples than
// before, and where the filter keeps it as it is. And the last value is clipped to within
// kAgreement standard errors of the pixel's own value (its shown value's noise, from
// denoise_prepare.comp) around this frame's filter: further apart, the difference is not the
// filter's noise and the new value shows. A precise pixel (no variance) shows f exactly.
// Reads: the keys, samples behind each value, their variance as radiance, this frame's
// filter (denoise_blend.comp), the last frame shown. Writes: the denoised radiance, and per pixel
// the key and samples it was shown with.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

#include "common/frame.glsl"
#include "common/denoise.glsl"

layout(local_size_x = 64) in;
#include "common/dispatch.glsl"

layout(scalar, binding = kDenoiseKeys) readonly buffer Keys { uint b_keys[]; };
layout(scalar, binding = kDenoiseSamples) readonly buffer Samples { uint b_samples[]; };
layout(scalar, binding = kDenoiseVariance) readonly buffer Variance { vec2 b_variance[]; };
layout(scalar, binding = kDenoiseFrame) readonly buffer ThisFrame { vec3 b_frame[]; };
layout(scalar, binding = kDenoiseResult) buffer Result { vec3 b_result[]; };
layout(scalar, binding = kDenoiseHistory) buffer History { uvec2 b_history[]; };
layout(push_constant, scalar) uniform Push { DenoisePush u_push; };

// How far (in standard errors of the pixel's value) the last frame may lie from this one's
// filter and still be taken for its noise.
const float kAgreement = 2.0;

void main() {
  const uint index = dispatch_index();
  if (index >= u_push.width * u_push.height) return;
  const vec3 filtered = b_frame[index];
  const uint key = b_keys[index];
  const uint samples = b_samples[index];
  const uvec2 last = b_history[index];  // key, samples
  b_history[index] = uvec2(key, samples);
  if (u_push.historyReset != 0u || u_push.historyKeep <= 0.0 || key == kDenoiseKept || last.x != key ||
      samples < last.y) {
    b_result[index] = filtered;
    return;
  }
  const vec3 previous = b_result[index];
  const float limit = kAgreement * sqrt(max(b_variance[index].y, 0.0));
  const vec3 apart = previous - filtered;
  const float distance = max(max(abs(apart.x), abs(apart.y)), abs(apart.z));
  const uint gained = samples - last.y;
  if (gained == 0u && distance <= limit) return;  // nothing of its own changed: shown as it was
  const vec3 held = distance > limit ? apart * (limit / distance) : apart;
  const float keep = min(pow(u_push.historyKeep, float(gained)), 1.0 - float(gained) / float(max(samples, 1u)));
  const vec3 shown = filtered + keep * held;
  b_result[index] = any(isinf(shown)) || any(isnan(shown)) ? filtered : shown;
}
