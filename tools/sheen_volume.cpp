// Random walks through the fuzz's fibre volume (sheen_volume.h).
//
// SGGX (Heitz et al. 2015) with matrix S: a direction w sees the projected area
// sigma(w) = sqrt(w^T S w), the extinction of a unit-density medium, and the flakes it meets
// are distributed as the visible normals of the ellipsoid x^T S x = 1. Those are sampled
// exactly: map the ellipsoid to the unit sphere (y = S^(1/2) x); lines parallel to w become
// lines parallel to S^(1/2) w, uniform over their projected disk; the point where such a line
// enters the sphere has the ellipsoid normal S^(1/2) y. A flake reflects specularly.
// The first flight is forced to interact inside the slab (weighted by the chance it does):
// at normal incidence most light passes the thin fibres without meeting any, and the forced
// flight keeps the estimate's relative noise low there.
#include "sheen_volume.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace hipr::tools {
namespace {

struct Vec {
  double x, y, z;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator*(double s, Vec a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec normalize(Vec a) { return (1.0 / std::sqrt(dot(a, a))) * a; }
Vec cross(Vec a, Vec b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Uniform in [0, 1) from 53 random bits: the same on every platform (std's distributions are not).
double uniform(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

struct Fibres {
  double sigma;  // alpha^2: S = diag(1, 1, sigma^2)
  double extinction(Vec d) const {
    return std::sqrt(d.x * d.x + d.y * d.y + sigma * sigma * d.z * d.z);
  }
  // A flake normal seen by light travelling along d (from the side -d).
  Vec visible_normal(Vec d, std::mt19937_64& rng) const {
    const Vec w = normalize({-d.x, -d.y, -sigma * d.z});  // S^(1/2) (-d)
    const Vec a = normalize(cross(w, std::abs(w.z) < 0.9 ? Vec{0, 0, 1} : Vec{1, 0, 0}));
    const Vec b = cross(w, a);
    const double r = std::sqrt(uniform(rng)), phi = 2.0 * M_PI * uniform(rng);
    const Vec y = (r * std::cos(phi)) * a + (r * std::sin(phi)) * b +
                  std::sqrt(std::max(0.0, 1.0 - r * r)) * w;
    return normalize({y.x, y.y, sigma * y.z});  // S^(1/2) y
  }
};

}  // namespace

double sheen_volume_albedo(double mu, double alpha, int paths, std::uint64_t seed) {
  const Fibres fibres{alpha * alpha};
  mu = std::clamp(mu, 1e-4, 1.0);
  const Vec in{-std::sqrt(1.0 - mu * mu), 0.0, -mu};
  // Chance that the first flight meets a flake before leaving through the bottom (depth 1).
  const double first = 1.0 - std::exp(-fibres.extinction(in) / mu);
  if (first <= 0.0) return 0.0;
  std::mt19937_64 rng(seed);
  long up = 0;
  for (int n = 0; n < paths; ++n) {
    Vec d = in;
    // The forced first flight: an exponential distance truncated to the slab.
    double z = 1.0 + d.z * (-std::log(1.0 - uniform(rng) * first) / fibres.extinction(d));
    for (int bounce = 0; bounce < 100000; ++bounce) {
      const Vec m = fibres.visible_normal(d, rng);
      d = d + (-2.0 * dot(d, m)) * m;
      z += d.z * (-std::log(1.0 - uniform(rng)) / fibres.extinction(d));
      if (z >= 1.0) {
        ++up;
        break;
      }
      if (z <= 0.0) break;
    }
  }
  return first * double(up) / paths;
}

}  // namespace hipr::tools
