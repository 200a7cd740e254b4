// Reading and writing a DifferenceRecord (shared/abi.h): floats at a half's precision.
// The difference estimate itself: docs/method.md#the-difference-estimate.
#ifndef HIPR_COMMON_DIFFERENCE_GLSL
#define HIPR_COMMON_DIFFERENCE_GLSL

float record_value(DifferenceRecord record, uint k) { return record.values[k]; }

void set_record_value(inout DifferenceRecord record, uint k, float value) { record.values[k] = value; }

vec3 record_vec3(DifferenceRecord record, uint first) {
  return vec3(record.values[first], record.values[first + 1u], record.values[first + 2u]);
}

void set_record_vec3(inout DifferenceRecord record, uint first, vec3 value) {
  for (uint k = 0u; k < 3u; ++k) record.values[first + k] = value[k];
}

// The sums since the last edit start over (the kept samples stay).
void clear_record_sums(inout DifferenceRecord record) {
  for (uint k = kDifferenceSum; k < kDifferenceValues; ++k) record.values[k] = 0.0;
}

// `value` (>= 0) rounded to a half's precision (11 significant bits, ties to even), in float's
// range: what the record keeps. Values an edit did not change round alike, and values that
// differ only in bits the path's arithmetic does not fix (a rebuilt acceleration structure's
// rounding) do too. No clamp: a sample of any radiance keeps its value (the sun's 1e9 nits).
float half_precision(float value) {
  const float v = max(value, 0.0);
  if (v < 6.103515625e-05) return roundEven(v * 16777216.0) / 16777216.0;  // as half's subnormals: steps of 2^-24
  const uint bits = floatBitsToUint(v);
  if (bits >= 0x7f800000u) return v;  // infinity stays (NaN is 0 above)
  return uintBitsToFloat((bits + 0xfffu + ((bits >> 13u) & 1u)) & ~0x1fffu);
}

vec3 half_precision(vec3 value) { return vec3(half_precision(value.x), half_precision(value.y), half_precision(value.z)); }

// The weighted sums at `first` (kDifferenceCross, kDifferenceOld: 3 channels; kDifferenceSquares: 1).
vec3 record_sums(DifferenceRecord record, uint first) { return record_vec3(record, first); }
float record_squares(DifferenceRecord record) { return record.values[kDifferenceSquares]; }

// A weighted sum overflowed: a sample too bright for the record to judge.
bool record_saturated(DifferenceRecord record) {
  return isinf(record_squares(record)) || isnan(record_squares(record)) ||
         any(isinf(record_vec3(record, kDifferenceCross))) || any(isnan(record_vec3(record, kDifferenceCross))) ||
         any(isinf(record_vec3(record, kDifferenceOld))) || any(isnan(record_vec3(record, kDifferenceOld)));
}

// Some difference since the last edit is not zero.
bool record_changed(DifferenceRecord record) {
  return record_squares(record) > 0.0 || any(notEqual(record_vec3(record, kDifferenceSum), vec3(0.0)));
}

// The pixel's difference estimate judges it: some difference is not zero, and none was too
// bright for the record.
bool record_judges(DifferenceRecord record) { return record_changed(record) && !record_saturated(record); }

// How many kept samples belong to the stale estimate's scene state (DisplayTexel::flags).
uint texel_valid(uint flags) { return (flags >> kDifferenceValidShift) & kDifferenceValidMask; }

// The relMSE weights of the display rules (resolve_display.comp), per channel.
vec3 relmse_weight(vec3 stale) { return 1.0 / (stale * stale + 0.01); }

#endif
