#version 460
// Stable LSD radix sort of 32-bit keys with 32-bit values, 8 bits per pass, any count.
// HIPR_SORT_STAGE 0: per-workgroup digit histograms -> hist[digit * groups + group].
// HIPR_SORT_STAGE 1: one workgroup turns hist into exclusive offsets (digit-major order).
// HIPR_SORT_STAGE 2: scatter. Thread d of a workgroup walks the block's keys in order and
//                    places those with digit d, so equal digits keep their order (stable)
//                    without depending on the subgroup size.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 256) in;  // == kSortBlock == kSortRadix

#include "shared/bindings/schedule.h"
#include "common/dispatch.glsl"

layout(push_constant, scalar) uniform Push { SortPush u_push; };
layout(scalar, binding = kSortKeys) buffer Keys { uint b_keys[]; };
layout(scalar, binding = kSortValues) buffer Values { uint b_values[]; };
layout(scalar, binding = kSortKeysAlt) buffer KeysAlt { uint b_keys_alt[]; };
layout(scalar, binding = kSortValuesAlt) buffer ValuesAlt { uint b_values_alt[]; };
layout(scalar, binding = kSortHistogram) buffer Histogram { uint b_hist[]; };

shared uint s_keys[kSortBlock];
shared uint s_values[kSortBlock];
shared uint s_sums[kSortRadix];

uint read_key(uint i) { return u_push.pingToPong != 0u ? b_keys[i] : b_keys_alt[i]; }
uint read_value(uint i) { return u_push.pingToPong != 0u ? b_values[i] : b_values_alt[i]; }
uint digit_of(uint key) { return (key >> u_push.shift) & 0xffu; }

void main() {
  const uint group = dispatch_group();
  const uint lane = gl_LocalInvocationIndex;
#if HIPR_SORT_STAGE != 1
  if (group >= u_push.groups) return;  // past the blocks, in a folded dispatch's last row
#endif
#if HIPR_SORT_STAGE == 0
  s_sums[lane] = 0u;
  barrier();
  const uint i = group * kSortBlock + lane;
  if (i < u_push.count) atomicAdd(s_sums[digit_of(read_key(i))], 1u);
  barrier();
  b_hist[lane * u_push.groups + group] = s_sums[lane];
#elif HIPR_SORT_STAGE == 1
  // Each lane sums a contiguous chunk, lanes are scanned in shared memory, then each lane
  // writes its chunk's exclusive offsets.
  const uint total = kSortRadix * u_push.groups;
  const uint chunk = (total + kSortRadix - 1u) / kSortRadix;
  const uint begin = min(lane * chunk, total);
  const uint end = min(begin + chunk, total);
  uint sum = 0u;
  for (uint k = begin; k < end; ++k) sum += b_hist[k];
  s_sums[lane] = sum;
  barrier();
  if (lane == 0u) {
    uint running = 0u;
    for (uint k = 0u; k < kSortRadix; ++k) {
      const uint v = s_sums[k];
      s_sums[k] = running;
      running += v;
    }
  }
  barrier();
  uint running = s_sums[lane];
  for (uint k = begin; k < end; ++k) {
    const uint v = b_hist[k];
    b_hist[k] = running;
    running += v;
  }
#else
  const uint i = group * kSortBlock + lane;
  const uint n = min(kSortBlock, u_push.count - group * kSortBlock);
  if (lane < n) {
    s_keys[lane] = read_key(i);
    s_values[lane] = read_value(i);
  }
  barrier();
  uint out_index = b_hist[lane * u_push.groups + group];
  for (uint k = 0u; k < n; ++k) {
    if (digit_of(s_keys[k]) != lane) continue;
    if (u_push.pingToPong != 0u) {
      b_keys_alt[out_index] = s_keys[k];
      b_values_alt[out_index] = s_values[k];
    } else {
      b_keys[out_index] = s_keys[k];
      b_values[out_index] = s_values[k];
    }
    out_index += 1u;
  }
#endif
}
