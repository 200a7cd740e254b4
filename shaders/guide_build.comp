#version 460
// Turns the training paths' sums into the guide (common/guiding.glsl), one invocation per cell.
// Reads:  per cell, each direction bin's fixed-point sum of reflected light and its largest
//         splat, and the cell's number of splats.
// Writes: per cell, the bins' CDF and the probability that the guide (not the BSDF) picks a
//         direction there.
// The light paths carry is heavy-tailed: at a few training paths per pixel one lucky path can
// hold most of a cell's sum, and a guide that believed it would send a third of the cell's paths
// where little light is. A bin's sum is therefore taken without its largest splat: light that
// one path alone found is not learnt (a bin that many paths lit keeps nearly all); a tenth of each cell's distribution is spread evenly over the sphere, so
// no direction is out of reach through the guide alone; and the guide's share grows with the
// splats the cell received (a cell a few paths crossed mostly trusts the BSDF). All of it only
// shapes the sampling: one-sample MIS keeps any choice unbiased.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;  // == kWorkgroupSize

#include "shared/bindings/guide.h"

layout(scalar, binding = kGuideBuildCounts) readonly buffer Counts { uint64_t b_counts[]; };
layout(scalar, binding = kGuideBuildGuide) writeonly buffer Guide { float b_guide[]; };
layout(push_constant, scalar) uniform Push { uint u_cells; };

const float kUniformShare = 0.1;
const float kHalfTrust = 16.0;   // splats at which the guide takes half of its largest share
const float kLargestShare = 0.5;

void main() {
  const uint cell = gl_GlobalInvocationID.x;
  if (cell >= u_cells) return;
  const uint sums = cell * kGuideSumSlots;
  const uint base = cell * kGuideSlots;
  uint64_t total = 0ul;
  for (uint b = 0u; b < kGuideBins; ++b) total += b_counts[sums + b] - b_counts[sums + kGuideBins + b];
  const float splats = float(b_counts[sums + 2u * kGuideBins]);
  float cdf = 0.0;
  for (uint b = 0u; b < kGuideBins; ++b) {
    const uint64_t robust = b_counts[sums + b] - b_counts[sums + kGuideBins + b];
    const float learnt = total > 0ul ? float(robust) / float(total) : 0.0;
    cdf += (1.0 - kUniformShare) * learnt + kUniformShare / float(kGuideBins);
    b_guide[base + b] = cdf;
  }
  b_guide[base + kGuideBins - 1u] = 1.0;  // rounding never leaves a direction out
  b_guide[base + kGuideBins] = total > 0ul ? kLargestShare * splats / (splats + kHalfTrust) : 0.0;
}
