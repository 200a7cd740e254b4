// Lookups of the generated albedo tables (ggx_energy_table.glsl, made by
// tools/make_ggx_tables.cpp): interpolation on the generator's grids. Roughness is recovered
// from alpha as sqrt(alpha). Shared with C++.
#ifndef HIPR_ENERGY_TABLES_GLSL
#define HIPR_ENERGY_TABLES_GLSL

#include "../common/sampling.glsl"
#include "ggx_energy_table.glsl"

// C++ reads the generated array; kernels read the same numbers from a storage buffer.
#ifdef __cplusplus
HIPR_FN float bsdf_table(int i) { return kBsdfTables[i]; }
#else
HIPR_FN float bsdf_table(int i) { return b_bsdf_tables[i]; }
#endif

// Continuous grid coordinate of `t` in [0, 1] on `size` points: the lower index and weight.
HIPR_FN int table_cell(float t, int size, OUT(float) weight) {
  const float x = clamp(t, 0.0f, 1.0f) * float(size - 1);
  const int i = min(int(x), size - 2);
  weight = x - float(i);
  return i;
}

// Bilinear lookup of a [row][column] table of rows x columns at (row t, column s).
HIPR_FN float table_2d(int offset, int rows, int columns, float t_row, float s_column) {
  float fr, fc;
  const int r = table_cell(t_row, rows, fr);
  const int c = table_cell(s_column, columns, fc);
  const int i = offset + r * columns + c;
  const float low = mix(bsdf_table(i), bsdf_table(i + 1), fc);
  const float high = mix(bsdf_table(i + columns), bsdf_table(i + columns + 1), fc);
  return mix(low, high, fr);
}

HIPR_FN float table_1d(int offset, int size, float t) {
  float f;
  const int i = table_cell(t, size, f);
  return mix(bsdf_table(offset + i), bsdf_table(offset + i + 1), f);
}

// Index coordinate of the dielectric tables: (n - 1) / (n + 1) over [0, 0.5] with n >= 1.
HIPR_FN float eta_coordinate(float eta) {
  const float n = eta < 1.0f ? 1.0f / max(eta, 1.0e-4f) : eta;
  return 2.0f * (n - 1.0f) / (n + 1.0f);
}

// GGX reflection albedo with F = 1 at cos_o = mu, and its cosine-weighted average.
HIPR_FN float ggx_energy(float mu, float alpha) {
  return table_2d(kTableGgxEnergy, kGgxTableSize, kGgxTableSize, sqrt(alpha), sqrt(max(mu, 0.0f)));
}

HIPR_FN float ggx_energy_average(float alpha) { return table_1d(kTableGgxEnergyAverage, kGgxTableSize, sqrt(alpha)); }

// Trilinear in (eta, roughness, sqrt(mu)) over a [eta][roughness][mu] table.
HIPR_FN float dielectric_table(int offset, float mu, float alpha, float eta) {
  const int n = kDielectricTableSize;
  float fe;
  const int e = table_cell(eta_coordinate(eta), kDielectricTableEtaSize, fe);
  const float low = table_2d(offset + e * n * n, n, n, sqrt(alpha), sqrt(max(mu, 0.0f)));
  const float high = table_2d(offset + (e + 1) * n * n, n, n, sqrt(alpha), sqrt(max(mu, 0.0f)));
  return mix(low, high, fe);
}

// Albedo of dielectric reflection alone (exact Fresnel), entering (eta > 1) or leaving.
HIPR_FN float dielectric_reflection_energy(float mu, float alpha, float eta) {
  return dielectric_table(eta >= 1.0f ? kTableDielectricReflection : kTableDielectricReflectionLeaving, mu, alpha, eta);
}

HIPR_FN float dielectric_reflection_energy_average(float alpha, float eta) {
  const int n = kDielectricTableSize;
  const int offset = eta >= 1.0f ? kTableDielectricReflectionAverage : kTableDielectricReflectionLeavingAverage;
  float fe;
  const int e = table_cell(eta_coordinate(eta), kDielectricTableEtaSize, fe);
  const float low = table_1d(offset + e * n, n, sqrt(alpha));
  const float high = table_1d(offset + (e + 1) * n, n, sqrt(alpha));
  return mix(low, high, fe);
}

// Albedo of reflection plus refraction of a rough interface, entering (eta > 1) or leaving.
HIPR_FN float dielectric_interface_energy(float mu, float alpha, float eta) {
  return dielectric_table(eta >= 1.0f ? kTableDielectricEntering : kTableDielectricLeaving, mu, alpha, eta);
}

#endif
