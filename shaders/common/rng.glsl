// The random numbers of a path. A value depends only on (pixel, sample index, bounce, dimension
// block, seed, sampler), never on tile order or dispatch size, so any schedule of the same
// samples produces bit-identical pixels. Shared with C++ (see shared/glsl_cpp.h): tests check
// the very code the kernels run.
//
// Two samplers (FrameParams::sampleSequence, from RenderSettings::sampler):
// - kSamplerSobol: the dimensions of a path come in 2D pairs (the camera jitter; per bounce the
//   light point, the light choice, the BSDF direction, lobe and Russian roulette), each its own
//   blue-noise Sobol pair (rng_blue_sobol2): Owen-scrambled with hashed seeds, sample indices
//   shuffled by a nested uniform scramble (Burley, "Practical Hash-based Owen Scrambling", JCGT
//   2020), and a per-pixel digital shift laid out in Z-order. Within a pixel, the first 2^m
//   samples of a pair form a (0,m,2)-net, whatever the batch sizes that reached them: a pixel's
//   samples 0..n-1 are the same points however they were split. Across pixels, neighbours take
//   different strata, so at a few samples per pixel the error is blue noise.
// - kSamplerRandom: independent uniform hashes (the sampler before Sobol, kept for comparison).
#ifndef HIPR_RNG_GLSL
#define HIPR_RNG_GLSL

#include "../shared/abi.h"
#include "../shared/glsl_cpp.h"

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

// Dimension 1 of Sobol point `index`, bit-reversed: bit k holds binary digit k + 1 after the
// point (bitfieldReverse of this is the 32-bit fraction). The direction numbers are
// v_k = (1 + z)^k v_0, z a right shift, so the point is I(1 + z) v_0 for the polynomial
// I(t) = sum of t^k over the set bits k of the index. With I = L + t^h H and (1 + z)^h = 1 + z^h
// (h a power of two, arithmetic mod 2), I(1 + z) = L(1 + z) + (1 + z^h) H(1 + z): five
// butterfly steps instead of a loop over 32 bits (a loop is slow on CPU Vulkan devices).
HIPR_FN uint rng_sobol1_reversed(uint index) {
  index ^= (index >> 1u) & 0x55555555u;
  index ^= (index >> 2u) & 0x33333333u;
  index ^= (index >> 4u) & 0x0f0f0f0fu;
  index ^= (index >> 8u) & 0x00ff00ffu;
  index ^= (index >> 16u) & 0x0000ffffu;
  return index;
}

// Dimensions 0 and 1 of Sobol point `index`, Owen-scrambled by the two seeds, bit-reversed
// (the nested scramble of bitfieldReverse(v) is bitfieldReverse(rng_laine_karras(v)), so the
// reversal waits until the caller has XORed what it needs).
HIPR_FN uvec2 rng_scrambled_sobol2_reversed(uint index, uvec2 seeds) {
  return uvec2(rng_laine_karras(index, seeds.x), rng_laine_karras(rng_sobol1_reversed(index), seeds.y));
}

// Z-order (Morton) index of a pixel: x in the even bits, y in the odd ones, so every aligned
// 2^k x 2^k block of pixels is an aligned run of 4^k indices.
HIPR_FN uint rng_morton(uvec2 pixel) {
  uvec2 v = pixel & 0xffffu;
  v = (v | (v << 8u)) & 0x00ff00ffu;
  v = (v | (v << 4u)) & 0x0f0f0f0fu;
  v = (v | (v << 2u)) & 0x33333333u;
  v = (v | (v << 1u)) & 0x55555555u;
  return v.x | (v.y << 1u);
}

// One 2D pair of a path's dimensions, blue-noise Sobol: sample i of pixel p is
//   X_i XOR D_p,
// X: one Owen-scrambled, index-shuffled 2D Sobol sequence shared by every pixel;
// D_p: a digital shift per pixel, point m(p) of another Owen-scrambled 2D Sobol sequence, where
//   m(p) is the pixel's Morton index, scrambled from its top bit down (Ahmed & Wonka, "Screen-
//   space blue-noise sampling by Z-order", 2020, randomise the Z-order the same way).
// A digital shift keeps nets nets, so
// - within a pixel, every aligned power-of-two run of samples is a (0,m,2)-net, as with
//   independent per-pixel sequences (the error per pixel is the same);
// - across pixels, at one sample index, every aligned 2^k x 2^k block of pixels holds a
//   (0,2k,2)-net (its Morton indices are an aligned run, the scramble maps it onto another):
//   neighbouring pixels sample different strata, so at a few samples per pixel the error is
//   blue noise, fine-grained, with little of it at low spatial frequencies.
// Each pair has its own seeds, so pairs (of one bounce or of two) are independent: padding.
HIPR_FN vec2 rng_blue_sobol2(uint index, uvec2 pixel, uint pair, uint seed) {
  // Salts keep these hashes apart from the random sampler's.
  const uvec4 sequenceSeeds = rng_hash4(uvec4(pair, 0x5eed0003u, seed, 0x9e3779b9u));
  const uvec4 shiftSeeds = rng_hash4(uvec4(pair, 0x5eed0004u, seed, 0x7f4a7c15u));
  const uint i = rng_nested_uniform_scramble(index, sequenceSeeds.x);
  const uvec2 x = rng_scrambled_sobol2_reversed(i, uvec2(sequenceSeeds.y, sequenceSeeds.z));
  const uint m = rng_nested_uniform_scramble(rng_morton(pixel), shiftSeeds.x);
  const uvec2 d = rng_scrambled_sobol2_reversed(m, uvec2(shiftSeeds.y, shiftSeeds.z));
  return vec2(rng_unit_float(bitfieldReverse(x.x ^ d.x)), rng_unit_float(bitfieldReverse(x.y ^ d.y)));
}

struct PathRng {
  uint pixel;  // linear index (the random sampler's hash input)
  uvec2 position;  // pixel coordinates (the Sobol sampler's Z-order)
  uint sampleIndex;
  uint seed;
  uint sequence;  // kSamplerSobol or kSamplerRandom
};

// Four uniforms in [0,1) for (bounce, block). Blocks: 0 = BSDF (direction in x,y, lobe in z,
// Russian roulette in w), 1 = light (point in x,y, choice of light in z), 2 = camera jitter
// (x,y), 3 = the colour channel of a dispersive hit (x), 4 = path guiding (guide or BSDF in x,
// the guide's direction in y,z), 5 and 6 = the shadow rays' roulette of the punctual lights
// sampled each (light i: block 5 + i / 4, component i % 4). With Sobol, (x,y) and (z,w) are two
// independent blue-noise 2D pairs: the 2D integrals that matter most get a pair of their own.
HIPR_FN vec4 rng_uniform4(PathRng rng, uint bounce, uint block) {
  const uint dimensionBlock = (bounce << 4u) | block;
  if (rng.sequence == kSamplerRandom) {
    const uvec4 h = rng_hash4(uvec4(rng.pixel, rng.sampleIndex, dimensionBlock, rng.seed));
    return vec4(rng_unit_float(h.x), rng_unit_float(h.y), rng_unit_float(h.z), rng_unit_float(h.w));
  }
  const vec2 first = rng_blue_sobol2(rng.sampleIndex, rng.position, dimensionBlock << 1u, rng.seed);
  const vec2 second = rng_blue_sobol2(rng.sampleIndex, rng.position, (dimensionBlock << 1u) | 1u, rng.seed);
  return vec4(first.x, first.y, second.x, second.y);
}

#endif
