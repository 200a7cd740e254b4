// Equirectangular environment: lookup, importance sampling by luminance x sin(theta), and
// the matching solid-angle pdf. Texel-constant (nearest) lookups keep the pdf exact.
#ifndef HIPR_ENVIRONMENT_GLSL
#define HIPR_ENVIRONMENT_GLSL

#include "features.glsl"

uint env_texel_count() { return u_frame.environmentWidth * u_frame.environmentHeight; }
uint env_marginal_offset() { return 3u * env_texel_count(); }
uint env_conditional_offset(uint row) {
  return env_marginal_offset() + u_frame.environmentHeight + 1u + row * (u_frame.environmentWidth + 1u);
}

// Direction -> (u, v) in [0,1)^2; v = 0 is +Y (top row), u grows with the azimuth.
vec2 env_direction_to_uv(vec3 d) {
  const float phi = atan(d.x, -d.z) - u_frame.environmentRotation;
  const float theta = acos(clamp(d.y, -1.0, 1.0));
  return vec2(fract(phi * (0.5 * kInvPi) + 0.5), theta * kInvPi);
}

vec3 env_uv_to_direction(vec2 uv) {
  const float phi = (uv.x - 0.5) * 2.0 * kPi + u_frame.environmentRotation;
  const float theta = uv.y * kPi;
  const float s = sin(theta);
  return vec3(s * sin(phi), cos(theta), -s * cos(phi));
}

uvec2 env_texel(vec2 uv) {
  return min(uvec2(uv * vec2(u_frame.environmentWidth, u_frame.environmentHeight)),
             uvec2(u_frame.environmentWidth - 1u, u_frame.environmentHeight - 1u));
}

vec3 env_radiance(vec3 direction) {
  if (HIPR_FEATURE_ENVIRONMENT == 0 || u_frame.environmentLight == kInvalidIndex) return vec3(0.0);
  const uvec2 t = env_texel(env_direction_to_uv(direction));
  const uint i = 3u * (t.y * u_frame.environmentWidth + t.x);
  return vec3(b_env[i], b_env[i + 1u], b_env[i + 2u]) * u_frame.environmentIntensity;
}

// Pdf of a texel's probability mass within its CDF row.
float cdf_mass(uint offset, uint i) { return b_env[offset + i + 1u] - b_env[offset + i]; }

// Smallest i in [0, count) with cdf[i + 1] > u.
uint cdf_search(uint offset, uint count, float u) {
  uint lo = 0u, hi = count - 1u;
  while (lo < hi) {
    const uint mid = (lo + hi) >> 1u;
    if (b_env[offset + mid + 1u] > u) hi = mid;
    else lo = mid + 1u;
  }
  return lo;
}

float env_pdf(vec3 direction) {
  const vec2 uv = env_direction_to_uv(direction);
  const uvec2 t = env_texel(uv);
  const float sinTheta = sin(uv.y * kPi);
  if (sinTheta <= 0.0) return 0.0;
  const float mass = cdf_mass(env_marginal_offset(), t.y) * cdf_mass(env_conditional_offset(t.y), t.x);
  const float texelsPerUnit = float(u_frame.environmentWidth * u_frame.environmentHeight);
  return mass * texelsPerUnit / (2.0 * kPi * kPi * sinTheta);
}

vec3 env_sample(vec2 u, out float pdf) {
  const uint row = cdf_search(env_marginal_offset(), u_frame.environmentHeight, u.y);
  const uint col = cdf_search(env_conditional_offset(row), u_frame.environmentWidth, u.x);
  // Reuse the remainder of u inside the chosen texel for a continuous position.
  const float rowMass = cdf_mass(env_marginal_offset(), row);
  const float colMass = cdf_mass(env_conditional_offset(row), col);
  const float fy = rowMass > 0.0 ? clamp((u.y - b_env[env_marginal_offset() + row]) / rowMass, 0.0, 0.99999) : 0.5;
  const float fx = colMass > 0.0 ? clamp((u.x - b_env[env_conditional_offset(row) + col]) / colMass, 0.0, 0.99999) : 0.5;
  const vec2 uv = (vec2(col, row) + vec2(fx, fy)) / vec2(u_frame.environmentWidth, u_frame.environmentHeight);
  const vec3 direction = env_uv_to_direction(uv);
  const float sinTheta = sin(uv.y * kPi);
  const float texelsPerUnit = float(u_frame.environmentWidth * u_frame.environmentHeight);
  pdf = sinTheta > 0.0 ? rowMass * colMass * texelsPerUnit / (2.0 * kPi * kPi * sinTheta) : 0.0;
  return direction;
}

#endif
