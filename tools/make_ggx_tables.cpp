// Generates shaders/bsdf/ggx_energy_table.glsl: directional albedos of GGX lobes that the BSDF
// needs for energy compensation and layering, all in one float array (the kernels read it from
// one storage buffer, C++ from the array):
//  - E(mu, roughness) of single-scattering GGX reflection with F = 1, and its cosine-weighted
//    average E_avg (the metal's multiple-scattering compensation of Kulla & Conty 2017, and the
//    thin-walled dielectric, whose slab reflects and transmits all that one bounce does not lose);
//  - E_r(mu, roughness, eta): dielectric reflection with exact Fresnel, and its average, entering
//    (eta > 1) and leaving (eta < 1, total internal reflection included) (the albedo scaling of
//    the diffuse base under the specular layer, and of the base under the coat);
//  - E_rt(mu, roughness, eta): reflection plus refraction of a dielectric interface, entering
//    (eta > 1) and leaving (eta < 1) (the compensation of rough glass);
//  - R(mu, alpha) of the fuzz (fuzz.glsl): the albedo of the fibre volume the LTC sheen stands
//    for, from random walks through it (sheen_volume.cpp), on the LTC sheen's own grid (mu and
//    alpha uniform, 32 x 32).
// It integrates the very GGX code the kernels run with a stratified, fixed sample grid, so the
// output is the same on every run. Usage: make_ggx_tables OUTPUT.glsl
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <glm/glm.hpp>

namespace hipr::shader {
using namespace glm;
#include "shaders/bsdf/dielectric.glsl"
}  // namespace hipr::shader

#include "sheen_volume.h"

namespace {

using hipr::shader::vec2;
using hipr::shader::vec3;

constexpr int kGgxSize = 32;            // mu x roughness resolution of the F = 1 table
constexpr int kDielectricSize = 32;     // mu x roughness resolution of the dielectric tables
constexpr int kDielectricEtaSize = 16;  // ... and their eta rows (the albedo varies slowly in eta)
constexpr int kStrata = 64;             // kStrata^2 samples per entry
constexpr int kFuzzSize = 32;           // mu x alpha resolution of the fuzz table
constexpr int kFuzzPaths =
    100000;  // random walks per fuzz entry (relative noise ~1 % where R ~ 0.02)

// The grids the lookups in shaders/bsdf/energy_tables.glsl invert.
float grid_mu(int i, int size) {
  const float t = float(i) / float(size - 1);
  return std::max(t * t, 1e-4f);  // sqrt(mu) uniform; mu = 0 is undefined
}
float grid_roughness(int i, int size) { return float(i) / float(size - 1); }
// eta in [1, 3] through x = (eta - 1) / (eta + 1) uniform over [0, 0.5].
float grid_eta(int i, int size) {
  const float x = 0.5f * float(i) / float(size - 1);
  return (1.0f + x) / (1.0f - x);
}

// Mean over a stratified grid of visible normals of `weight(wo, m)`.
double integrate(float mu, float roughness, const std::function<double(vec3, vec3, vec2)>& weight) {
  const vec2 alpha(hipr::shader::ggx_alpha(roughness));
  const vec3 wo(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu);
  double sum = 0.0;
  for (int i = 0; i < kStrata; ++i)
    for (int j = 0; j < kStrata; ++j) {
      const vec2 u((i + 0.5f) / kStrata, (j + 0.5f) / kStrata);
      sum += weight(wo, hipr::shader::ggx_sample_visible_normal(wo, alpha, u), alpha);
    }
  return std::min(sum / (kStrata * kStrata), 1.0);
}

// Sample weight f cos / pdf of the reflection about m, times the event's probability `p`.
double reflection_weight(vec3 wo, vec3 m, vec2 alpha, double p) {
  using namespace hipr::shader;
  const vec3 wi = 2.0f * dot(wo, m) * m - wo;
  return wi.z > 0.0f ? p * ggx_g2(wo, wi, alpha) / ggx_g1(wo, alpha) : 0.0;
}

double refraction_weight(vec3 wo, vec3 m, vec2 alpha, float eta, double p) {
  using namespace hipr::shader;
  vec3 wi;
  if (!refract_through(wo, m, eta, wi) || wi.z >= 0.0f) return 0.0;
  return p * ggx_g2(wo, wi, alpha) / ggx_g1(wo, alpha);
}

// 2 * integral of E(mu) mu dmu, trapezoid rule on the sqrt(mu) grid of `row`.
double cosine_average(const double* row, int size) {
  double avg = 0.0;
  for (int m = 0; m + 1 < size; ++m) {
    const double t0 = double(m) / (size - 1), t1 = double(m + 1) / (size - 1);
    const double mu0 = t0 * t0, mu1 = t1 * t1;
    avg += (row[m] * mu0 + row[m + 1] * mu1) * (mu1 - mu0);
  }
  return std::min(avg, 1.0);
}

struct Table {
  std::string name;
  std::string layout;
  std::vector<double> values;
};

Table ggx_energy() {
  Table t{"kTableGgxEnergy", "[roughness][mu]", {}};
  for (int r = 0; r < kGgxSize; ++r)
    for (int m = 0; m < kGgxSize; ++m)
      t.values.push_back(
          integrate(grid_mu(m, kGgxSize), grid_roughness(r, kGgxSize),
                    [](vec3 wo, vec3 h, vec2 a) { return reflection_weight(wo, h, a, 1.0); }));
  return t;
}

Table averages(const Table& source, const std::string& name, int size) {
  Table t{name, "[rows of " + source.name + "]", {}};
  for (size_t row = 0; row < source.values.size(); row += size_t(size))
    t.values.push_back(cosine_average(&source.values[row], size));
  return t;
}

// A [eta][roughness][mu] table of the dielectric albedo `weight` at relative index eta or 1/eta.
Table dielectric(const std::string& name, bool leaving, bool refraction) {
  Table t{name, "[eta][roughness][mu]", {}};
  const int n = kDielectricSize;
  for (int e = 0; e < kDielectricEtaSize; ++e) {
    const float eta =
        leaving ? 1.0f / grid_eta(e, kDielectricEtaSize) : grid_eta(e, kDielectricEtaSize);
    for (int r = 0; r < n; ++r)
      for (int m = 0; m < n; ++m)
        t.values.push_back(
            integrate(grid_mu(m, n), grid_roughness(r, n), [&](vec3 wo, vec3 h, vec2 a) {
              const double f = hipr::shader::fresnel_dielectric(hipr::shader::dot(wo, h), eta);
              return reflection_weight(wo, h, a, f) +
                     (refraction ? refraction_weight(wo, h, a, eta, 1.0 - f) : 0.0);
            }));
  }
  return t;
}

// R(mu, alpha) on a [alpha][mu] grid, both uniform over [0, 1]. Each entry has its own seed, so
// the table is the same however the entries are shared among threads.
Table fuzz_albedo() {
  Table t{"kTableFuzzAlbedo", "[alpha][mu], mu (not its square root) uniform",
          std::vector<double>(kFuzzSize * kFuzzSize)};
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> workers;
  for (unsigned w = 0; w < threads; ++w)
    workers.emplace_back([&t, w, threads] {
      for (size_t i = w; i < t.values.size(); i += threads) {
        const int a = int(i) / kFuzzSize, m = int(i) % kFuzzSize;
        t.values[i] = hipr::tools::sheen_volume_albedo(
            double(m) / (kFuzzSize - 1), double(a) / (kFuzzSize - 1), kFuzzPaths, 1000u + i);
      }
    });
  for (std::thread& worker : workers) worker.join();
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_ggx_tables OUTPUT.glsl\n");
    return 2;
  }
  std::vector<Table> tables;
  tables.push_back(ggx_energy());
  tables.push_back(averages(tables.back(), "kTableGgxEnergyAverage", kGgxSize));
  tables.push_back(dielectric("kTableDielectricReflection", false, false));
  tables.push_back(averages(tables.back(), "kTableDielectricReflectionAverage", kDielectricSize));
  tables.push_back(dielectric("kTableDielectricReflectionLeaving", true, false));
  tables.push_back(
      averages(tables.back(), "kTableDielectricReflectionLeavingAverage", kDielectricSize));
  tables.push_back(dielectric("kTableDielectricEntering", false, true));
  tables.push_back(dielectric("kTableDielectricLeaving", true, true));
  tables.push_back(fuzz_albedo());

  std::ostringstream out;
  out << "// Generated by tools/make_ggx_tables.cpp; do not edit. Lookups: energy_tables.glsl.\n"
      << "// One float array; each table starts at its offset. Axes: mu with sqrt(mu) uniform over "
         "[0, 1],\n"
      << "// roughness uniform over [0, 1], eta through (eta - 1) / (eta + 1) uniform over [0, "
         "0.5].\n"
      << "// C++ sees the array; kernels read the same numbers from a storage buffer that the\n"
      << "// renderer fills from it (big constant arrays are slow on CPU Vulkan devices).\n"
      << "#ifndef HIPR_GGX_ENERGY_TABLE_GLSL\n#define HIPR_GGX_ENERGY_TABLE_GLSL\n\n"
      << "#define kGgxTableSize " << kGgxSize << "\n#define kDielectricTableSize "
      << kDielectricSize << "\n#define kDielectricTableEtaSize " << kDielectricEtaSize
      << "\n#define kFuzzTableSize " << kFuzzSize << "\n";
  size_t offset = 0;
  for (const Table& t : tables) {
    out << "#define " << t.name << " " << offset << "  // " << t.layout << "\n";
    offset += t.values.size();
  }
  out << "#define kBsdfTableFloats " << offset
      << "\n\n#ifdef __cplusplus\ninline const float kBsdfTables[" << offset << "] = {\n";
  size_t i = 0;
  for (const Table& t : tables)
    for (double v : t.values) {
      out << (i % 8 == 0 ? "  " : " ") << std::fixed << std::setprecision(6) << v << "f"
          << (i + 1 < offset ? "," : "") << (i % 8 == 7 || i + 1 == offset ? "\n" : "");
      ++i;
    }
  out << "};\n#endif\n\n#endif\n";
  std::ofstream(argv[1]) << out.str();
  return 0;
}
