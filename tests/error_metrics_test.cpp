// relMSE and LDR-FLIP (src/image/error_metrics.h) on small synthetic images; no GPU.
#include "image/error_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numeric>
#include <random>

#include "core/error.h"

namespace hipr {
namespace {

using Rgb = std::array<float, 3>;

ImageRGB make_image(uint32_t width, uint32_t height,
                    const std::function<Rgb(uint32_t, uint32_t)>& colour) {
  ImageRGB image{width, height, std::vector<float>(size_t(width) * height * 3)};
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const Rgb c = colour(x, y);
      std::copy(c.begin(), c.end(),
                image.rgb.begin() + std::ptrdiff_t((size_t(y) * width + x) * 3));
    }
  return image;
}

ImageRGB uniform(uint32_t width, uint32_t height, Rgb c) {
  return make_image(width, height, [&](uint32_t, uint32_t) { return c; });
}

// Radiance in [0, max_value) per channel, different for every seed.
ImageRGB random_image(uint32_t width, uint32_t height, uint32_t seed, float max_value = 1.0f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, max_value);
  return make_image(width, height, [&](uint32_t, uint32_t) { return Rgb{u(rng), u(rng), u(rng)}; });
}

void set_pixel(ImageRGB& image, uint32_t x, uint32_t y, Rgb c) {
  std::copy(c.begin(), c.end(),
            image.rgb.begin() + std::ptrdiff_t((size_t(y) * image.width + x) * 3));
}

float at(const std::vector<float>& map, const ImageRGB& image, uint32_t x, uint32_t y) {
  return map[size_t(y) * image.width + x];
}

// ---------------------------------------------------------------------------------------------
// relMSE

TEST(RelMse, IdenticalImagesHaveNoError) {
  const ImageRGB image = random_image(13, 7, 1, 5.0f);
  EXPECT_EQ(relmse(image, image), 0.0);
  for (double sum : relmse_tile_sums(image, image, 4)) EXPECT_EQ(sum, 0.0);
}

TEST(RelMse, MatchesHandComputedValue) {
  const ImageRGB test{2, 1, {1.0f, 0.0f, 0.5f, 0.0f, 0.0f, 0.0f}};
  const ImageRGB reference{2, 1, {0.5f, 0.0f, 0.5f, 0.1f, 0.2f, 0.0f}};
  // Terms (x-y)^2 / (y^2 + 0.01): 0.25/0.26, 0, 0 for the first pixel, 0.01/0.02, 0.04/0.05, 0
  // for the second; mean over 6 values, halved.
  const double expected = (0.25 / 0.26 + 0.01 / 0.02 + 0.04 / 0.05) / 6.0 / 2.0;
  EXPECT_NEAR(relmse(test, reference), expected, 1e-7);
  // The test image is x and the reference y: swapping them changes the denominators.
  const double swapped = (0.25 / 1.01 + 0.01 / 0.01 + 0.04 / 0.01) / 6.0 / 2.0;
  EXPECT_NEAR(relmse(reference, test), swapped, 1e-7);
}

TEST(RelMse, SizeMismatchThrows) {
  const ImageRGB a = uniform(8, 4, {0.5f, 0.5f, 0.5f});
  EXPECT_THROW(relmse(a, uniform(4, 8, {0.5f, 0.5f, 0.5f})), InternalError);
  EXPECT_THROW(relmse(a, uniform(8, 5, {0.5f, 0.5f, 0.5f})), InternalError);
  EXPECT_THROW(relmse_tile_sums(a, uniform(9, 4, {0.5f, 0.5f, 0.5f}), 4), InternalError);
  ImageRGB short_buffer = a;
  short_buffer.rgb.pop_back();
  EXPECT_THROW(relmse(a, short_buffer), InternalError);
  EXPECT_THROW(relmse_tile_sums(a, a, 0), InternalError);
}

TEST(RelMse, BrokenSamplesAreNotHidden) {
  const ImageRGB reference = uniform(4, 4, {0.5f, 0.5f, 0.5f});
  ImageRGB test = reference;
  set_pixel(test, 1, 2, {std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.5f});
  EXPECT_FALSE(std::isfinite(relmse(test, reference)));
  set_pixel(test, 1, 2, {std::numeric_limits<float>::infinity(), 0.5f, 0.5f});
  EXPECT_FALSE(std::isfinite(relmse(test, reference)));
  EXPECT_FALSE(std::isfinite(relmse(reference, test)));
}

TEST(RelMse, EmptyImagesHaveNoError) {
  const ImageRGB empty;
  EXPECT_EQ(relmse(empty, empty), 0.0);
  EXPECT_TRUE(relmse_tile_sums(empty, empty, 8).empty());
}

TEST(RelMse, TileSumsLandInTheirTilesAndAddUpToTheTotal) {
  // 10x7 with 4-pixel tiles: 3x2 tiles, the last column and row of tiles partial.
  const ImageRGB reference = uniform(10, 7, {0.5f, 0.5f, 0.5f});
  ImageRGB test = reference;
  const double per_channel = 0.25 / 0.26 / 2.0;  // x = 1, y = 0.5, halved
  set_pixel(test, 0, 0, {1.0f, 0.5f, 0.5f});     // tile 0, one channel
  set_pixel(test, 5, 2, {1.0f, 1.0f, 0.5f});     // tile 1, two channels
  set_pixel(test, 9, 3, {1.0f, 1.0f, 1.0f});     // tile 2 (partial in x), three channels
  set_pixel(test, 9, 6, {1.0f, 0.5f, 0.5f});     // tile 5 (partial in x and y)
  set_pixel(test, 3, 4, {1.0f, 0.5f, 1.0f});     // tile 3 (partial in y)
  const std::vector<double> sums = relmse_tile_sums(test, reference, 4);
  ASSERT_EQ(sums.size(), 6u);
  const std::array<double, 6> expected = {
      1 * per_channel, 2 * per_channel, 3 * per_channel, 2 * per_channel, 0.0, 1 * per_channel};
  for (size_t t = 0; t < sums.size(); ++t) EXPECT_NEAR(sums[t], expected[t], 1e-9) << "tile " << t;

  // Random images: the tiles add up to the full sum for tile sizes that do and do not divide.
  const ImageRGB x = random_image(37, 23, 2, 3.0f);
  const ImageRGB y = random_image(37, 23, 3, 3.0f);
  const double total = relmse(x, y) * 3.0 * 37 * 23;
  for (uint32_t tile : {1u, 5u, 8u, 16u, 64u}) {
    const std::vector<double> tiles = relmse_tile_sums(x, y, tile);
    EXPECT_EQ(tiles.size(), size_t((37 + tile - 1) / tile) * ((23 + tile - 1) / tile));
    EXPECT_NEAR(std::accumulate(tiles.begin(), tiles.end(), 0.0), total, 1e-9 * total) << tile;
  }
}

// ---------------------------------------------------------------------------------------------
// LDR-FLIP

// The paper's formulas, step by step in double, independent of the implementation's float code.
namespace paper {

using Colour = std::array<double, 3>;

constexpr double kPi = 3.14159265358979323846;
constexpr double kM[3][3] = {{0.4124564, 0.3575761, 0.1804375},  // linear sRGB -> XYZ (D65)
                             {0.2126729, 0.7151522, 0.0721750},
                             {0.0193339, 0.1191920, 0.9503041}};

Colour to_colour(Rgb c) { return {c[0], c[1], c[2]}; }
double white(int i) { return kM[i][0] + kM[i][1] + kM[i][2]; }

// XYZ relative to the white point.
Colour relative_xyz(const Colour& rgb) {
  Colour n;
  for (int i = 0; i < 3; ++i)
    n[size_t(i)] = (kM[i][0] * rgb[0] + kM[i][1] * rgb[1] + kM[i][2] * rgb[2]) / white(i);
  return n;
}

// Linear RGB -> YyCxCz (linearised CIELAB).
Colour opponent(const Colour& rgb) {
  const Colour n = relative_xyz(rgb);
  return {116 * n[1] - 16, 500 * (n[0] - n[1]), 200 * (n[1] - n[2])};
}

// YyCxCz -> linear RGB through XYZ with the inverse of kM, computed here by cofactors.
Colour from_opponent(const Colour& o) {
  const double ny = (o[0] + 16) / 116;
  const Colour xyz = {(o[1] / 500 + ny) * white(0), ny * white(1), (ny - o[2] / 200) * white(2)};
  const auto m = [](int r, int c) { return kM[r][c]; };
  const double det = m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
                     m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
                     m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
  double inv[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      // Cofactor of (c, r) over the determinant.
      const int r0 = (c + 1) % 3, r1 = (c + 2) % 3, c0 = (r + 1) % 3, c1 = (r + 2) % 3;
      inv[r][c] = (m(r0, c0) * m(r1, c1) - m(r0, c1) * m(r1, c0)) / det;
    }
  Colour rgb;
  for (int i = 0; i < 3; ++i)
    rgb[size_t(i)] = inv[i][0] * xyz[0] + inv[i][1] * xyz[1] + inv[i][2] * xyz[2];
  return rgb;
}

// Clamp to [0,1], CIELAB, Hunt adjustment.
Colour hunt_lab(const Colour& rgb) {
  const Colour n = relative_xyz(
      {std::clamp(rgb[0], 0.0, 1.0), std::clamp(rgb[1], 0.0, 1.0), std::clamp(rgb[2], 0.0, 1.0)});
  Colour f;
  for (size_t i = 0; i < 3; ++i) {
    const double d = 6.0 / 29.0;
    f[i] = n[i] > d * d * d ? std::cbrt(n[i]) : n[i] / (3 * d * d) + 4.0 / 29.0;
  }
  const double l = 116 * f[1] - 16;
  const double a = 500 * (f[0] - f[1]);
  const double b = 200 * (f[1] - f[2]);
  return {l, l / 100 * a, l / 100 * b};
}

double hyab(const Colour& p, const Colour& q) {
  const Colour x = hunt_lab(p);
  const Colour y = hunt_lab(q);
  return std::abs(x[0] - y[0]) +
         std::sqrt((x[1] - y[1]) * (x[1] - y[1]) + (x[2] - y[2]) * (x[2] - y[2]));
}

// Compressed, normalised colour error ec of two (filtered) linear RGB colours.
double colour_error(const Colour& p, const Colour& q) {
  const double qc = 0.7, pc = 0.4, pt = 0.95;
  const double cmax = std::pow(hyab({0, 1, 0}, {0, 0, 1}), qc);
  const double e = std::pow(hyab(p, q), qc);
  return e < pc * cmax ? pt / (pc * cmax) * e
                       : pt + (e - pc * cmax) / (cmax - pc * cmax) * (1 - pt);
}

// For flat images the CSF filters (which sum to 1) change nothing and there are no features, so
// FLIP's error is the colour error of the two colours.
double uniform_error(Rgb p, Rgb q) { return colour_error(to_colour(p), to_colour(q)); }

// The CSF kernel of an opponent channel, built as a full 2D kernel and summed over its rows: the
// weights a vertical edge sees along x. s(x) = sum_k a_k sqrt(pi/b_k) exp(-pi^2 |x|^2 / b_k) with
// |x| in degrees, radius ceil(3 sqrt(0.04 / (2 pi^2)) ppd), normalised to sum 1.
std::vector<double> csf_along_x(double a1, double b1, double a2, double b2, double ppd) {
  const int r = int(std::ceil(3 * std::sqrt(0.04 / (2 * kPi * kPi)) * ppd));
  std::vector<double> along_x(size_t(2 * r + 1), 0.0);
  double total = 0.0;
  for (int i = -r; i <= r; ++i)
    for (int j = -r; j <= r; ++j) {
      const double d2 = double(i * i + j * j) / (ppd * ppd);
      const double s = a1 * std::sqrt(kPi / b1) * std::exp(-kPi * kPi * d2 / b1) +
                       a2 * std::sqrt(kPi / b2) * std::exp(-kPi * kPi * d2 / b2);
      along_x[size_t(i + r)] += s;
      total += s;
    }
  for (double& w : along_x) w /= total;
  return along_x;
}

}  // namespace paper

TEST(Flip, IdenticalImagesGiveExactlyZero) {
  for (uint32_t seed : {1u, 2u}) {
    const ImageRGB image = random_image(40, 30, seed, 3.0f);
    const FlipComponents components = flip_components(image, image);
    for (size_t p = 0; p < components.color.size(); ++p) {
      ASSERT_EQ(components.color[p], 0.0f);
      ASSERT_EQ(components.feature[p], 0.0f);
    }
    for (float e : flip_error_map(image, image)) ASSERT_EQ(e, 0.0f);
    EXPECT_EQ(flip_mean(image, image), 0.0);
  }
}

TEST(Flip, ErrorStaysWithinUnitRange) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (uint32_t seed = 0; seed < 4; ++seed) {
    ImageRGB a = random_image(33, 21, 10 + seed, seed % 2 ? 10.0f : 1.0f);
    ImageRGB b = random_image(33, 21, 20 + seed, 1.0f);
    set_pixel(a, 3, 3, {nan, inf, -inf});  // broken samples count like srgb_encode does (as 0)
    set_pixel(b, 30, 0, {0, 1, 0});
    set_pixel(a, 30, 0, {0, 0, 1});  // the paper's maximum distance at a corner
    for (float ppd : {1.0f, 10.0f, 67.0f, 300.0f}) {
      const std::vector<float> map = flip_error_map(a, b, {ppd, 0.0f});
      ASSERT_EQ(map.size(), size_t(33) * 21);
      for (float e : map) {
        ASSERT_TRUE(std::isfinite(e));
        ASSERT_GE(e, 0.0f);
        ASSERT_LE(e, 1.0f);
      }
      const double mean = flip_mean(a, b, {ppd, 0.0f});
      EXPECT_GT(mean, 0.0);
      EXPECT_LT(mean, 1.0);
    }
  }
}

TEST(Flip, UniformImagesGiveThePapersColourDistance) {
  const std::array<std::pair<Rgb, Rgb>, 8> pairs = {{
      {{0.5f, 0.5f, 0.5f}, {0.52f, 0.5f, 0.5f}},       // small: below the compression knee
      {{0.2f, 0.2f, 0.2f}, {0.25f, 0.25f, 0.25f}},     // grey levels
      {{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}},        // red vs green
      {{0.8f, 0.6f, 0.1f}, {0.1f, 0.3f, 0.9f}},        // saturated, large
      {{0.001f, 0.002f, 0.0f}, {0.0f, 0.0f, 0.003f}},  // dark: CIELAB's linear segment
      {{0.05f, 0.3f, 0.2f}, {0.06f, 0.28f, 0.25f}},
      {{3.0f, 0.5f, 0.2f}, {1.0f, 0.5f, 0.2f}},  // radiance above 1 clamps: no error
      {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}},  // black vs white
  }};
  for (const auto& [p, q] : pairs) {
    const ImageRGB a = uniform(48, 40, p);
    const ImageRGB b = uniform(48, 40, q);
    const double expected = paper::uniform_error(p, q);
    const FlipComponents components = flip_components(a, b);
    const std::vector<float> map = flip_error_map(a, b);
    // The filters clamp at the borders, so a flat image stays flat everywhere, borders included.
    for (size_t i = 0; i < map.size(); ++i) {
      ASSERT_EQ(components.feature[i], 0.0f) << "no features in a flat image";
      ASSERT_NEAR(map[i], expected, 1e-4)
          << "pixel " << i << " colours " << p[0] << "," << p[1] << "," << p[2] << " vs " << q[0]
          << "," << q[1] << "," << q[2];
    }
    EXPECT_NEAR(flip_mean(a, b), expected, 1e-4);
  }
}

TEST(Flip, ColourErrorAcrossAnEdgeFollowsThePapersCsf) {
  // A vertical edge between two saturated colours against the flat left colour: every column's
  // colour error follows from the CSF kernels' weights along x, the opponent transforms, the
  // clamp to [0,1] (the channels are blurred by different amounts, so the filtered colours leave
  // the RGB cube near the edge), and the colour error. Red | green stresses the red-green
  // channel, yellow | blue the blue-yellow one, whose CSF is a sum of two Gaussians.
  const std::array<std::pair<Rgb, Rgb>, 2> edges = {
      {{{1, 0, 0}, {0, 1, 0}}, {{1, 1, 0}, {0, 0, 1}}}};
  const uint32_t width = 64, edge = 32;
  for (const auto& [left, right] : edges) {
    const ImageRGB test =
        make_image(width, 24, [&](uint32_t x, uint32_t) { return x < edge ? left : right; });
    const ImageRGB reference = uniform(width, 24, left);
    for (float ppd : {20.0f, 67.0f}) {
      const std::array<std::vector<double>, 3> csf = {
          paper::csf_along_x(1, 0.0047, 0, 1e-5, ppd), paper::csf_along_x(1, 0.0053, 0, 1e-5, ppd),
          paper::csf_along_x(34.1, 0.04, 13.5, 0.025, ppd)};
      const int r = int(csf[0].size() / 2);
      const std::vector<float> colour = flip_components(test, reference, {ppd, 0.0f}).color;
      double lowest = 0.0, highest = 1.0;
      for (uint32_t x = 0; x < width; ++x) {
        paper::Colour filtered = {0, 0, 0};
        for (int i = -r; i <= r; ++i) {
          const int column = std::clamp(int(x) + i, 0, int(width) - 1);
          const paper::Colour o =
              paper::opponent(paper::to_colour(column < int(edge) ? left : right));
          for (size_t c = 0; c < 3; ++c) filtered[c] += csf[c][size_t(i + r)] * o[c];
        }
        const paper::Colour rgb = paper::from_opponent(filtered);
        lowest = std::min(lowest, *std::min_element(rgb.begin(), rgb.end()));
        highest = std::max(highest, *std::max_element(rgb.begin(), rgb.end()));
        const double expected = paper::colour_error(rgb, paper::to_colour(left));
        for (uint32_t y : {0u, 11u, 23u})
          EXPECT_NEAR(at(colour, test, x, y), expected, 2e-4) << ppd << " x " << x;
      }
      EXPECT_LT(lowest, -0.005) << ppd;  // the clamp mattered
      EXPECT_GT(highest, 1.005) << ppd;
    }
  }
}

TEST(Flip, EdgeStrengthOfAStepIsItsLuminanceStep) {
  // With positive weights summing to 1 and negative ones to -1, a first-derivative kernel centred
  // next to a vertical step responds with exactly the step in Y/Yn; the point response there is at
  // most half of it. The flat reference has no features, so ef = (dY / sqrt(2))^0.5.
  const float dark = 0.2f, bright = 0.7f;
  const ImageRGB test = make_image(64, 20, [&](uint32_t x, uint32_t) {
    return x < 32 ? Rgb{dark, dark, dark} : Rgb{bright, bright, bright};
  });
  const ImageRGB reference = uniform(64, 20, {dark, dark, dark});
  const double expected = std::sqrt((bright - dark) / std::sqrt(2.0));
  for (float ppd : {10.0f, 67.0f, 120.0f}) {
    const std::vector<float> feature = flip_components(test, reference, {ppd, 0.0f}).feature;
    for (uint32_t y = 0; y < 20; ++y) {
      EXPECT_NEAR(at(feature, test, 31, y), expected, 1e-5) << ppd;
      EXPECT_NEAR(at(feature, test, 32, y), expected, 1e-5) << ppd;
      EXPECT_LT(at(feature, test, 20, y), at(feature, test, 31, y)) << ppd;
    }
  }
}

TEST(Flip, PointStrengthOfALineFollowsTheNormalisedSecondDerivative) {
  // A bright one-pixel horizontal line on a flat background. On the line, the edge response is 0
  // by symmetry and the point response is dY times the 2D second-derivative kernel summed along
  // its centre row; the kernel (d2/dy2 of a Gaussian with sigma = 0.5 * 0.082 * ppd, radius
  // ceil(3 sigma)) is built here in full and normalised: positive weights to 1, negative to -1.
  const float background = 0.25f, line = 0.6f;
  const ImageRGB reference = uniform(40, 64, {background, background, background});
  ImageRGB test = reference;
  for (uint32_t x = 0; x < 40; ++x) set_pixel(test, x, 30, {line, line, line});
  for (float ppd : {30.0f, 67.0f}) {
    const double sigma = 0.5 * 0.082 * ppd;
    const int r = int(std::ceil(3 * sigma));
    double negative = 0.0, centre_row = 0.0;
    for (int i = -r; i <= r; ++i)
      for (int j = -r; j <= r; ++j) {
        const double k =
            (j * j / (sigma * sigma) - 1) * std::exp(-(i * i + j * j) / (2 * sigma * sigma));
        if (k < 0) negative += k;
        if (j == 0) centre_row += k;  // all negative
      }
    const double point = (line - background) * centre_row / negative;
    const double expected = std::sqrt(point / std::sqrt(2.0));
    const std::vector<float> feature = flip_components(test, reference, {ppd, 0.0f}).feature;
    for (uint32_t x = 0; x < 40; ++x)
      EXPECT_NEAR(at(feature, test, x, 30), expected, 1e-5) << ppd << " x " << x;
  }
}

ImageRGB transposed(const ImageRGB& image) {
  return make_image(image.height, image.width, [&](uint32_t x, uint32_t y) {
    const size_t i = (size_t(x) * image.width + y) * 3;
    return Rgb{image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
  });
}

// The image with its border pixels repeated `pad` times on every side.
ImageRGB edge_padded(const ImageRGB& image, uint32_t pad) {
  return make_image(image.width + 2 * pad, image.height + 2 * pad, [&](uint32_t x, uint32_t y) {
    const uint32_t sx = uint32_t(std::clamp(int(x) - int(pad), 0, int(image.width) - 1));
    const uint32_t sy = uint32_t(std::clamp(int(y) - int(pad), 0, int(image.height) - 1));
    const size_t i = (size_t(sy) * image.width + sx) * 3;
    return Rgb{image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
  });
}

TEST(Flip, BordersRepeatTheEdgePixels) {
  // Clamped coordinates mean an image behaves as if its edge pixels went on forever: padding it
  // with copies of them (more than the filters reach) changes nothing inside.
  const ImageRGB a = random_image(29, 17, 31, 1.5f);
  const ImageRGB b = random_image(29, 17, 32, 1.5f);
  const uint32_t pad = 12;  // CSF radius 10 and feature radius 9 at 67 pixels per degree
  const std::vector<float> map = flip_error_map(a, b);
  const ImageRGB padded_a = edge_padded(a, pad);
  const std::vector<float> padded_map = flip_error_map(padded_a, edge_padded(b, pad));
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x)
      ASSERT_NEAR(at(map, a, x, y), at(padded_map, padded_a, x + pad, y + pad), 1e-6)
          << x << "," << y;
}

TEST(Flip, TreatsRowsAndColumnsAlike) {
  const ImageRGB a = random_image(23, 37, 41, 1.0f);
  const ImageRGB b = random_image(23, 37, 42, 1.0f);
  const ImageRGB a_transposed = transposed(a);
  const std::vector<float> map = flip_error_map(a, b);
  const std::vector<float> map_t = flip_error_map(a_transposed, transposed(b));
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x)
      ASSERT_NEAR(at(map, a, x, y), at(map_t, a_transposed, y, x), 1e-4) << x << "," << y;
}

TEST(Flip, GreenVersusBlueIsTheMaximum) {
  const ImageRGB green = uniform(32, 32, {0, 1, 0});
  const ImageRGB blue = uniform(32, 32, {0, 0, 1});
  EXPECT_NEAR(flip_mean(green, blue), 1.0, 1e-4);
  EXPECT_NEAR(flip_mean(blue, green), 1.0, 1e-4);
}

TEST(Flip, BlackVersusWhiteIsHighButBelowOne) {
  const double e = flip_mean(uniform(32, 32, {0, 0, 0}), uniform(32, 32, {1, 1, 1}));
  EXPECT_GT(e, 0.95);  // above the compression knee
  EXPECT_LT(e, 0.99);
}

TEST(Flip, ErrorGrowsWithTheColourDifference) {
  // Flat images, and a square patch on a background (colour and feature error together).
  double previous_flat = 0.0, previous_patch = 0.0;
  for (float d : {0.005f, 0.02f, 0.05f, 0.1f, 0.2f, 0.4f, 0.6f}) {
    const double flat =
        flip_mean(uniform(32, 32, {0.2f + d, 0.2f, 0.2f}), uniform(32, 32, {0.2f, 0.2f, 0.2f}));
    EXPECT_GT(flat, previous_flat) << d;
    previous_flat = flat;
    const ImageRGB background = uniform(64, 64, {0.1f, 0.2f, 0.3f});
    const ImageRGB patch = make_image(64, 64, [&](uint32_t x, uint32_t y) {
      const bool inside = x >= 24 && x < 40 && y >= 24 && y < 40;
      return inside ? Rgb{0.1f + d, 0.2f + d, 0.3f} : Rgb{0.1f, 0.2f, 0.3f};
    });
    const double with_patch = flip_mean(patch, background);
    EXPECT_GT(with_patch, previous_patch) << d;
    previous_patch = with_patch;
  }
}

TEST(Flip, EdgeShiftedByOnePixelIsAFeatureErrorAtTheEdge) {
  const auto edge_at = [](uint32_t column) {
    return make_image(64, 32, [=](uint32_t x, uint32_t) {
      return x < column ? Rgb{0.05f, 0.05f, 0.05f} : Rgb{0.8f, 0.8f, 0.8f};
    });
  };
  const ImageRGB reference = edge_at(32);
  const ImageRGB test = edge_at(33);  // column 32 turned dark
  const FlipComponents components = flip_components(test, reference);
  const std::vector<float> map = flip_error_map(test, reference);
  const uint32_t row = 16;
  // The largest error is next to the changed column, where the edge features add to the colour
  // error. (At column 32 itself both images have an equally strong edge, half a pixel to either
  // side, so the feature difference peaks on its neighbours.)
  uint32_t worst = 0, worst_feature = 0;
  for (uint32_t x = 0; x < 64; ++x) {
    if (at(map, test, x, row) > at(map, test, worst, row)) worst = x;
    if (at(components.feature, test, x, row) > at(components.feature, test, worst_feature, row))
      worst_feature = x;
  }
  EXPECT_GE(worst, 31u);
  EXPECT_LE(worst, 33u);
  EXPECT_GT(at(map, test, worst, row), at(components.color, test, worst, row) + 0.05f);
  EXPECT_GE(worst_feature, 29u);
  EXPECT_LE(worst_feature, 35u);
  EXPECT_GT(at(components.feature, test, worst_feature, row), 0.3f);
  // Most of the error lies within a few pixels of the change and none beyond the filters' reach
  // (CSF radius 10 and feature radius 9 at 67 pixels per degree).
  double near = 0.0, total = 0.0;
  for (uint32_t x = 0; x < 64; ++x) {
    const float e = at(map, test, x, row);
    total += e;
    if (x >= 29 && x <= 35) near += e;
    if (x + 11 < 32 || x > 33 + 11) {
      EXPECT_EQ(e, 0.0f) << x;
    }
  }
  EXPECT_GT(near, 0.6 * total);
  // Every row sees the same vertical edge.
  for (uint32_t y = 0; y < 32; ++y) EXPECT_FLOAT_EQ(at(map, test, 32, y), at(map, test, 32, row));
}

TEST(Flip, SmallDotIsConcentratedAroundTheDot) {
  const ImageRGB reference = uniform(64, 64, {0.3f, 0.3f, 0.3f});
  ImageRGB test = reference;
  set_pixel(test, 32, 32, {1.0f, 1.0f, 1.0f});
  const FlipComponents components = flip_components(test, reference);
  const std::vector<float> map = flip_error_map(test, reference);
  const float peak = at(map, test, 32, 32);
  EXPECT_EQ(peak, *std::max_element(map.begin(), map.end()));
  // The point detector fires, strongest at the dot.
  EXPECT_GT(at(components.feature, test, 32, 32), 0.1f);
  EXPECT_EQ(at(components.feature, test, 32, 32),
            *std::max_element(components.feature.begin(), components.feature.end()));
  // Falls off with distance along the row and column through the dot; nothing beyond reach.
  for (uint32_t d = 1; d < 32; ++d) {
    EXPECT_LE(at(map, test, 32 + d, 32), at(map, test, 32 + d - 1, 32)) << d;
    EXPECT_LE(at(map, test, 32, 32 - d), at(map, test, 32, 32 - d + 1)) << d;
    if (d > 11) {
      EXPECT_EQ(at(map, test, 32 + d, 32), 0.0f) << d;
    }
  }
  EXPECT_LT(at(map, test, 36, 32), 0.5f * peak);
  // FLIP is not exactly symmetric in general; both orders must see the dot.
  EXPECT_GT(flip_mean(test, reference), 0.0);
  EXPECT_GT(flip_mean(reference, test), 0.0);
}

TEST(Flip, FartherViewerSeesLessFineNoise) {
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0.0f, 0.08f);
  const ImageRGB flat = uniform(64, 64, {0.4f, 0.4f, 0.4f});
  const ImageRGB noisy = make_image(64, 64, [&](uint32_t, uint32_t) {
    return Rgb{0.4f + noise(rng), 0.4f + noise(rng), 0.4f + noise(rng)};
  });
  double previous = 1.0;
  for (float ppd : {10.0f, 30.0f, 67.0f, 150.0f}) {
    const double e = flip_mean(noisy, flat, {ppd, 0.0f});
    EXPECT_LT(e, previous) << ppd;
    EXPECT_GT(e, 0.0) << ppd;
    previous = e;
  }
}

TEST(Flip, ExposureThatClipsBothImagesToWhiteRemovesTheError) {
  // Both images have every value >= 0.3, and they differ everywhere.
  ImageRGB a = random_image(32, 32, 5, 1.0f);
  ImageRGB b = a;
  for (float& v : a.rgb) v = 0.3f + v;
  for (float& v : b.rgb) v = 0.3f + 0.5f * v;
  EXPECT_GT(flip_mean(a, b), 0.0);
  EXPECT_GT(flip_mean(a, b, {67.0f, -1.0f}), 0.0);
  // 2^2 * 0.3 > 1: every channel of both images clips to 1.
  for (float e : flip_error_map(a, b, {67.0f, 2.0f})) ASSERT_EQ(e, 0.0f);
}

TEST(Flip, RejectsBadInput) {
  const ImageRGB a = uniform(8, 8, {0.5f, 0.5f, 0.5f});
  EXPECT_THROW(flip_mean(a, uniform(8, 9, {0.5f, 0.5f, 0.5f})), InternalError);
  EXPECT_THROW(flip_mean(a, a, {0.0f, 0.0f}), InputError);
  EXPECT_THROW(flip_mean(a, a, {0.5f, 0.0f}), InputError);
  EXPECT_THROW(flip_mean(a, a, {std::numeric_limits<float>::quiet_NaN(), 0.0f}), InputError);
  EXPECT_THROW(flip_mean(a, a, {std::numeric_limits<float>::infinity(), 0.0f}), InputError);
  EXPECT_THROW(flip_mean(a, a, {67.0f, std::numeric_limits<float>::infinity()}), InputError);
  const ImageRGB empty;
  EXPECT_EQ(flip_mean(empty, empty), 0.0);
  EXPECT_TRUE(flip_error_map(empty, empty).empty());
  // Images narrower than the filters are fine: coordinates clamp.
  EXPECT_NEAR(flip_mean(uniform(1, 1, {0, 1, 0}), uniform(1, 1, {0, 0, 1})), 1.0, 1e-4);
}

}  // namespace
}  // namespace hipr
