// Unit vectors in one word: the denoiser's guide normals, the G-buffer's geometric normals.
#ifndef HIPR_OCTAHEDRAL_GLSL
#define HIPR_OCTAHEDRAL_GLSL

// Octahedral map of a unit vector to two snorm16 (Cigolle et al. 2014): 4 bytes per normal,
// under 1e-4 rad of error, enough for an edge test that cares about degrees.
uint pack_normal(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 e = n.xy;
  if (n.z < 0.0) e = (1.0 - abs(n.yx)) * mix(vec2(-1.0), vec2(1.0), greaterThanEqual(n.xy, vec2(0.0)));
  return packSnorm2x16(e);
}

vec3 unpack_normal(uint packed) {
  const vec2 e = unpackSnorm2x16(packed);
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  const float t = max(-n.z, 0.0);
  n.xy += mix(vec2(t), vec2(-t), greaterThanEqual(n.xy, vec2(0.0)));
  return normalize(n);
}

// Whether two G-buffer normals (kNormalUnknown: not known) are of different faces of a surface.
bool surface_turned(uint a, uint b) {
  return a != kNormalUnknown && b != kNormalUnknown && dot(unpack_normal(a), unpack_normal(b)) < kSurfaceTurnCosine;
}

#endif
