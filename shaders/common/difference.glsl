// Reading and writing a DifferenceRecord (shared/abi.h): halves packed two to a uint.
// The difference estimate itself: docs/method.md#the-difference-estimate.
#ifndef HIPR_COMMON_DIFFERENCE_GLSL
#define HIPR_COMMON_DIFFERENCE_GLSL

// Half's largest finite value: larger values are clamped to it, on both sides of a difference.
const float kHalfMax = 65504.0;

float record_half(DifferenceRecord record, uint h) {
  const vec2 pair = unpackHalf2x16(record.halves[h >> 1u]);
  return (h & 1u) == 0u ? pair.x : pair.y;
}

void set_record_half(inout DifferenceRecord record, uint h, float value) {
  vec2 pair = unpackHalf2x16(record.halves[h >> 1u]);
  const float v = clamp(value, -kHalfMax, kHalfMax);
  if ((h & 1u) == 0u) pair.x = v;
  else pair.y = v;
  record.halves[h >> 1u] = packHalf2x16(pair);
}

vec3 record_vec3(DifferenceRecord record, uint first) {
  return vec3(record_half(record, first), record_half(record, first + 1u), record_half(record, first + 2u));
}

void set_record_vec3(inout DifferenceRecord record, uint first, vec3 value) {
  for (uint k = 0u; k < 3u; ++k) set_record_half(record, first + k, value[k]);
}

// The sums since the last edit start over (the kept samples stay).
void clear_record_sums(inout DifferenceRecord record) {
  for (uint h = kDifferenceSumHalf; h < kDifferenceHalves; ++h) set_record_half(record, h, 0.0);
}

// `value` (>= 0) rounded to the nearest half, ties to even, clamped to half's range: what the
// record keeps. Rounded by hand, not by unpackHalf2x16(packHalf2x16(v)): compilers may fold
// that pair away (lavapipe does), which left a new sample's float against an old one's half.
float half_rounded(float value) {
  const float v = clamp(value, 0.0, kHalfMax);
  if (v < 6.103515625e-05) return roundEven(v * 16777216.0) / 16777216.0;  // half subnormals: steps of 2^-24
  const uint bits = floatBitsToUint(v);
  return min(uintBitsToFloat((bits + 0xfffu + ((bits >> 13u) & 1u)) & ~0x1fffu), kHalfMax);
}

vec3 half_rounded(vec3 value) { return vec3(half_rounded(value.x), half_rounded(value.y), half_rounded(value.z)); }

// The weighted sums at `first` (kDifferenceCrossHalf, kDifferenceOldHalf: 3 channels;
// kDifferenceSquaresHalf: 1), unscaled.
vec3 record_sums(DifferenceRecord record, uint first) { return record_vec3(record, first) / kDifferenceSumScale; }
float record_squares(DifferenceRecord record) { return record_half(record, kDifferenceSquaresHalf) / kDifferenceSumScale; }

// A weighted sum reached half's range: a sample too bright for the record to judge.
bool record_saturated(DifferenceRecord record) {
  return record_half(record, kDifferenceSquaresHalf) >= kHalfMax || any(greaterThanEqual(abs(record_vec3(record, kDifferenceCrossHalf)), vec3(kHalfMax))) ||
         any(greaterThanEqual(record_vec3(record, kDifferenceOldHalf), vec3(kHalfMax)));
}

// Some difference since the last edit is not zero.
bool record_changed(DifferenceRecord record) {
  return record_half(record, kDifferenceSquaresHalf) > 0.0 || any(notEqual(record_vec3(record, kDifferenceSumHalf), vec3(0.0)));
}

// The pixel's difference estimate judges it: some difference is not zero, and none was too
// bright for the record.
bool record_judges(DifferenceRecord record) { return record_changed(record) && !record_saturated(record); }

// How many kept samples belong to the stale estimate's scene state (DisplayTexel::flags).
uint texel_valid(uint flags) { return (flags >> kDifferenceValidShift) & kDifferenceValidMask; }

// The relMSE weights of the display rules (resolve_display.comp), per channel.
vec3 relmse_weight(vec3 stale) { return 1.0 / (stale * stale + 0.01); }

#endif
