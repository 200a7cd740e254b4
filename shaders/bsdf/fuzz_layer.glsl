// Fuzz as OpenPBR's top layer: the scale of everything under the fuzz, from the fuzz lobe's
// directional albedo E_fuzz(mu, roughness) (fuzz_energy in energy_tables.glsl):
//   f = fuzz_weight fuzz_color f_fuzz + fuzz_layer_scale(...) f_under.
// Shared with C++.
#ifndef HIPR_FUZZ_LAYER_GLSL
#define HIPR_FUZZ_LAYER_GLSL

#include "fuzz.glsl"
#include "energy_tables.glsl"

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
