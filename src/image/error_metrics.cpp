// Image error metrics for `hipr bench`.
//
// relMSE (docs/method.md#measuring-run-time-against-error): mean over pixels and channels of
// (x-y)^2 / (y^2 + 0.01), halved.
//
// LDR-FLIP, implemented from the description in P. Andersson, J. Nilsson, T. Akenine-Moller,
// M. Oskarsson, K. Astrom and M. D. Fairchild, "FLIP: A Difference Evaluator for Alternating
// Images", Proc. ACM Comput. Graph. Interact. Tech. 3(2), article 15, 2020
// (doi:10.1145/3406183). Both images take the same steps; then they are compared per pixel.
//  Colour pipeline
//   1. Display values: radiance * 2^exposure clamped to [0,1], which is what tonemap_srgb8
//      sRGB-encodes. LDR-FLIP decodes sRGB to linear first, which gives these values back, so the
//      encode/decode round trip (and the 8-bit rounding of PNGs) is left out.
//   2. Linear RGB -> XYZ (sRGB primaries, D65 white) -> YyCxCz, the linearised L*a*b* opponent
//      space: Yy = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn).
//   3. Each channel is convolved with the paper's contrast sensitivity filter for it, a sum of
//      Gaussians over visual angle x in degrees: s(x) = sum_k a_k sqrt(pi/b_k) exp(-pi^2 x^2/b_k),
//      (a1, b1, a2, b2) = Yy (1, 0.0047, 0, 1e-5), Cx (1, 0.0053, 0, 1e-5),
//      Cz (34.1, 0.04, 13.5, 0.025). A pixel spans 1/ppd degrees; every kernel has radius
//      ceil(3 sqrt(b_max / (2 pi^2)) ppd) pixels with b_max the largest b (0.04), and its weights
//      sum to 1. A Gaussian term is separable, so a kernel runs as one separable pass per term.
//   4. Back to linear RGB, clamped to [0,1]; then CIELAB with the Hunt adjustment (a and b
//      scaled by 0.01 L).
//   5. HyAB distance |dL| + sqrt(da^2 + db^2), raised to qc = 0.7, and compressed against
//      cmax = HyAB(green, blue)^qc, the largest distance in the gamut: [0, pc cmax] maps linearly
//      onto [0, pt] and [pc cmax, cmax] onto [pt, 1] with pc = 0.4, pt = 0.95. That is ec.
//  Feature pipeline
//   6. The achromatic channel Y/Yn = (Yy + 16) / 116, in [0,1], of the unfiltered images.
//   7. First and second derivatives of a Gaussian with sigma = 0.5 w ppd pixels (w = 0.082
//      degrees), radius ceil(3 sigma), positive weights normalised to sum 1 and negative ones to
//      -1. Edge strength = |(d/dx, d/dy)|, point strength = |(d2/dx2, d2/dy2)|. Each kernel is a
//      derivative profile along one axis times a Gaussian along the other: separable as well.
//   8. ef = (max(|edge_t - edge_r|, |point_t - point_r|) / sqrt(2))^qf with qf = 0.5.
//  Combination: e = ec^(1 - ef).
// Filters clamp coordinates at the image borders (edge pixels repeat).
#include "image/error_metrics.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace hipr {
namespace {

std::string size_text(const ImageRGB& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void check_same_size(const ImageRGB& test, const ImageRGB& reference, const char* what) {
  for (const ImageRGB* image : {&test, &reference})
    if (image->rgb.size() != size_t(image->width) * image->height * 3)
      throw InternalError(std::string(what) + ": a " + size_text(*image) + " image holds " +
                          std::to_string(image->rgb.size()) + " values");
  if (test.width != reference.width || test.height != reference.height)
    throw InternalError(std::string(what) + ": test image is " + size_text(test) +
                        " but the reference is " + size_text(reference));
}

// One pixel's relMSE terms, summed over RGB (halved, as relMSE is).
double relmse_pixel(const float* x, const float* y) {
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double d = double(x[c]) - double(y[c]);
    sum += d * d / (double(y[c]) * double(y[c]) + 0.01);
  }
  return 0.5 * sum;
}

}  // namespace

double relmse(const ImageRGB& test, const ImageRGB& reference) {
  check_same_size(test, reference, "relmse");
  const size_t values = test.rgb.size();
  if (values == 0) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < values; i += 3) sum += relmse_pixel(&test.rgb[i], &reference.rgb[i]);
  return sum / double(values);
}

double relmse_masked(const ImageRGB& test, const ImageRGB& reference,
                     const std::vector<uint8_t>& mask) {
  check_same_size(test, reference, "relmse_masked");
  if (mask.size() * 3 != test.rgb.size())
    throw InternalError("relmse_masked: the mask is not one entry per pixel");
  double sum = 0.0;
  size_t pixels = 0;
  for (size_t p = 0; p < mask.size(); ++p)
    if (mask[p]) {
      sum += relmse_pixel(&test.rgb[p * 3], &reference.rgb[p * 3]);
      ++pixels;
    }
  return pixels ? sum / double(pixels * 3) : 0.0;
}

std::vector<double> relmse_tile_sums(const ImageRGB& test, const ImageRGB& reference,
                                     uint32_t tile) {
  check_same_size(test, reference, "relmse_tile_sums");
  if (tile == 0) throw InternalError("relmse_tile_sums: tile size is 0");
  const uint32_t tiles_x = (test.width + tile - 1) / tile;
  const uint32_t tiles_y = (test.height + tile - 1) / tile;
  std::vector<double> sums(size_t(tiles_x) * tiles_y, 0.0);
  for (uint32_t y = 0; y < test.height; ++y)
    for (uint32_t x = 0; x < test.width; ++x) {
      const size_t i = (size_t(y) * test.width + x) * 3;
      sums[size_t(y / tile) * tiles_x + x / tile] += relmse_pixel(&test.rgb[i], &reference.rgb[i]);
    }
  return sums;
}

namespace {

constexpr double kPi = std::numbers::pi;

// The paper's constants.
constexpr float kQc = 0.7f;   // exponent on the HyAB distance
constexpr float kPc = 0.4f;   // share of cmax below which errors are expanded ...
constexpr float kPt = 0.95f;  // ... onto [0, pt]
constexpr float kQf = 0.5f;   // exponent on the feature difference
constexpr double kFeatureWidthDegrees = 0.082;

struct GaussianTerm {
  double a, b;
};
using Csf = std::array<GaussianTerm, 2>;
constexpr Csf kCsfAchromatic{{{1.0, 0.0047}, {0.0, 1e-5}}};
constexpr Csf kCsfRedGreen{{{1.0, 0.0053}, {0.0, 1e-5}}};
constexpr Csf kCsfBlueYellow{{{34.1, 0.04}, {13.5, 0.025}}};
constexpr double kCsfLargestB = 0.04;

// sRGB primaries with a D65 white; the white point is XYZ of RGB (1,1,1).
constexpr float kRgbToXyz[3][3] = {{0.4124564f, 0.3575761f, 0.1804375f},
                                   {0.2126729f, 0.7151522f, 0.0721750f},
                                   {0.0193339f, 0.1191920f, 0.9503041f}};
constexpr float kXyzToRgb[3][3] = {{3.2404542f, -1.5371385f, -0.4985314f},
                                   {-0.9692660f, 1.8760108f, 0.0415560f},
                                   {0.0556434f, -0.2040259f, 1.0572252f}};
constexpr float kWhite[3] = {kRgbToXyz[0][0] + kRgbToXyz[0][1] + kRgbToXyz[0][2],
                             kRgbToXyz[1][0] + kRgbToXyz[1][1] + kRgbToXyz[1][2],
                             kRgbToXyz[2][0] + kRgbToXyz[2][1] + kRgbToXyz[2][2]};

// One channel, row-major.
struct Plane {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> v;

  Plane(uint32_t w, uint32_t h) : width(w), height(h), v(size_t(w) * h, 0.0f) {}
  float* row(uint32_t y) { return v.data() + size_t(y) * width; }
  const float* row(uint32_t y) const { return v.data() + size_t(y) * width; }
};

// How a 1D kernel's weight at offset -i relates to its weight w[i] at +i.
enum class Parity {
  kEven,         // w(-i) = w(i)
  kOdd,          // w(-i) = -w(i), w(0) = 0
  kEvenZeroSum,  // w(-i) = w(i) and all weights sum to 0, so w(0) = -2 sum_{i>0} w(i)
};

// Weights at offsets 0..radius. The odd and zero-sum forms are evaluated as sums of differences
// so that a flat region gives exactly 0: otherwise float rounding leaves ~1e-8 responses that
// the square root in ef magnifies to ~1e-4.
struct HalfKernel {
  std::vector<float> w;
  Parity parity = Parity::kEven;
  int radius() const { return int(w.size()) - 1; }
};

// out[x] = sum over offsets i of weight(i) * line_at(i)[x], for x in [0, n).
template <typename LineAt>
void apply_kernel(const HalfKernel& kernel, LineAt line_at, uint32_t n, float* out) {
  const float* centre = line_at(0);
  const float w0 = kernel.parity == Parity::kEven ? kernel.w[0] : 0.0f;
  for (uint32_t x = 0; x < n; ++x) out[x] = w0 * centre[x];
  for (int i = 1; i <= kernel.radius(); ++i) {
    const float wi = kernel.w[size_t(i)];
    const float* plus = line_at(i);
    const float* minus = line_at(-i);
    switch (kernel.parity) {
      case Parity::kEven:
        for (uint32_t x = 0; x < n; ++x) out[x] += wi * (plus[x] + minus[x]);
        break;
      case Parity::kOdd:
        for (uint32_t x = 0; x < n; ++x) out[x] += wi * (plus[x] - minus[x]);
        break;
      case Parity::kEvenZeroSum:
        for (uint32_t x = 0; x < n; ++x) out[x] += wi * ((plus[x] + minus[x]) - 2.0f * centre[x]);
        break;
    }
  }
}

Plane filter_rows(const Plane& in, const HalfKernel& kernel) {
  Plane out(in.width, in.height);
  const int r = kernel.radius();
  std::vector<float> padded(size_t(in.width) + 2 * size_t(r));
  for (uint32_t y = 0; y < in.height; ++y) {
    const float* src = in.row(y);
    std::fill(padded.begin(), padded.begin() + r, src[0]);
    std::copy(src, src + in.width, padded.begin() + r);
    std::fill(padded.begin() + r + in.width, padded.end(), src[in.width - 1]);
    const float* middle = padded.data() + r;
    apply_kernel(
        kernel, [&](int i) { return middle + i; }, in.width, out.row(y));
  }
  return out;
}

Plane filter_columns(const Plane& in, const HalfKernel& kernel) {
  Plane out(in.width, in.height);
  const int last = int(in.height) - 1;
  for (uint32_t y = 0; y < in.height; ++y)
    apply_kernel(
        kernel, [&](int i) { return in.row(uint32_t(std::clamp(int(y) + i, 0, last))); }, in.width,
        out.row(y));
  return out;
}

// One Gaussian term of a CSF kernel as a pair of 1D passes.
struct SeparablePass {
  HalfKernel horizontal, vertical;
};

// The CSF kernel for one channel: the vertical pass is the bare Gaussian, the horizontal one
// carries the term's amplitude and the normalisation of the whole 2D kernel to sum 1.
std::vector<SeparablePass> csf_kernel(const Csf& csf, double ppd) {
  const int radius = int(std::ceil(3.0 * std::sqrt(kCsfLargestB / (2.0 * kPi * kPi)) * ppd));
  std::vector<SeparablePass> passes;
  std::vector<std::vector<double>> profiles;
  std::vector<double> amplitudes;
  double total = 0.0;
  for (const GaussianTerm& term : csf) {
    if (term.a == 0.0) continue;
    std::vector<double> profile(size_t(radius) + 1);
    double line_sum = 0.0;
    for (int i = 0; i <= radius; ++i) {
      const double degrees = double(i) / ppd;
      profile[size_t(i)] = std::exp(-kPi * kPi * degrees * degrees / term.b);
      line_sum += (i == 0 ? 1.0 : 2.0) * profile[size_t(i)];
    }
    const double amplitude = term.a * std::sqrt(kPi / term.b);
    total += amplitude * line_sum * line_sum;
    profiles.push_back(std::move(profile));
    amplitudes.push_back(amplitude);
  }
  for (size_t t = 0; t < profiles.size(); ++t) {
    SeparablePass pass;
    for (double value : profiles[t]) {
      pass.horizontal.w.push_back(float(amplitudes[t] * value / total));
      pass.vertical.w.push_back(float(value));
    }
    passes.push_back(std::move(pass));
  }
  return passes;
}

Plane apply_csf(const Plane& in, const std::vector<SeparablePass>& passes) {
  Plane sum(in.width, in.height);
  for (const SeparablePass& pass : passes) {
    const Plane term = filter_columns(filter_rows(in, pass.horizontal), pass.vertical);
    for (size_t i = 0; i < sum.v.size(); ++i) sum.v[i] += term.v[i];
  }
  return sum;
}

// The 2D feature kernels are products of a 1D derivative profile and a 1D Gaussian. Normalising
// the 2D kernel's positive weights to 1 and negative ones to -1 is the same as normalising the
// derivative profile that way and the Gaussian to sum 1, since the Gaussian factor is positive.
struct FeatureKernels {
  HalfKernel gaussian, first, second;
};

FeatureKernels feature_kernels(double ppd) {
  const double sigma = 0.5 * kFeatureWidthDegrees * ppd;
  const int radius = int(std::ceil(3.0 * sigma));
  std::vector<double> g(size_t(radius) + 1), d1(g.size()), d2(g.size());
  double g_sum = 0.0, d1_positive = 0.0, d2_positive = 0.0, d2_negative = 0.0;
  for (int i = 0; i <= radius; ++i) {
    const double x = double(i);
    const double count = i == 0 ? 1.0 : 2.0;  // offsets +i and -i
    g[size_t(i)] = std::exp(-x * x / (2.0 * sigma * sigma));
    // Derivative profiles up to positive factors, which the normalisation removes; the sign of
    // the first derivative does not matter since only magnitudes are compared.
    d1[size_t(i)] = x * g[size_t(i)];
    d2[size_t(i)] = (x * x / (sigma * sigma) - 1.0) * g[size_t(i)];
    g_sum += count * g[size_t(i)];
    d1_positive += d1[size_t(i)];  // only the +i side is positive
    (d2[size_t(i)] > 0.0 ? d2_positive : d2_negative) += count * d2[size_t(i)];
  }
  FeatureKernels kernels;
  kernels.gaussian.parity = Parity::kEven;
  kernels.first.parity = Parity::kOdd;
  kernels.second.parity = Parity::kEvenZeroSum;
  for (int i = 0; i <= radius; ++i) {
    kernels.gaussian.w.push_back(float(g[size_t(i)] / g_sum));
    kernels.first.w.push_back(float(d1[size_t(i)] / d1_positive));
    const double d = d2[size_t(i)];
    kernels.second.w.push_back(float(d > 0.0 ? d / d2_positive : -d / d2_negative));
  }
  return kernels;
}

// Cube root of t > 0. std::cbrt took a fifth of FLIP's run time; a bit-level first guess (the
// float exponent divided by 3, good to a few percent) and three Newton steps in double reach
// float precision.
float cube_root(float t) {
  const double y0 = double(std::bit_cast<float>(std::bit_cast<uint32_t>(t) / 3u + 709921077u));
  double y = y0;
  for (int i = 0; i < 3; ++i) y -= (y * y * y - double(t)) / (3.0 * y * y);
  return float(y);
}

// CIELAB's companding function.
float lab_f(float t) {
  constexpr float delta = 6.0f / 29.0f;
  return t > delta * delta * delta ? cube_root(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
}

// Linear RGB in [0,1] -> L*a*b* with the Hunt adjustment.
std::array<float, 3> hunt_lab(float r, float g, float b) {
  std::array<float, 3> f;
  for (int c = 0; c < 3; ++c)
    f[size_t(c)] =
        lab_f((kRgbToXyz[c][0] * r + kRgbToXyz[c][1] * g + kRgbToXyz[c][2] * b) / kWhite[c]);
  const float lightness = 116.0f * f[1] - 16.0f;
  const float a = 500.0f * (f[0] - f[1]);
  const float bb = 200.0f * (f[1] - f[2]);
  return {lightness, 0.01f * lightness * a, 0.01f * lightness * bb};
}

float hyab(const std::array<float, 3>& p, const std::array<float, 3>& q) {
  const float da = p[1] - q[1], db = p[2] - q[2];
  return std::abs(p[0] - q[0]) + std::sqrt(da * da + db * db);
}

// What the two pipelines produce for one image, per pixel.
struct FlipPrepared {
  Plane lab_l, lab_a, lab_b;  // Hunt-adjusted L*a*b* after CSF filtering
  Plane edges, points;        // feature strengths of the achromatic channel
};

FlipPrepared prepare(const ImageRGB& image, const FlipOptions& options,
                     const std::array<std::vector<SeparablePass>, 3>& csf,
                     const FeatureKernels& features) {
  const uint32_t w = image.width, h = image.height;
  const float scale = std::exp2(options.exposure_ev);
  Plane yy(w, h), cx(w, h), cz(w, h), luminance(w, h);
  for (size_t p = 0; p < size_t(w) * h; ++p) {
    float rgb[3];
    if (options.tone_mapper == ToneMapper::Clamp) {
      for (int c = 0; c < 3; ++c) {
        const float v = image.rgb[p * 3 + size_t(c)] * scale;
        rgb[c] = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;  // as srgb_encode does
      }
    } else {
      const glm::vec3 shown =
          tone_map(glm::vec3(image.rgb[p * 3], image.rgb[p * 3 + 1], image.rgb[p * 3 + 2]) * scale,
                   options.tone_mapper);
      for (int c = 0; c < 3; ++c) rgb[c] = shown[c];
    }
    float n[3];  // XYZ relative to the white point
    for (int c = 0; c < 3; ++c)
      n[c] = (kRgbToXyz[c][0] * rgb[0] + kRgbToXyz[c][1] * rgb[1] + kRgbToXyz[c][2] * rgb[2]) /
             kWhite[c];
    yy.v[p] = 116.0f * n[1] - 16.0f;
    cx.v[p] = 500.0f * (n[0] - n[1]);
    cz.v[p] = 200.0f * (n[1] - n[2]);
    luminance.v[p] = n[1];
  }

  FlipPrepared out{Plane(w, h), Plane(w, h), Plane(w, h), Plane(w, h), Plane(w, h)};
  const Plane yy_f = apply_csf(yy, csf[0]);
  const Plane cx_f = apply_csf(cx, csf[1]);
  const Plane cz_f = apply_csf(cz, csf[2]);
  for (size_t p = 0; p < size_t(w) * h; ++p) {
    const float ny = (yy_f.v[p] + 16.0f) / 116.0f;
    const float xyz[3] = {(cx_f.v[p] / 500.0f + ny) * kWhite[0], ny * kWhite[1],
                          (ny - cz_f.v[p] / 200.0f) * kWhite[2]};
    float rgb[3];
    for (int c = 0; c < 3; ++c)
      rgb[c] =
          std::clamp(kXyzToRgb[c][0] * xyz[0] + kXyzToRgb[c][1] * xyz[1] + kXyzToRgb[c][2] * xyz[2],
                     0.0f, 1.0f);
    const std::array<float, 3> lab = hunt_lab(rgb[0], rgb[1], rgb[2]);
    out.lab_l.v[p] = lab[0];
    out.lab_a.v[p] = lab[1];
    out.lab_b.v[p] = lab[2];
  }

  // Horizontal passes shared by the four 2D kernels: d/dx = first (x) * gaussian (y), and so on.
  const Plane h_gauss = filter_rows(luminance, features.gaussian);
  const Plane h_first = filter_rows(luminance, features.first);
  const Plane h_second = filter_rows(luminance, features.second);
  const Plane dx = filter_columns(h_first, features.gaussian);
  const Plane dy = filter_columns(h_gauss, features.first);
  const Plane dxx = filter_columns(h_second, features.gaussian);
  const Plane dyy = filter_columns(h_gauss, features.second);
  for (size_t p = 0; p < size_t(w) * h; ++p) {
    // Filter responses are at most 1 in size: no overflow for hypot to guard against.
    out.edges.v[p] = std::sqrt(dx.v[p] * dx.v[p] + dy.v[p] * dy.v[p]);
    out.points.v[p] = std::sqrt(dxx.v[p] * dxx.v[p] + dyy.v[p] * dyy.v[p]);
  }
  return out;
}

void check_options(const FlipOptions& options) {
  // Below 1 pixel per degree the feature Gaussian is narrower than a hundredth of a pixel and its
  // derivative weights underflow; no real viewing setup is that coarse.
  if (!(options.pixels_per_degree >= 1.0f) || !std::isfinite(options.pixels_per_degree))
    throw InputError("FLIP: pixels per degree must be a finite number >= 1, got " +
                     std::to_string(options.pixels_per_degree));
  if (!std::isfinite(options.exposure_ev))
    throw InputError("FLIP: exposure must be a finite number of stops");
}

// The HyAB distance of the Hunt-adjusted colours green and blue, raised to qc.
float flip_cmax() {
  static const float cmax = std::pow(hyab(hunt_lab(0, 1, 0), hunt_lab(0, 0, 1)), kQc);
  return cmax;
}

}  // namespace

FlipComponents flip_components(const ImageRGB& test, const ImageRGB& reference,
                               const FlipOptions& options) {
  check_same_size(test, reference, "FLIP");
  check_options(options);
  const size_t pixels = size_t(test.width) * test.height;
  FlipComponents result;
  if (pixels == 0) return result;

  const double ppd = options.pixels_per_degree;
  const std::array<std::vector<SeparablePass>, 3> csf = {csf_kernel(kCsfAchromatic, ppd),
                                                         csf_kernel(kCsfRedGreen, ppd),
                                                         csf_kernel(kCsfBlueYellow, ppd)};
  const FeatureKernels features = feature_kernels(ppd);
  const FlipPrepared t = prepare(test, options, csf, features);
  const FlipPrepared r = prepare(reference, options, csf, features);

  const float cmax = flip_cmax();
  const float knee = kPc * cmax;
  result.color.resize(pixels);
  result.feature.resize(pixels);
  for (size_t p = 0; p < pixels; ++p) {
    const float distance = std::pow(hyab({t.lab_l.v[p], t.lab_a.v[p], t.lab_b.v[p]},
                                         {r.lab_l.v[p], r.lab_a.v[p], r.lab_b.v[p]}),
                                    kQc);
    const float ec = distance < knee ? kPt / knee * distance
                                     : kPt + (distance - knee) / (cmax - knee) * (1.0f - kPt);
    // Green-blue is the largest distance in the gamut; the clamp only absorbs rounding.
    result.color[p] = std::min(ec, 1.0f);
    const float feature_difference =
        std::max(std::abs(t.edges.v[p] - r.edges.v[p]), std::abs(t.points.v[p] - r.points.v[p]));
    result.feature[p] =
        std::min(std::pow(feature_difference * float(1.0 / std::numbers::sqrt2), kQf), 1.0f);
  }
  return result;
}

std::vector<float> flip_error_map(const ImageRGB& test, const ImageRGB& reference,
                                  const FlipOptions& options) {
  FlipComponents components = flip_components(test, reference, options);
  std::vector<float>& error = components.color;
  for (size_t p = 0; p < error.size(); ++p)
    error[p] = std::pow(error[p], 1.0f - components.feature[p]);
  return std::move(components.color);
}

double flip_mean(const ImageRGB& test, const ImageRGB& reference, const FlipOptions& options) {
  const std::vector<float> error = flip_error_map(test, reference, options);
  if (error.empty()) return 0.0;
  double sum = 0.0;
  for (float e : error) sum += e;
  return sum / double(error.size());
}

}  // namespace hipr
