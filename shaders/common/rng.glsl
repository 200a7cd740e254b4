// The random numbers of a path. A value depends only on (pixel, sample index, bounce, dimension
// block, seed, sampler), never on tile order or dispatch size, so any schedule of the same
// samples produces bit-identical pixels. Shared with C++ (see shared/glsl_cpp.h): tests check
// the very code the kernels run.
//
// Two samplers (FrameParams::sampleSequence, from RenderSettings::sampler):
// - kSamplerSobol: each 4-dimension block of a path (the camera jitter, the light sample of a
//   bounce, the BSDF sample of a bounce) is its own 4D Sobol sequence, Owen-scrambled and with
//   its sample indices shuffled by a nested uniform scramble, both seeded by a hash of
//   (pixel, block, seed) (Burley, "Practical Hash-based Owen Scrambling", JCGT 2020). Padding
//   blocks by independent shuffles keeps any two blocks uncorrelated; within a block, the first
//   2^m samples of dimensions 0 and 1 form a (0,m,2)-net, whatever the batch sizes that reached
//   them: a pixel's samples 0..n-1 are the same points however they were split.
// - kSamplerRandom: independent uniform hashes (the sampler before Sobol, kept for comparison).
#ifndef HIPR_RNG_GLSL
#define HIPR_RNG_GLSL

#include "../shared/abi.h"
#include "../shared/glsl_cpp.h"
#include "sobol_matrices.glsl"

// PCG-style 4D hash (Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 2020).
HIPR_FN uvec4 rng_hash4(uvec4 v) {
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

// [0,1) from the top 24 bits: every value is a float, and 1 is never reached.
HIPR_FN float rng_unit_float(uint bits) { return float(bits >> 8u) * (1.0f / 16777216.0f); }

// A random bijection of 32-bit words in which output bit i depends only on input bits 0..i
// (every step adds or XORs multiples of lower bits): the hash of Laine & Karras (2011) with
// Burley's and Vegdahl's constants.
HIPR_FN uint rng_laine_karras(uint x, uint seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16u) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

// Owen scrambling of a binary fraction: bit i from the top flips by a random function of the
// bits above it, so points that share a dyadic interval stay together in a random one.
HIPR_FN uint rng_nested_uniform_scramble(uint x, uint seed) {
  return bitfieldReverse(rng_laine_karras(bitfieldReverse(x), seed));
}

// Dimensions 1..3 of Sobol point `index` (dimension 0 is bitfieldReverse(index)). The
// direction numbers follow their recurrences in registers: a table indexed in a loop is slow
// on CPU Vulkan devices. kSobolMatrices holds the same columns; tests check that both agree.
//   dimension 1 (x + 1):         v_k = v_(k-1) ^ (v_(k-1) >> 1)
//   dimension 2 (x^2 + x + 1):   v_k = v_(k-1) ^ v_(k-2) ^ (v_(k-2) >> 2)
//   dimension 3 (x^3 + x + 1):   v_k = v_(k-2) ^ v_(k-3) ^ (v_(k-3) >> 3)
HIPR_FN uvec3 rng_sobol123(uint index) {
  uvec3 result = uvec3(0u);
  uint d1 = 0x80000000u;
  uint d2 = 0x80000000u, d2Previous = 0u;  // v_k, v_(k-1); m = 1, 3
  uint d3 = 0x80000000u, d3Previous = 0u, d3Before = 0u;  // v_k, v_(k-1), v_(k-2); m = 1, 3, 1
  for (uint k = 0u; index != 0u; ++k, index >>= 1u) {
    if ((index & 1u) != 0u) result ^= uvec3(d1, d2, d3);
    d1 ^= d1 >> 1u;
    uint next2 = k == 0u ? 0xc0000000u : d2 ^ d2Previous ^ (d2Previous >> 2u);
    d2Previous = d2;
    d2 = next2;
    uint next3 = k == 0u ? 0xc0000000u : k == 1u ? 0x20000000u : d3Previous ^ d3Before ^ (d3Before >> 3u);
    d3Before = d3Previous;
    d3Previous = d3;
    d3 = next3;
  }
  return result;
}

// Dimension d (0..3) of Sobol point `index` by its generator matrix: the XOR of the columns
// of its set bits (the tests' definition of the sequence).
HIPR_FN uint rng_sobol(uint index, uint d) {
  uint result = 0u;
  for (uint bit = 0u; index != 0u; ++bit, index >>= 1u)
    if ((index & 1u) != 0u) result ^= kSobolMatrices[d * 32u + bit];
  return result;
}

// Point `index` of the Owen-scrambled, index-shuffled 4D Sobol sequence chosen by the seeds.
// The shuffle scrambles the index as a binary fraction from its top bit down, so it maps every
// aligned run of 2^m indices (the first 2^m samples, the next 2^m...) onto another aligned run,
// and an aligned run of a Sobol sequence is a digitally shifted (0,m,2)-net in dimensions 0
// and 1: every power-of-two prefix of a pixel's samples keeps its stratification.
HIPR_FN vec4 rng_sobol4(uint index, uvec4 scrambleSeeds, uint shuffleSeed) {
  // Only the low 16 bits are shuffled (within each run of 2^16 samples, a nested scramble
  // still), so the Sobol loop stops at bit 16 for a pixel's first 65536 samples.
  const uint i = (rng_nested_uniform_scramble(index, shuffleSeed) & 0xffffu) | (index & 0xffff0000u);
  const uvec3 high = rng_sobol123(i);
  return vec4(rng_unit_float(rng_nested_uniform_scramble(bitfieldReverse(i), scrambleSeeds.x)),
              rng_unit_float(rng_nested_uniform_scramble(high.x, scrambleSeeds.y)),
              rng_unit_float(rng_nested_uniform_scramble(high.y, scrambleSeeds.z)),
              rng_unit_float(rng_nested_uniform_scramble(high.z, scrambleSeeds.w)));
}

struct PathRng {
  uint pixel;
  uint sampleIndex;
  uint seed;
  uint sequence;  // kSamplerSobol or kSamplerRandom
};

// Four uniforms in [0,1) for (bounce, block). Blocks: 0 = BSDF (direction in x,y, lobe in z,
// Russian roulette in w), 1 = light (point in x,y, choice of light in z), 2 = camera jitter
// (x,y). The best-stratified dimensions (x,y) go to the 2D integrals that matter most.
HIPR_FN vec4 rng_uniform4(PathRng rng, uint bounce, uint block) {
  const uint dimensionBlock = (bounce << 4u) | block;
  if (rng.sequence == kSamplerRandom) {
    const uvec4 h = rng_hash4(uvec4(rng.pixel, rng.sampleIndex, dimensionBlock, rng.seed));
    return vec4(rng_unit_float(h.x), rng_unit_float(h.y), rng_unit_float(h.z), rng_unit_float(h.w));
  }
  // Salts keep these hashes apart from the random sampler's (which has the sample index there).
  const uvec4 scrambleSeeds = rng_hash4(uvec4(rng.pixel, 0x5eed0001u, dimensionBlock, rng.seed));
  const uint shuffleSeed = rng_hash4(uvec4(rng.pixel, 0x5eed0002u, dimensionBlock, rng.seed)).x;
  return rng_sobol4(rng.sampleIndex, scrambleSeeds, shuffleSeed);
}

#endif
