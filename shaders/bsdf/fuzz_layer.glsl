// Fuzz as OpenPBR's top layer, by albedo scaling on the view side:
//   f = fuzz_weight fuzz_color f_fuzz + (1 - fuzz_weight E_fuzz(mu_o)) f_under,
// with E_fuzz the fuzz lobe's albedo (fuzz_energy). Seen from wo, the fuzz takes w E(mu_o) and
// hands the rest to the layers below, so a white stack under a white fuzz reflects exactly 1.
// Taking the light side into account too (reciprocal) loses energy: the larger of the two
// sides, used before, lost 13.7 % over white at normal incidence. OpenPBR's reference
// implementation scales by the view side by default, and the LTC lobe itself is not
// reciprocal (docs/openpbr.md). Shared with C++.
#ifndef HIPR_FUZZ_LAYER_GLSL
#define HIPR_FUZZ_LAYER_GLSL

#include "fuzz.glsl"

// What the fuzz leaves for the layers beneath it, seen from cos_o = mu_o. weight = fuzz_weight.
HIPR_FN float fuzz_layer_scale(float weight, float roughness, float mu_o) {
  const float w = clamp(weight, 0.0f, 1.0f);
  return w > 0.0f ? 1.0f - w * fuzz_energy(mu_o, roughness) : 1.0f;
}

#endif
