// What the eye makes of a spectrum that oscillates like cos(2 pi opd / lambda + shift): the
// CIE 1931 colour matching functions integrated against it, in closed form. Belcour and Barla
// (2017) fit each matching function with Gaussians in wavenumber, whose Fourier transforms are
// Gaussians again; we use their fitted constants, each channel normalised so that a flat
// spectrum (opd = 0, shift = 0) gives exactly 1. Large opd averages out to 0: thick films turn
// white instead of aliasing into false colours. Then XYZ to linear Rec.709, balanced so that
// a flat spectrum stays grey. Shared with C++.
#ifndef HIPR_THIN_FILM_SPECTRAL_GLSL
#define HIPR_THIN_FILM_SPECTRAL_GLSL

#include "../common/sampling.glsl"

// One Gaussian lobe: weight * cos(mean * p + shift) * exp(-variance * p^2), p = 2 pi opd in
// metres (mean in 1/m, as fitted).
HIPR_FN float thin_film_lobe(float weight, float mean, float variance, float p, float shift) {
  return weight * cos(mean * p + shift) * exp(-variance * p * p);
}

HIPR_FN vec3 thin_film_sensitivity(float opd_nm, float shift) {
  const float p = 2.0e-9f * kPi * opd_nm;
  // weight = amplitude * sqrt(2 pi variance) of the fit, divided by the channel's total.
  const float x = thin_film_lobe(0.846202f, 1.6810e6f, 4.3278e9f, p, shift) +
                  thin_film_lobe(0.153798f, 2.2399e6f, 4.5282e9f, p, shift);
  const float y = thin_film_lobe(1.0f, 1.7953e6f, 9.3046e9f, p, shift);
  const float z = thin_film_lobe(1.0f, 2.2084e6f, 6.6121e9f, p, shift);
  return vec3(x, y, z);
}

// The Y channel's centre wavelength (1 / mean wavenumber) and spread, for terms that are
// treated as one narrow band.
const float kThinFilmCentreNm = 557.0f;
const float kThinFilmCentreVariance = 9.3046e9f;

HIPR_FN vec3 thin_film_xyz_to_rgb(vec3 xyz) {
  const vec3 r = vec3(3.2404542f, -1.5371385f, -0.4985314f);
  const vec3 g = vec3(-0.9692660f, 1.8760108f, 0.0415560f);
  const vec3 b = vec3(0.0556434f, -0.2040259f, 1.0572252f);
  // Divide by the image of XYZ = (1, 1, 1), the flat spectrum: it must stay grey.
  return vec3(dot(r, xyz), dot(g, xyz), dot(b, xyz)) / vec3(r.x + r.y + r.z, g.x + g.y + g.z, b.x + b.y + b.z);
}

#endif
