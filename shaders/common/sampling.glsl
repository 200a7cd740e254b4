#ifndef HIPR_SAMPLING_GLSL
#define HIPR_SAMPLING_GLSL

const float kPi = 3.14159265358979;
const float kInvPi = 0.31830988618379;
const float kFloatMax = 3.0e38;

float max3(vec3 v) { return max(v.x, max(v.y, v.z)); }
float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// Orthonormal basis around unit n (Duff et al. 2017, branchless).
void make_basis(vec3 n, out vec3 t, out vec3 b) {
  const float s = n.z >= 0.0 ? 1.0 : -1.0;
  const float a = -1.0 / (s + n.z);
  const float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

vec3 to_world(vec3 local, vec3 n) {
  vec3 t, b;
  make_basis(n, t, b);
  return local.x * t + local.y * b + local.z * n;
}

// Cosine-weighted hemisphere around +Z (concentric disk mapping, then lift).
vec3 sample_cosine_hemisphere(vec2 u) {
  const vec2 d = 2.0 * u - 1.0;
  vec2 p = vec2(0.0);
  if (d.x != 0.0 || d.y != 0.0) {
    float r, phi;
    if (abs(d.x) > abs(d.y)) {
      r = d.x;
      phi = (kPi / 4.0) * (d.y / d.x);
    } else {
      r = d.y;
      phi = (kPi / 2.0) - (kPi / 4.0) * (d.x / d.y);
    }
    p = r * vec2(cos(phi), sin(phi));
  }
  return vec3(p, sqrt(max(0.0, 1.0 - dot(p, p))));
}

// Uniform point on a triangle as barycentrics (b1, b2) (Heitz 2019 low-distortion warp).
vec2 sample_triangle(vec2 u) {
  if (u.y > u.x) {
    const float b0 = u.x * 0.5;
    return vec2(b0, u.y - b0);
  }
  const float b1 = u.y * 0.5;
  return vec2(u.x - b1, b1);
}

float power_heuristic(float a, float b) {
  const float a2 = a * a;
  const float b2 = b * b;
  return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
}

#endif
