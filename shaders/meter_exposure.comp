#version 460
// The viewer's automatic exposure, on the device: a histogram of what the display shows, by the
// log2 of each lit pixel's luminance (Rec. 709), from which the host reads the 90th percentile
// (image/auto_exposure.h). 4 KB cross to the host instead of the display (56 bytes a pixel:
// 116 MB at 1920x1080, every eighth frame).
// Reads: the display (`shown`). Adds to: the histogram (cleared before).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

#include "shared/bindings/exposure.h"

// Declared before dispatch.glsl: its gl_WorkGroupSize is this size only after the declaration.
layout(local_size_x = kMeterWorkgroupSize) in;
#include "common/dispatch.glsl"

layout(push_constant) uniform Push { uint pixelCount; } u_push;
layout(scalar, binding = kMeterDisplay) readonly buffer Display { DisplayTexel b_display[]; };
layout(scalar, binding = kMeterHistogram) buffer Histogram { uint b_histogram[]; };

// Each workgroup counts its pixels in shared memory and adds its non-empty bins once: at 1080p
// every pixel's atomic on the device's histogram would contend on the few bins an image fills.
shared uint s_bins[kMeterBins];

void main() {
  for (uint bin = gl_LocalInvocationIndex; bin < kMeterBins; bin += gl_WorkGroupSize.x) s_bins[bin] = 0u;
  barrier();
  const uint index = dispatch_index();
  if (index < u_push.pixelCount) {
    const vec3 c = b_display[index].shown;
    const float y = dot(c, vec3(0.2126, 0.7152, 0.0722));
    if (!isnan(y) && !isinf(y) && y > 0.0) {  // else unlit or not a number: not metered
      const float bin = floor((log2(y) - float(kMeterLowestStop)) * float(kMeterBinsPerStop));
      atomicAdd(s_bins[uint(clamp(bin, 0.0, float(kMeterBins - 1u)))], 1u);
    }
  }
  barrier();
  for (uint bin = gl_LocalInvocationIndex; bin < kMeterBins; bin += gl_WorkGroupSize.x)
    if (s_bins[bin] != 0u) atomicAdd(b_histogram[bin], s_bins[bin]);
}
