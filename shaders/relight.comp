#version 460
// Relighting by linearity (docs/method.md#relighting), at an edit that only scaled emitters'
// intensity or colour: radiance is a sum over emitters, linear in each, so every pixel's best
// estimate of the scene before the edit, split into light groups, becomes an unbiased estimate
// of the edited scene by scaling each group's share. It becomes the stale estimate and is shown
// at once; fresh samples then take over by the display rule as after any edit.
// Reads:  per-pixel accumulation and its light-group shares (the estimate of the scene before
//         the edit, where it is current), RelightPush's factor per group.
// Writes: the display texels (stale = shown = the relit value; no kept samples of its scene state
//         for the difference estimate: the relit value is already the edited scene's estimate, a
//         difference from the old scene would count the edit twice) and the stale estimate's shares.
// Per pixel, the estimate relit is the accumulation when it holds samples of the scene as it
// was and at least as many as the stale estimate, else the stale estimate when its groups are
// known (an earlier relight: a slider dragged). Other pixels (owing an earlier, non-linear edit)
// keep what they show.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;  // == kWorkgroupSize

#include "shared/bindings/relight.h"

layout(scalar, binding = kRelightAccumulation) readonly buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kRelightGroupSums) readonly buffer GroupSums { vec3 b_group_sums[]; };
layout(scalar, binding = kRelightDisplay) buffer Display { DisplayTexel b_display[]; };
layout(scalar, binding = kRelightStaleGroups) buffer StaleGroups { vec3 b_stale_groups[]; };
layout(push_constant, scalar) uniform Push { RelightPush u_push; };

void main() {
  const uint index = gl_GlobalInvocationID.x;
  if (index >= u_push.pixelCount) return;
  const uint groups = u_push.groupCount;
  const PixelAccum accum = b_accum[index];
  DisplayTexel texel = b_display[index];
  const uint n = accum.count & kPixelCountMask;
  const bool current = (accum.count & kPixelOwed) == 0u && n > 0u;
  const bool staleGrouped = (texel.flags & kStaleGrouped) != 0u;
  const bool fromAccumulation = current && (n >= texel.staleSamples || !staleGrouped);
  if (!fromAccumulation && !staleGrouped) return;

  const vec3 total = fromAccumulation ? accum.sum / float(n) : texel.stale;
  // What no group holds (pooled emitters) stays; each group's share is scaled.
  vec3 rest = total;
  vec3 relit = vec3(0.0);
  for (uint g = 0u; g < groups; ++g) {
    const vec3 share = fromAccumulation ? b_group_sums[index * groups + g] / float(n) : b_stale_groups[index * groups + g];
    rest -= share;
    const vec3 scaled = share * u_push.factors[g];
    relit += scaled;
    b_stale_groups[index * groups + g] = scaled;
  }
  // Rounding can leave the rest a hair below zero where groups hold everything.
  const vec3 value = max(max(rest, vec3(0.0)) + relit, vec3(0.0));
  texel.stale = value;
  texel.shown = value;
  texel.staleSamples = fromAccumulation ? n : texel.staleSamples;
  texel.shownSamples = texel.staleSamples;
  texel.staleRecord = texel.shownRecord;
  texel.staleNormal = texel.shownNormal;
  texel.flags = kShownGrouped | kStaleGrouped | kShownCurrent | kStaleCurrent;
  b_display[index] = texel;
}
