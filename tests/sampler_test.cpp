// The path sampler (shaders/common/rng.glsl) on the CPU, the very code the kernels run: the
// Sobol generator matrix, stratification of every power-of-two run of a pixel's samples and of
// every aligned block of pixels at one sample, error on analytic integrands against N^-1/2,
// blue-noise error at one sample, and independence of dimension pairs and bounces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "shaders/shared/abi.h"

namespace hipr::test::shader {
using namespace glm;
using namespace hipr::abi;
#include "shaders/common/rng.glsl"
}  // namespace hipr::test::shader

namespace hipr {
namespace {

namespace sh = test::shader;
using abi::kSamplerRandom;
using abi::kSamplerSobol;

// Columns of Sobol dimension d from a primitive polynomial of degree s with inner
// coefficients a and initial direction integers m (Joe & Kuo's recurrence), written apart
// from the shader's register recurrences.
std::vector<uint32_t> sobol_columns(int s, uint32_t a, std::vector<uint32_t> m) {
  for (int k = s; k < 32; ++k) {
    uint32_t v = m[k - s] ^ (m[k - s] << s);
    for (int j = 1; j < s; ++j)
      if ((a >> (s - 1 - j)) & 1u) v ^= m[k - j] << j;
    m.push_back(v);
  }
  std::vector<uint32_t> columns(32);
  for (int k = 0; k < 32; ++k) columns[k] = m[k] << (31 - k);
  return columns;
}

TEST(Sobol, DimensionOneFollowsTheJoeKuoRecurrence) {
  const std::vector<uint32_t> columns = sobol_columns(1, 0, {1});  // x + 1
  std::vector<uint32_t> indices = {0u, 1u, 2u, 3u, 0xffffffffu, 0x80000000u, 0x7fffffffu};
  uint32_t x = 12345u;
  for (int i = 0; i < 2000; ++i) indices.push_back(x = x * 747796405u + 2891336453u);
  for (const uint32_t index : indices) {
    uint32_t expected = 0;
    for (int k = 0; k < 32; ++k)
      if ((index >> k) & 1u) expected ^= columns[k];
    EXPECT_EQ(glm::bitfieldReverse(sh::rng_sobol1_reversed(index)), expected) << index;
  }
}

TEST(Sobol, MortonIndexInterleavesTheCoordinates) {
  EXPECT_EQ(sh::rng_morton({0u, 0u}), 0u);
  EXPECT_EQ(sh::rng_morton({1u, 0u}), 1u);
  EXPECT_EQ(sh::rng_morton({0u, 1u}), 2u);
  EXPECT_EQ(sh::rng_morton({3u, 5u}), 0b100111u);
  EXPECT_EQ(sh::rng_morton({0xffffu, 0u}), 0x55555555u);
  EXPECT_EQ(sh::rng_morton({0u, 0xffffu}), 0xaaaaaaaau);
}

// Pixels are given by their coordinates; the random sampler hashes a linear index.
constexpr uint32_t kWidth = 4096;

sh::PathRng path_rng(glm::uvec2 pixel, uint32_t sample, uint32_t sampler = kSamplerSobol,
                     uint32_t seed = 5) {
  return sh::PathRng{pixel.y * kWidth + pixel.x, pixel, sample, seed, sampler};
}

std::vector<glm::vec4> pixel_samples(glm::uvec2 pixel, uint32_t first, uint32_t count,
                                     uint32_t bounce, uint32_t block,
                                     uint32_t sampler = kSamplerSobol, uint32_t seed = 5) {
  std::vector<glm::vec4> points;
  for (uint32_t i = first; i < first + count; ++i)
    points.push_back(sh::rng_uniform4(path_rng(pixel, i, sampler, seed), bounce, block));
  return points;
}

// Every elementary interval of area 1/n (2^a x 2^b cells, a + b = m) holds exactly one point.
bool is_02_net(const std::vector<glm::vec4>& points, int x, int y) {
  const int m = int(std::log2(double(points.size())));
  for (int a = 0; a <= m; ++a) {
    const int b = m - a;
    std::set<std::pair<uint32_t, uint32_t>> cells;
    for (const glm::vec4& p : points)
      cells.insert({uint32_t(p[x] * float(1u << a)), uint32_t(p[y] * float(1u << b))});
    if (cells.size() != points.size()) return false;
  }
  return true;
}

// Every interval of length 1/n holds exactly one point.
bool is_stratified_1d(const std::vector<glm::vec4>& points, int d) {
  std::set<uint32_t> cells;
  for (const glm::vec4& p : points) cells.insert(uint32_t(p[d] * float(points.size())));
  return cells.size() == points.size();
}

TEST(Sampler, EveryPowerOfTwoRunOfAPixelIsAnElementaryNet) {
  for (glm::uvec2 pixel :
       {glm::uvec2(0, 0), glm::uvec2(1, 0), glm::uvec2(4095, 0), glm::uvec2(1234, 567)}) {
    for (uint32_t block : {0u, 1u, 2u}) {
      for (uint32_t bounce : {0u, 3u}) {
        for (uint32_t m = 0; m <= 10; ++m) {
          const uint32_t n = 1u << m;
          // The first n samples, and the next n (the second batch of a progressive render).
          for (uint32_t first : {0u, n}) {
            const std::vector<glm::vec4> points = pixel_samples(pixel, first, n, bounce, block);
            const std::string where = "pixel " + std::to_string(pixel.x) + "," +
                                      std::to_string(pixel.y) + " block " + std::to_string(block) +
                                      " n " + std::to_string(n) + " from " + std::to_string(first);
            EXPECT_TRUE(is_02_net(points, 0, 1)) << where;
            EXPECT_TRUE(is_02_net(points, 2, 3)) << where;
            for (int d = 0; d < 4; ++d)
              EXPECT_TRUE(is_stratified_1d(points, d)) << "dimension " << d << " n " << n;
          }
        }
      }
    }
  }
}

// Sample `sample` of every pixel of the size x size block at `corner`.
std::vector<glm::vec4> block_samples(glm::uvec2 corner, uint32_t size, uint32_t sample,
                                     uint32_t bounce, uint32_t block,
                                     uint32_t sampler = kSamplerSobol) {
  std::vector<glm::vec4> points;
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x)
      points.push_back(
          sh::rng_uniform4(path_rng(corner + glm::uvec2(x, y), sample, sampler), bounce, block));
  return points;
}

TEST(Sampler, AtOneSampleIndexEveryAlignedPixelBlockIsAnElementaryNet) {
  // What makes the error blue noise: neighbouring pixels take different strata.
  for (uint32_t sample : {0u, 1u, 7u, 100u}) {
    for (uint32_t block : {0u, 1u, 2u}) {
      for (uint32_t size : {2u, 4u, 8u, 16u}) {
        for (glm::uvec2 corner : {glm::uvec2(0, 0), glm::uvec2(size, 0),
                                  glm::uvec2(3 * size, 5 * size), glm::uvec2(640, 368)}) {
          const std::vector<glm::vec4> points = block_samples(corner, size, sample, 1, block);
          EXPECT_TRUE(is_02_net(points, 0, 1))
              << "sample " << sample << " block " << block << " size " << size;
          EXPECT_TRUE(is_02_net(points, 2, 3))
              << "sample " << sample << " block " << block << " size " << size;
        }
      }
    }
  }
  // The control: with independent random numbers, blocks miss cells.
  int nets = 0;
  for (uint32_t y = 0; y < 8; ++y)
    nets += is_02_net(block_samples({0, 8 * y}, 8, 0, 1, 0, kSamplerRandom), 0, 1);
  EXPECT_EQ(nets, 0);
}

TEST(Sampler, RandomSamplerIsNotStratified) {
  // The control: independent hashes miss cells (otherwise the test above proves nothing).
  int nets = 0;
  for (uint32_t pixel = 0; pixel < 20; ++pixel)
    nets += is_02_net(pixel_samples({pixel, 0}, 0, 64, 0, 0, kSamplerRandom), 0, 1);
  EXPECT_EQ(nets, 0);
}

TEST(Sampler, ValuesAreInTheUnitIntervalAndDependOnlyOnTheirInputs) {
  for (uint32_t sampler : {kSamplerSobol, kSamplerRandom}) {
    for (uint32_t i = 0; i < 4096; ++i) {
      const glm::uvec2 pixel(i * 7919u % kWidth, i % 2003u);
      const glm::vec4 u = sh::rng_uniform4(path_rng(pixel, i, sampler), i % 9, i % 3);
      for (int d = 0; d < 4; ++d) {
        EXPECT_GE(u[d], 0.0f);
        EXPECT_LT(u[d], 1.0f);
      }
      EXPECT_EQ(u, sh::rng_uniform4(path_rng(pixel, i, sampler), i % 9, i % 3));
    }
  }
}

// Root mean square error of n-sample estimates of the integral of f over [0,1)^2 (dimensions
// x,y of one block), over many pixels, each with its own seed: pixels of one seed share their
// scrambling (only a digital shift sets them apart), so the expected error is over seeds.
template <class F>
double rmse(F f, double exact, uint32_t n, uint32_t sampler, int x = 0, int y = 1) {
  const uint32_t pixels = 256;
  double sum = 0.0;
  for (uint32_t pixel = 0; pixel < pixels; ++pixel) {
    double estimate = 0.0;
    for (const glm::vec4& p :
         pixel_samples({pixel % 16, pixel / 16}, 0, n, 1, 0, sampler, pixel + 1))
      estimate += f(p[x], p[y]);
    estimate /= n;
    sum += (estimate - exact) * (estimate - exact);
  }
  return std::sqrt(sum / pixels);
}

// Error slope between n = 16 and n = 1024 (log-log).
template <class F>
double error_slope(F f, double exact, uint32_t sampler, int x = 0, int y = 1) {
  return std::log(rmse(f, exact, 1024, sampler, x, y) / rmse(f, exact, 16, sampler, x, y)) /
         std::log(64.0);
}

TEST(Sampler, ErrorFallsFasterThanTheSquareRootOfTheSampleCount) {
  const auto smooth = [](float x, float y) {
    return double(x) * std::exp(double(y));
  };  // integral e - 1 over 2
  const double smooth_exact = 0.5 * (std::exp(1.0) - 1.0);
  // A discontinuous integrand, as a shadow edge: the quarter disc of radius 1 (area pi / 4).
  const auto disc = [](float x, float y) { return x * x + y * y < 1.0f ? 1.0 : 0.0; };
  const double disc_exact = 3.14159265358979323846 / 4.0;
  // Owen-scrambled nets (RMSE): N^-1.5 on smooth integrands, N^-0.75 across a discontinuity
  // (variance N^-1.5 in two dimensions).
  EXPECT_LT(error_slope(smooth, smooth_exact, kSamplerSobol), -1.2);
  EXPECT_LT(error_slope(disc, disc_exact, kSamplerSobol), -0.65);
  // Dimensions 2 and 3 are a good pair too (the light choice and Russian roulette live there).
  EXPECT_LT(error_slope(smooth, smooth_exact, kSamplerSobol, 2, 3), -1.0);
  // The control: independent random numbers fall as N^-0.5.
  EXPECT_NEAR(error_slope(smooth, smooth_exact, kSamplerRandom), -0.5, 0.12);
  EXPECT_NEAR(error_slope(disc, disc_exact, kSamplerRandom), -0.5, 0.12);
}

// Sample correlation of dimension a of one stream with dimension b of another, over pixels.
double correlation(const std::vector<float>& a, const std::vector<float>& b) {
  double ma = 0, mb = 0;
  for (size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= double(a.size());
  mb /= double(b.size());
  double cab = 0, caa = 0, cbb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    cab += (a[i] - ma) * (b[i] - mb);
    caa += (a[i] - ma) * (a[i] - ma);
    cbb += (b[i] - mb) * (b[i] - mb);
  }
  return cab / std::sqrt(caa * cbb);
}

TEST(Sampler, OneSampleErrorIsBlueNoise) {
  // One-sample estimates of a shadow edge's integral (the quarter disc) over a 64 x 64 image,
  // seen from afar: averaged over 8 x 8 pixels. White noise keeps 1/8 of its RMSE there; blue
  // noise, whose error lives at high spatial frequencies, keeps much less: under half of that
  // here (0.042 and 0.048 of it with this seed; at most 0.059 over 39 seeds).
  const auto box_filtered_rmse = [](uint32_t sampler, uint32_t block, int x, int y) {
    const double exact = 3.14159265358979323846 / 4.0;
    double pixel_sum = 0.0, box_sum = 0.0;
    for (uint32_t by = 0; by < 8; ++by) {
      for (uint32_t bx = 0; bx < 8; ++bx) {
        double box_error = 0.0;
        for (const glm::vec4& p : block_samples({8 * bx, 8 * by}, 8, 0, 0, block, sampler)) {
          const double error = (p[x] * p[x] + p[y] * p[y] < 1.0f ? 1.0 : 0.0) - exact;
          pixel_sum += error * error;
          box_error += error / 64.0;
        }
        box_sum += box_error * box_error;
      }
    }
    return std::sqrt(box_sum / 64.0) / std::sqrt(pixel_sum / 4096.0);
  };
  for (uint32_t block : {0u, 1u, 2u}) {
    EXPECT_LT(box_filtered_rmse(kSamplerSobol, block, 0, 1), 1.0 / 16.0) << "block " << block;
    EXPECT_LT(box_filtered_rmse(kSamplerSobol, block, 2, 3), 1.0 / 16.0) << "block " << block;
  }
  EXPECT_GT(box_filtered_rmse(kSamplerRandom, 0, 0, 1), 0.08);  // the control: white, about 1/8
}

TEST(Sampler, BouncesAndPairsAreUncorrelated) {
  // Sample 0 of 20000 pixels: each pair's first dimension against the others'. (Neighbouring
  // pixels are correlated on purpose: they take different strata.)
  const uint32_t pixels = 20000;
  std::vector<float> camera(pixels), light(pixels), light_choice(pixels), bsdf(pixels),
      lobe(pixels), bsdf_next(pixels);
  for (uint32_t p = 0; p < pixels; ++p) {
    const glm::uvec2 pixel(p % 160, p / 160);
    camera[p] = sh::rng_uniform4(path_rng(pixel, 0), 0, 2).x;
    light[p] = sh::rng_uniform4(path_rng(pixel, 0), 0, 1).x;
    light_choice[p] = sh::rng_uniform4(path_rng(pixel, 0), 0, 1).z;
    bsdf[p] = sh::rng_uniform4(path_rng(pixel, 0), 0, 0).x;
    lobe[p] = sh::rng_uniform4(path_rng(pixel, 0), 0, 0).z;
    bsdf_next[p] = sh::rng_uniform4(path_rng(pixel, 0), 1, 0).x;
  }
  const double bound = 4.0 / std::sqrt(double(pixels));  // 4 sigma of a zero correlation
  EXPECT_LT(std::abs(correlation(camera, light)), bound);
  EXPECT_LT(std::abs(correlation(light, light_choice)), bound);
  EXPECT_LT(std::abs(correlation(light, bsdf)), bound);
  EXPECT_LT(std::abs(correlation(bsdf, lobe)), bound);
  EXPECT_LT(std::abs(correlation(bsdf, bsdf_next)), bound);
}

TEST(Sampler, SeedsGiveDifferentSequences) {
  const std::vector<glm::vec4> a = pixel_samples({7, 3}, 0, 16, 0, 0, kSamplerSobol, 1);
  const std::vector<glm::vec4> b = pixel_samples({7, 3}, 0, 16, 0, 0, kSamplerSobol, 2);
  int same = 0;
  for (size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
  EXPECT_EQ(same, 0);
}

}  // namespace
}  // namespace hipr
