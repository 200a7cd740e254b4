// The path sampler (shaders/common/rng.glsl) on the CPU, the very code the kernels run: the
// Sobol generator matrices, stratification of every power-of-two run of a pixel's samples,
// error on analytic integrands against N^-1/2, and independence of pixels and blocks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
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

TEST(SobolMatrices, TableFollowsTheJoeKuoRecurrence) {
  const std::vector<std::vector<uint32_t>> expected = {
      sobol_columns(1, 0, {1}), sobol_columns(2, 1, {1, 3}), sobol_columns(3, 1, {1, 3, 1})};
  for (uint32_t k = 0; k < 32; ++k) {
    EXPECT_EQ(sh::kSobolMatrices[k], 0x80000000u >> k) << "dimension 0, column " << k;
    for (uint32_t d = 1; d < 4; ++d)
      EXPECT_EQ(sh::kSobolMatrices[d * 32 + k], expected[d - 1][k]) << "dimension " << d << ", column " << k;
  }
}

TEST(SobolMatrices, RegisterRecurrencesEqualTheTable) {
  std::vector<uint32_t> indices = {0u, 1u, 2u, 3u, 0xffffffffu, 0x80000000u, 0x7fffffffu};
  uint32_t x = 12345u;
  for (int i = 0; i < 2000; ++i) indices.push_back(x = x * 747796405u + 2891336453u);
  for (const uint32_t index : indices) {
    const glm::uvec3 fast = sh::rng_sobol123(index);
    EXPECT_EQ(sh::rng_sobol(index, 0u), glm::bitfieldReverse(index));
    EXPECT_EQ(fast.x, sh::rng_sobol(index, 1u)) << index;
    EXPECT_EQ(fast.y, sh::rng_sobol(index, 2u)) << index;
    EXPECT_EQ(fast.z, sh::rng_sobol(index, 3u)) << index;
  }
}

sh::PathRng path_rng(uint32_t pixel, uint32_t sample, uint32_t sampler = kSamplerSobol, uint32_t seed = 5) {
  return sh::PathRng{pixel, sample, seed, sampler};
}

std::vector<glm::vec4> pixel_samples(uint32_t pixel, uint32_t first, uint32_t count, uint32_t bounce, uint32_t block,
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
    for (const glm::vec4& p : points) cells.insert({uint32_t(p[x] * float(1u << a)), uint32_t(p[y] * float(1u << b))});
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
  for (uint32_t pixel : {0u, 1u, 4095u, 123456u}) {
    for (uint32_t block : {0u, 1u, 2u}) {
      for (uint32_t bounce : {0u, 3u}) {
        for (uint32_t m = 0; m <= 10; ++m) {
          const uint32_t n = 1u << m;
          // The first n samples, and the next n (the second batch of a progressive render).
          for (uint32_t first : {0u, n}) {
            const std::vector<glm::vec4> points = pixel_samples(pixel, first, n, bounce, block);
            EXPECT_TRUE(is_02_net(points, 0, 1)) << "pixel " << pixel << " block " << block << " n " << n << " from " << first;
            for (int d = 0; d < 4; ++d) EXPECT_TRUE(is_stratified_1d(points, d)) << "dimension " << d << " n " << n;
          }
        }
      }
    }
  }
}

TEST(Sampler, RandomSamplerIsNotStratified) {
  // The control: independent hashes miss cells (otherwise the test above proves nothing).
  int nets = 0;
  for (uint32_t pixel = 0; pixel < 20; ++pixel) nets += is_02_net(pixel_samples(pixel, 0, 64, 0, 0, kSamplerRandom), 0, 1);
  EXPECT_EQ(nets, 0);
}

TEST(Sampler, ValuesAreInTheUnitIntervalAndDependOnlyOnTheirInputs) {
  for (uint32_t sampler : {kSamplerSobol, kSamplerRandom}) {
    for (uint32_t i = 0; i < 4096; ++i) {
      const glm::vec4 u = sh::rng_uniform4(path_rng(i * 7919u, i, sampler), i % 9, i % 3);
      for (int d = 0; d < 4; ++d) {
        EXPECT_GE(u[d], 0.0f);
        EXPECT_LT(u[d], 1.0f);
      }
      EXPECT_EQ(u, sh::rng_uniform4(path_rng(i * 7919u, i, sampler), i % 9, i % 3));
    }
  }
}

// Root mean square error of n-sample estimates of the integral of f over [0,1)^2 (dimensions
// x,y of one block), over many pixels.
template <class F>
double rmse(F f, double exact, uint32_t n, uint32_t sampler, int x = 0, int y = 1) {
  const uint32_t pixels = 256;
  double sum = 0.0;
  for (uint32_t pixel = 0; pixel < pixels; ++pixel) {
    double estimate = 0.0;
    for (const glm::vec4& p : pixel_samples(pixel * 2654435761u, 0, n, 1, 0, sampler)) estimate += f(p[x], p[y]);
    estimate /= n;
    sum += (estimate - exact) * (estimate - exact);
  }
  return std::sqrt(sum / pixels);
}

// Error slope between n = 16 and n = 1024 (log-log).
template <class F>
double error_slope(F f, double exact, uint32_t sampler, int x = 0, int y = 1) {
  return std::log(rmse(f, exact, 1024, sampler, x, y) / rmse(f, exact, 16, sampler, x, y)) / std::log(64.0);
}

TEST(Sampler, ErrorFallsFasterThanTheSquareRootOfTheSampleCount) {
  const auto smooth = [](float x, float y) { return double(x) * std::exp(double(y)); };  // integral e - 1 over 2
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

TEST(Sampler, PixelsBouncesAndBlocksAreUncorrelated) {
  // Sample 0 of 20000 pixels: each block's first dimension against its neighbours'.
  const uint32_t pixels = 20000;
  std::vector<float> camera(pixels), light(pixels), bsdf(pixels), bsdf_next(pixels), next_pixel(pixels);
  for (uint32_t p = 0; p < pixels; ++p) {
    camera[p] = sh::rng_uniform4(path_rng(p, 0), 0, 2).x;
    light[p] = sh::rng_uniform4(path_rng(p, 0), 0, 1).x;
    bsdf[p] = sh::rng_uniform4(path_rng(p, 0), 0, 0).x;
    bsdf_next[p] = sh::rng_uniform4(path_rng(p, 0), 1, 0).x;
    next_pixel[p] = sh::rng_uniform4(path_rng(p + 1, 0), 0, 0).x;
  }
  const double bound = 4.0 / std::sqrt(double(pixels));  // 4 sigma of a zero correlation
  EXPECT_LT(std::abs(correlation(camera, light)), bound);
  EXPECT_LT(std::abs(correlation(light, bsdf)), bound);
  EXPECT_LT(std::abs(correlation(bsdf, bsdf_next)), bound);
  EXPECT_LT(std::abs(correlation(bsdf, next_pixel)), bound);
}

TEST(Sampler, SeedsGiveDifferentSequences) {
  const std::vector<glm::vec4> a = pixel_samples(7, 0, 16, 0, 0, kSamplerSobol, 1);
  const std::vector<glm::vec4> b = pixel_samples(7, 0, 16, 0, 0, kSamplerSobol, 2);
  int same = 0;
  for (size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
  EXPECT_EQ(same, 0);
}

}  // namespace
}  // namespace hipr
