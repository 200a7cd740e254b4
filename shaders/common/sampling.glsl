// Sampling and small math helpers. Shared with C++ (see shared/glsl_cpp.h).
#ifndef HIPR_SAMPLING_GLSL
#define HIPR_SAMPLING_GLSL

#include "../shared/glsl_cpp.h"

const float kPi = 3.14159265358979f;
const float kInvPi = 0.31830988618379f;
const float kFloatMax = 3.0e38f;

HIPR_FN float max3(vec3 v) { return max(v.x, max(v.y, v.z)); }
HIPR_FN float luminance(vec3 c) { return dot(c, vec3(0.2126f, 0.7152f, 0.0722f)); }

// Orthonormal basis around unit n (Duff et al. 2017, branchless).
HIPR_FN void make_basis(vec3 n, OUT(vec3) t, OUT(vec3) b) {
  const float s = n.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (s + n.z);
  const float c = n.x * n.y * a;
  t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

HIPR_FN vec3 to_world(vec3 local, vec3 n) {
  vec3 t, b;
  make_basis(n, t, b);
  return local.x * t + local.y * b + local.z * n;
}

// Uniform point on the unit disc (Shirley and Chiu's concentric mapping: strata stay compact).
HIPR_FN vec2 sample_concentric_disk(vec2 u) {
  const vec2 d = 2.0f * u - 1.0f;
  vec2 p = vec2(0.0f);
  if (d.x != 0.0f || d.y != 0.0f) {
    float r, phi;
    if (abs(d.x) > abs(d.y)) {
      r = d.x;
      phi = (kPi / 4.0f) * (d.y / d.x);
    } else {
      r = d.y;
      phi = (kPi / 2.0f) - (kPi / 4.0f) * (d.x / d.y);
    }
    p = r * vec2(cos(phi), sin(phi));
  }
  return p;
}

// Cosine-weighted hemisphere around +Z (concentric disk mapping, then lift).
HIPR_FN vec3 sample_cosine_hemisphere(vec2 u) {
  const vec2 p = sample_concentric_disk(u);
  return vec3(p, sqrt(max(0.0f, 1.0f - dot(p, p))));
}

// Uniform over the hemisphere around +Z (pdf 1 / (2 pi)): for lobes that do not fall off
// toward the horizon, where cosine sampling would give unbounded weights.
HIPR_FN vec3 sample_uniform_hemisphere(vec2 u) {
  const float z = u.x;
  const float r = sqrt(max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  return vec3(r * cos(phi), r * sin(phi), z);
}

// Uniform point on a triangle as barycentrics (b1, b2) (Heitz 2019 low-distortion warp).
HIPR_FN vec2 sample_triangle(vec2 u) {
  if (u.y > u.x) {
    const float b0 = u.x * 0.5f;
    return vec2(b0, u.y - b0);
  }
  const float b1 = u.y * 0.5f;
  return vec2(u.x - b1, b1);
}

HIPR_FN float power_heuristic(float a, float b) {
  const float a2 = a * a;
  const float b2 = b * b;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

#endif
