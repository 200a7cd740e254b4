// Counter-based random numbers: a value depends only on (pixel, sample index, bounce,
// dimension block, seed), never on tile order or dispatch size, so any schedule of the same
// samples produces bit-identical pixels.
#ifndef HIPR_RNG_GLSL
#define HIPR_RNG_GLSL

// PCG-style 4D hash (Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 2020).
uvec4 rng_hash4(uvec4 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  v ^= v >> 16u;
  v.x += v.y * v.w;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v.w += v.y * v.z;
  return v;
}

struct PathRng {
  uint pixel;
  uint sampleIndex;
  uint seed;
};

// Four uniforms in [0,1) for (bounce, block). Blocks: 0 = BSDF, 1 = light, 2 = camera/misc.
vec4 rng_uniform4(PathRng rng, uint bounce, uint block) {
  const uvec4 h = rng_hash4(uvec4(rng.pixel, rng.sampleIndex, (bounce << 4u) | block, rng.seed));
  return vec4(h >> 8u) * (1.0 / 16777216.0);
}

#endif
