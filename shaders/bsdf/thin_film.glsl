// Thin-film iridescence: one dielectric film (index film_ior, thickness in nm) on a
// dielectric base (index base_ior), lit from a medium of index 1. Reflectance is the Airy sum
// of all the waves bouncing inside the film, for s and p polarisation separately (averaged for
// unpolarised light), integrated over the visible spectrum into RGB after Belcour and Barla
// (2017): written as a Fourier series in the film's round-trip phase, each term meets the
// colour matching functions in closed form (thin_film_spectral.glsl).
// Amplitudes are complex, so one formula covers the phase flips at each interface and total
// internal reflection at the base (base_ior < 1, as when the base is seen from inside): no
// special cases, no NaN. A film of index < 1 past its critical angle carries no oscillating
// wave, only a decaying one; that case is evaluated at 650, 532 and 450 nm instead.
// Shared with C++.
#ifndef HIPR_THIN_FILM_GLSL
#define HIPR_THIN_FILM_GLSL

#include "fresnel.glsl"
#include "thin_film_spectral.glsl"

// Fourier terms evaluated one by one; the rest is summed in closed form (see below).
const int kThinFilmHarmonics = 4;

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

// Amplitude reflection coefficient from medium a to medium b given q = n cos. For p, pass
// q / n^2: that turns (n_b cos_a - n_a cos_b) / (n_b cos_a + n_a cos_b) into this same form.
HIPR_FN vec2 thin_film_r(vec2 qa, vec2 qb) { return thin_film_div(qa - qb, qa + qb); }

// Both interfaces for both polarisations: s = (r01, r12), p = (r01, r12), complex each
// (no swizzles: the C++ side's glm has them off).
HIPR_FN void thin_film_interfaces(float cos0, float film_ior, float base_ior, OUT(vec2) q1, OUT(vec4) s, OUT(vec4) p) {
  const vec2 q0 = vec2(cos0, 0.0f);
  q1 = thin_film_q(film_ior, cos0);
  const vec2 q2 = thin_film_q(base_ior, cos0);
  s = vec4(thin_film_r(q0, q1), thin_film_r(q1, q2));
  const vec2 p1 = q1 / (film_ior * film_ior);
  p = vec4(thin_film_r(q0, p1), thin_film_r(p1, q2 / (base_ior * base_ior)));
}

// |r|^2 for one polarisation at one wavelength: r = (r01 + r12 e) / (1 + r01 r12 e), where
// e = exp(i delta) is the round trip through the film, delta = 4 pi d q1 / lambda (complex
// when the film is evanescent: a decay, not a phase).
HIPR_FN float thin_film_airy(vec4 r, vec2 q1, float thickness_nm, float wavelength_nm) {
  const vec2 delta = (4.0f * kPi * thickness_nm / wavelength_nm) * q1;
  const vec2 e = exp(-delta.y) * vec2(cos(delta.x), sin(delta.x));
  const vec2 r01 = vec2(r.x, r.y);
  const vec2 r12e = thin_film_mul(vec2(r.z, r.w), e);
  const vec2 total = thin_film_div(r01 + r12e, vec2(1.0f, 0.0f) + thin_film_mul(r01, r12e));
  return dot(total, total);
}

// Index and angle handling shared by both entry points: the cosine from the index-1 side,
// indices kept above 1e-3 so the p terms never divide by zero, thickness >= 0.
HIPR_FN float thin_film_clamp_inputs(INOUT(float) film_ior, INOUT(float) base_ior, INOUT(float) thickness_nm, float cos_i) {
  film_ior = max(film_ior, 1.0e-3f);
  base_ior = max(base_ior, 1.0e-3f);
  thickness_nm = max(thickness_nm, 0.0f);
  return clamp(cos_i, 0.0f, 1.0f);
}

// Unpolarised reflectance at a single wavelength, exactly (for checks, and for the
// evanescent case).
HIPR_FN float thin_film_reflectance(float cos_i, float film_ior, float base_ior, float thickness_nm, float wavelength_nm) {
  const float c = thin_film_clamp_inputs(film_ior, base_ior, thickness_nm, cos_i);
  if (c <= 0.0f) return 1.0f;
  vec2 q1;
  vec4 s, p;
  thin_film_interfaces(c, film_ior, base_ior, q1, s, p);
  return 0.5f * (thin_film_airy(s, q1, thickness_nm, wavelength_nm) + thin_film_airy(p, q1, thickness_nm, wavelength_nm));
}

// One polarisation over the spectrum, in XYZ. With r01 real (the film is not evanescent),
// rho = |r12|, phi = arg r12, x = r01 rho, K = (1 - r01^2)(1 - rho^2) and
// theta = 2 pi opd / lambda + phi, the Airy reflectance is
//   R = 1 - K / (1 + x^2 + 2 x cos theta) = C0 + C sum_m (-x)^m cos(m theta),
// with C0 = 1 - K / (1 - x^2), C = -2 K / (1 - x^2). Term m oscillates in 1 / lambda with
// opd m, so its spectral integral is C (-x)^m sensitivity(m opd, m phi).
HIPR_FN vec3 thin_film_polarisation_xyz(vec4 r, float opd_nm) {
  const float r01 = r.x;
  const float rho = length(vec2(r.z, r.w));
  // GLSL leaves atan(0, 0) undefined, and a NaN phase would survive its zero weight.
  const float phi = rho > 0.0f ? atan(r.w, r.z) : 0.0f;
  const float x = r01 * rho;
  const float one_minus_x2 = 1.0f - x * x;
  // |x| -> 1 only when the first interface reflects everything (grazing): R = 1.
  if (one_minus_x2 < 1.0e-6f) return vec3(1.0f);
  const float k = (1.0f - r01 * r01) * (1.0f - rho * rho) / one_minus_x2;
  vec3 xyz = vec3(1.0f - k);
  float power = 1.0f;
  for (int m = 1; m <= kThinFilmHarmonics; ++m) {
    power *= -x;
    xyz += (-2.0f * k * power) * thin_film_sensitivity(float(m) * opd_nm, float(m) * phi);
  }
  // The terms past the last: with w = -x exp(i theta), sum_{m > M} w^m = w^(M+1) / (1 - w),
  // taken at the centre of the visible band and damped like term M + 1. Exact for opd = 0
  // (a film of no thickness is then exactly the bare base); they matter only where both
  // interfaces reflect strongly, near grazing.
  const float theta = 2.0f * kPi * opd_nm / kThinFilmCentreNm + phi;
  const vec2 w = -x * vec2(cos(theta), sin(theta));
  vec2 w_power = w;
  for (int m = 0; m < kThinFilmHarmonics; ++m) w_power = thin_film_mul(w_power, w);
  const float tail = thin_film_div(w_power, vec2(1.0f, 0.0f) - w).x;
  const float p = 2.0e-9f * kPi * float(kThinFilmHarmonics + 1) * opd_nm;
  xyz += vec3(-2.0f * k * tail * exp(-kThinFilmCentreVariance * p * p));
  return xyz;
}

// RGB reflectance of the film stack at cosine cos_i (from the index-1 side), in [0, 1].
HIPR_FN vec3 fresnel_thin_film(float cos_i, float film_ior, float base_ior, float thickness_nm) {
  const float c = thin_film_clamp_inputs(film_ior, base_ior, thickness_nm, cos_i);
  // At grazing every stack reflects everything (r01 = -1); this also skips the one 0/0 there.
  if (c <= 0.0f) return vec3(1.0f);
  vec2 q1;
  vec4 s, p;
  thin_film_interfaces(c, film_ior, base_ior, q1, s, p);
  if (q1.y > 0.0f) {
    // Evanescent film: smooth in wavelength, so three samples represent it well.
    vec3 result = vec3(0.0f);
    for (int k = 0; k < 3; ++k) {
      const float wavelength = k == 0 ? 650.0f : (k == 1 ? 532.0f : 450.0f);
      result[k] = 0.5f * (thin_film_airy(s, q1, thickness_nm, wavelength) + thin_film_airy(p, q1, thickness_nm, wavelength));
    }
    return clamp(result, vec3(0.0f), vec3(1.0f));
  }
  // Optical path difference of one round trip: 2 d n1 cos(theta_1) = 2 d q1.
  const float opd = 2.0f * thickness_nm * q1.x;
  const vec3 xyz = 0.5f * (thin_film_polarisation_xyz(s, opd) + thin_film_polarisation_xyz(p, opd));
  // Interference colours can lie outside the RGB gamut; clamping keeps reflectance physical.
  return clamp(thin_film_xyz_to_rgb(xyz), vec3(0.0f), vec3(1.0f));
}

// The specular Fresnel of a dielectric of index ior with OpenPBR's thin film on it:
// thin_film_weight in [0, 1] blends from the plain interface to the filmed one.
HIPR_FN vec3 fresnel_with_thin_film(float cos_i, float ior, float weight, float film_ior, float thickness_nm) {
  const vec3 plain = vec3(fresnel_dielectric(cos_i, ior));
  if (weight <= 0.0f) return plain;
  return mix(plain, fresnel_thin_film(cos_i, film_ior, ior, thickness_nm), min(weight, 1.0f));
}

#endif
