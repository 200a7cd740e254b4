#version 460
// Estimates how far the film's image still is from its converged limit, from each pixel's own
// samples: the expected relMSE of the pixel's mean, Var(sample) / n per channel over
// (mean^2 - Var / n) + 0.01, halved as relmse() halves it (src/image/error_metrics.h). Summed
// per workgroup in a fixed order, so that one image always gets one estimate (the viewer stops
// rendering at a noise target: the stopping point must not depend on the GPU's timing).
// Reads: every pixel's accumulation. Writes: one NoisePartial per workgroup.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "shared/bindings/film.h"
#include "common/dispatch.glsl"

layout(push_constant) uniform Push { uint pixelCount; } u_push;
layout(scalar, binding = kNoiseAccumulation) readonly buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kNoisePartials) writeonly buffer Partials { NoisePartial b_partials[]; };

shared float s_relmse[64];
shared uint s_unknown[64];

// The pixel's expected relMSE against its own limit, or -1 where it cannot tell: an owed pixel
// still holds samples of the scene before an edit, and one sample has no variance.
float expected_relmse(PixelAccum accum) {
  const uint n = accum.count & kPixelCountMask;
  if ((accum.count & kPixelOwed) != 0u || n < 2u) return -1.0;
  const vec3 mean = accum.sum / float(n);
  const vec3 variance = max(accum.sumSquares - float(n) * mean * mean, vec3(0.0)) / float(n - 1u);
  // mean^2 overestimates the square of the limit by the mean's own variance (E[m^2] = mu^2 +
  // Var/n): a pixel whose few samples hold a bright path would otherwise judge itself precise.
  const vec3 error = variance / float(n);
  const vec3 terms = error / (max(mean * mean - error, vec3(0.0)) + 0.01);
  const float sum = 0.5 * (terms.r + terms.g + terms.b);
  return isnan(sum) || isinf(sum) ? -1.0 : sum;
}

void main() {
  // Workgroups past the requested count (a folded dispatch's last row) have no partial to write.
  if (dispatch_group() * 64u >= u_push.pixelCount) return;
  const uint local = gl_LocalInvocationIndex;
  const uint index = dispatch_index();
  float relmse = 0.0;
  uint unknown = 0u;
  if (index < u_push.pixelCount) {
    relmse = expected_relmse(b_accum[index]);
    if (relmse < 0.0) {
      relmse = 0.0;
      unknown = 1u;
    }
  }
  s_relmse[local] = relmse;
  s_unknown[local] = unknown;
  barrier();
  if (local != 0u) return;
  NoisePartial partial;
  partial.relmse = 0.0;
  partial.unknown = 0u;
  for (uint i = 0u; i < 64u; ++i) {
    partial.relmse += s_relmse[i];
    partial.unknown += s_unknown[i];
  }
  b_partials[dispatch_group()] = partial;
}
