// Thin-film iridescence: one dielectric film (index film_ior, thickness in nm) on a
// dielectric base (index base_ior), lit from a medium of index 1. Reflectance is the Airy sum
// of all the waves bouncing inside the film, for s and p polarisation separately (averaged for
// unpolarised light), evaluated at one wavelength per RGB channel (650, 532, 450 nm) rather
// than integrated over the spectrum: cheap, and exact at those wavelengths.
// Amplitudes are complex, so one formula covers the phase flips at each interface and total
// internal reflection (an evanescent wave in the film when film_ior < 1, or TIR at the base
// when base_ior < 1, as when the base is seen from inside): no special cases, no NaN.
// Shared with C++.
#ifndef HIPR_THIN_FILM_GLSL
#define HIPR_THIN_FILM_GLSL

#include "fresnel.glsl"

const vec3 kThinFilmWavelengthsNm = vec3(650.0f, 532.0f, 450.0f);

// Complex numbers as vec2(real, imaginary).
HIPR_FN vec2 thin_film_mul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

// a / b, or 0 where b vanishes: that only happens between two media with the same index at
// grazing, where the interface reflects nothing.
HIPR_FN vec2 thin_film_div(vec2 a, vec2 b) {
  const float d = dot(b, b);
  return d > 1.0e-30f ? vec2(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / d : vec2(0.0f);
}

// n cos(theta) in a medium of index n, for light entering the stack from index 1 at cosine
// cos0 (Snell: n^2 cos^2 = n^2 - 1 + cos0^2, free of the cancellation in 1 - sin^2). Past the
// critical angle the square root is imaginary; the branch with a positive imaginary part makes
// the wave decay with depth.
HIPR_FN vec2 thin_film_q(float n, float cos0) {
  const float q2 = n * n - 1.0f + cos0 * cos0;
  return q2 >= 0.0f ? vec2(sqrt(q2), 0.0f) : vec2(0.0f, sqrt(-q2));
}

// Amplitude reflection coefficients going from medium a to medium b; the p form divides each
// q by n^2, which turns (n_b cos_a - n_a cos_b) / (n_b cos_a + n_a cos_b) into the s form.
HIPR_FN vec2 thin_film_r(vec2 qa, vec2 qb) { return thin_film_div(qa - qb, qa + qb); }

// |r|^2 of the film for one polarisation: r = (r01 + r12 e) / (1 + r01 r12 e), where
// e = exp(i delta) is the round trip through the film (phase and, if evanescent, decay).
HIPR_FN float thin_film_airy(vec2 r01, vec2 r12, vec2 e) {
  const vec2 r12e = thin_film_mul(r12, e);
  const vec2 r = thin_film_div(r01 + r12e, vec2(1.0f, 0.0f) + thin_film_mul(r01, r12e));
  return dot(r, r);
}

// RGB reflectance of the film stack at cosine cos_i (from the index-1 side). Indices are
// absolute (relative to that medium), kept above 1e-3 so the p terms never divide by zero.
HIPR_FN vec3 fresnel_thin_film(float cos_i, float film_ior, float base_ior, float thickness_nm) {
  const float c = clamp(cos_i, 0.0f, 1.0f);
  film_ior = max(film_ior, 1.0e-3f);
  base_ior = max(base_ior, 1.0e-3f);
  // At grazing every stack reflects everything (r01 = -1); this also skips the one 0/0 there.
  if (c <= 0.0f) return vec3(1.0f);
  const vec2 q0 = vec2(c, 0.0f);
  const vec2 q1 = thin_film_q(film_ior, c);
  const vec2 q2 = thin_film_q(base_ior, c);
  const float n1_2 = film_ior * film_ior;
  const float n2_2 = base_ior * base_ior;
  const vec2 r01s = thin_film_r(q0, q1), r12s = thin_film_r(q1, q2);
  const vec2 r01p = thin_film_r(q0, q1 / n1_2), r12p = thin_film_r(q1 / n1_2, q2 / n2_2);
  vec3 result = vec3(0.0f);
  for (int k = 0; k < 3; ++k) {
    // Round-trip phase 4 pi d n1 cos1 / lambda (complex when the film is evanescent).
    const vec2 delta = (4.0f * kPi * max(thickness_nm, 0.0f) / kThinFilmWavelengthsNm[k]) * q1;
    const vec2 e = exp(-delta.y) * vec2(cos(delta.x), sin(delta.x));
    result[k] = 0.5f * (thin_film_airy(r01s, r12s, e) + thin_film_airy(r01p, r12p, e));
  }
  return result;
}

// The specular Fresnel of a dielectric of index ior with OpenPBR's thin film on it:
// thin_film_weight in [0, 1] blends from the plain interface to the filmed one.
HIPR_FN vec3 fresnel_with_thin_film(float cos_i, float ior, float weight, float film_ior, float thickness_nm) {
  const vec3 plain = vec3(fresnel_dielectric(cos_i, ior));
  if (weight <= 0.0f) return plain;
  return mix(plain, fresnel_thin_film(cos_i, film_ior, ior, thickness_nm), min(weight, 1.0f));
}

#endif
