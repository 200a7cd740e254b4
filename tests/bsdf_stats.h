#pragma once
// Generic statistical checks for BSDF lobes, so each lobe test is a few lines:
// chi-square goodness of fit of sample() against pdf() over the whole sphere, the integral of
// pdf(), and the directional albedo (white furnace) estimated from sample weights.
#include <functional>
#include <optional>

#include <glm/glm.hpp>

namespace hipr::test {

struct DirectionSample {
  glm::vec3 direction;  // unit
  glm::vec3 weight;     // f * |cos| / pdf
};

using SampleFn = std::function<std::optional<DirectionSample>(glm::vec2 u, float u_lobe)>;
using PdfFn = std::function<float(glm::vec3 direction)>;

struct ChiSquareResult {
  double statistic = 0.0;
  int degrees_of_freedom = 0;
  double p_value = 0.0;
  double pdf_integral = 0.0;      // of pdf() over the sphere
  double sampled_fraction = 0.0;  // of sample() calls that returned a direction
};

// Bins directions on an equal-area (cos theta, phi) grid; expected counts integrate pdf() per
// bin; bins expecting fewer than 5 samples are pooled. Deterministic (fixed-seed RNG).
ChiSquareResult chi_square_sphere(const SampleFn& sample, const PdfFn& pdf, int samples = 200000,
                                  int z_bins = 20, int phi_bins = 40);

// Mean of sample weights: the directional albedo. Failed samples count as zero.
glm::dvec3 albedo(const SampleFn& sample, int samples = 200000);

// Integral over the upper hemisphere (z > 0) with a midpoint rule uniform in (z, phi):
// deterministic and accurate for smooth integrands, for checks tighter than sampling allows.
double hemisphere_integral(const std::function<double(glm::vec3 direction)>& f, int z_steps = 256,
                           int phi_steps = 256);

// Upper regularized incomplete gamma Q(a, x): the chi-square p-value is Q(dof/2, stat/2).
double gamma_q(double a, double x);

}  // namespace hipr::test
