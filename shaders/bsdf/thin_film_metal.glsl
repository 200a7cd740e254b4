// OpenPBR's thin film over the metallic base: the same Airy sum as over the dielectric
// (thin_film.glsl), with the metal as a complex index n + ik per RGB channel. The index comes
// from the two colours the artist gives, after Gulbrandsen (2014): r = base colour (normal
// reflectance), g = specular_color (edge tint), n = g (1 - r) / (1 + r) + (1 - g)(1 + sqrt r) /
// (1 - sqrt r), k = sqrt(((n + 1)^2 r - (n - 1)^2) / (1 - r)), which reflects exactly r at
// normal incidence. Each channel is integrated over the spectrum as the dielectric film is
// (Belcour and Barla 2017), with that channel's index held constant across it, and keeps its
// own channel of the result; under a coat all indices are taken relative to the coat's.
// OpenPBR's reference evaluates one wavelength per channel instead; docs/openpbr.md gives the
// difference. Shared with C++.
#ifndef HIPR_THIN_FILM_METAL_GLSL
#define HIPR_THIN_FILM_METAL_GLSL

#include "thin_film.glsl"

// Gulbrandsen's complex index (n, k) for normal reflectance r (kept below 0.99, where k would
// diverge) and edge tint g.
HIPR_FN vec2 metal_complex_index(float r, float g) {
  r = clamp(r, 0.0f, 0.99f);
  g = clamp(g, 0.0f, 1.0f);
  const float sr = sqrt(r);
  const float n = g * (1.0f - r) / (1.0f + r) + (1.0f - g) * (1.0f + sr) / (1.0f - sr);
  const float k2 = ((n + 1.0f) * (n + 1.0f) * r - (n - 1.0f) * (n - 1.0f)) / (1.0f - r);
  return vec2(n, sqrt(max(k2, 0.0f)));
}

// Square root of a complex number, the branch with a non-negative real part.
HIPR_FN vec2 complex_sqrt(vec2 z) {
  const float m = length(z);
  const float re = sqrt(max(0.5f * (m + z.x), 0.0f));
  const float im = sqrt(max(0.5f * (m - z.x), 0.0f));
  return vec2(re, z.y < 0.0f ? -im : im);
}

// One channel: film of index film_ior on a metal of complex index nk, at cosine cos_i from index 1
// (indices relative to the medium above the film).
HIPR_FN float thin_film_metal_channel(float cos_i, float film_ior, vec2 nk, float thickness_nm, int channel) {
  const vec2 q0 = vec2(cos_i, 0.0f);
  const vec2 q1 = thin_film_q(film_ior, cos_i);
  const vec2 n2 = vec2(nk.x * nk.x - nk.y * nk.y, 2.0f * nk.x * nk.y);  // (n + ik)^2
  const vec2 q2 = complex_sqrt(n2 + vec2(cos_i * cos_i - 1.0f, 0.0f));
  const vec4 s = vec4(thin_film_r(q0, q1), thin_film_r(q1, q2));
  const vec2 p1 = q1 / (film_ior * film_ior);
  const vec4 p = vec4(thin_film_r(q0, p1), thin_film_r(p1, thin_film_div(q2, n2)));
  if (q1.y > 0.0f) {
    // Evanescent film (optically thinner than the medium above it, past its critical angle):
    // smooth in wavelength, evaluated at the channel's wavelength as over the dielectric.
    const float wavelength = channel == 0 ? 650.0f : (channel == 1 ? 532.0f : 450.0f);
    return clamp(0.5f * (thin_film_airy(s, q1, thickness_nm, wavelength) + thin_film_airy(p, q1, thickness_nm, wavelength)), 0.0f, 1.0f);
  }
  const float opd = 2.0f * thickness_nm * q1.x;
  const vec3 xyz = 0.5f * (thin_film_polarisation_xyz(s, opd) + thin_film_polarisation_xyz(p, opd));
  return clamp(thin_film_xyz_to_rgb(xyz)[channel], 0.0f, 1.0f);
}

// RGB reflectance of the film on the metal at cosine cos_i, seen from a medium of index
// `ambient` (1 in air; a coat's index under a coat): the film's and the metal's indices are taken
// relative to it.
HIPR_FN vec3 fresnel_thin_film_metal(float cos_i, float film_ior, vec3 f0, vec3 edge_tint, float thickness_nm, float ambient) {
  const float c = clamp(cos_i, 0.0f, 1.0f);
  if (c <= 0.0f) return vec3(1.0f);
  const float a = max(ambient, 1.0f);
  film_ior = max(film_ior, 1.0f) / a;  // OpenPBR keeps thin_film_ior at 1 or more
  thickness_nm = max(thickness_nm, 0.0f);
  vec3 result;
  for (int k = 0; k < 3; ++k)
    result[k] = thin_film_metal_channel(c, film_ior, metal_complex_index(f0[k], edge_tint[k]) / a, thickness_nm, k);
  return result;
}

// The metal's Fresnel with OpenPBR's film on it: F82-tint blended toward the filmed metal by
// thin_film_weight; films under 30 nm fade in (at zero thickness the film is gone, and the bare
// metal stays F82-tint rather than Gulbrandsen's conductor).
// film = (weight, ior, thickness nm, index of the medium above the film).
HIPR_FN vec3 metal_fresnel(vec3 f0, vec3 edge_tint, vec4 film, float cos_i) {
  const vec3 plain = fresnel_f82_tint(f0, edge_tint, cos_i);
  const float presence = clamp(film.x, 0.0f, 1.0f) * smoothstep(0.0f, 30.0f, film.z);
  if (presence <= 0.0f) return plain;
  return mix(plain, fresnel_thin_film_metal(cos_i, film.y, f0, edge_tint, film.z, film.w), presence);
}

#endif
