// Fuzz as OpenPBR's top layer: the fuzz lobe's directional albedo E_fuzz(mu, roughness), read
// from the table tools/make_ggx_tables.cpp generates (arrays in C++; on the GPU the storage
// buffer kBindingBsdfTables at kFuzzEnergyOffset, so bindings.glsl must come first), and the
// scale of everything under the fuzz:
//   f = fuzz_weight fuzz_color f_fuzz + fuzz_layer_scale(...) f_under.
// Shared with C++.
#ifndef HIPR_FUZZ_LAYER_GLSL
#define HIPR_FUZZ_LAYER_GLSL

#include "fuzz.glsl"
#include "ggx_energy_table.glsl"

#ifdef __cplusplus
HIPR_FN float fuzz_energy_entry(int i) { return kFuzzEnergy[i]; }
#else
HIPR_FN float fuzz_energy_entry(int i) { return b_bsdf_tables[kFuzzEnergyOffset + i]; }
#endif

// Bilinear in (roughness, sqrt(mu)), the table's grid: kGgxTableSize rows of roughness,
// kFuzzTableMuSize columns of mu; roughness in [0, 1], mu = cos theta.
HIPR_FN float fuzz_energy(float mu, float roughness) {
  const float r = clamp(roughness, 0.0f, 1.0f) * float(kGgxTableSize - 1);
  const float m = sqrt(clamp(mu, 0.0f, 1.0f)) * float(kFuzzTableMuSize - 1);
  const int r0 = min(int(r), kGgxTableSize - 2);
  const int m0 = min(int(m), kFuzzTableMuSize - 2);
  const int i = r0 * kFuzzTableMuSize + m0;
  const float fm = m - float(m0);
  const float low = mix(fuzz_energy_entry(i), fuzz_energy_entry(i + 1), fm);
  const float high = mix(fuzz_energy_entry(i + kFuzzTableMuSize), fuzz_energy_entry(i + kFuzzTableMuSize + 1), fm);
  return mix(low, high, r - float(r0));
}

// What the fuzz leaves for the layers beneath it. Taking the larger albedo of the two
// directions keeps it symmetric (reciprocal) and never lets fuzz plus underlayer reflect more
// than a white underlayer alone: the fuzz takes w E(mu_o) and the rest is scaled by at most
// 1 - w E(mu_o). weight = fuzz_weight in [0, 1].
HIPR_FN float fuzz_layer_scale(float weight, float roughness, float mu_o, float mu_i) {
  const float w = clamp(weight, 0.0f, 1.0f);
  if (w == 0.0f) return 1.0f;
  return 1.0f - w * max(fuzz_energy(mu_o, roughness), fuzz_energy(mu_i, roughness));
}

#endif
