#include "image/builtin_environments.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/gtc/constants.hpp>

#include "core/error.h"
#include "image/environment_loader.h"

namespace hipr {

namespace {

constexpr float kPi = glm::pi<float>();

// The centre of texel (column, row) of a width x height equirectangular map, in the kernels'
// convention (shaders/common/environment.glsl, top row = +Y): u = atan2(x, -z) / 2pi + 1/2,
// v = acos(y) / pi.
glm::vec3 texel_direction(uint32_t width, uint32_t height, uint32_t column, uint32_t row) {
  const float theta = kPi * (float(row) + 0.5f) / float(height);
  const float phi = 2.0f * kPi * ((float(column) + 0.5f) / float(width) - 0.5f);
  return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

// Solid angle of a texel of `row`.
double texel_solid_angle(uint32_t width, uint32_t height, uint32_t row) {
  return (2.0 * kPi / width) * (kPi / height) * std::sin(kPi * (row + 0.5) / height);
}

double luminance(glm::dvec3 rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

// A soft area light as seen from the centre: a smooth bump around `axis`, `radiance` at its
// centre, falling to half at about `half_angle_degrees` (a power of the cosine, so no edge).
float soft_light(glm::vec3 direction, glm::vec3 axis, float radiance, float half_angle_degrees) {
  const float c = glm::dot(direction, glm::normalize(axis));
  if (c <= 0.0f) return 0.0f;
  const float exponent = std::log(0.5f) / std::log(std::cos(glm::radians(half_angle_degrees)));
  return radiance * std::pow(c, exponent);
}

}  // namespace

glm::vec3 studio_radiance(glm::vec3 direction) {
  const glm::vec3 d = glm::normalize(direction);
  // Surround: 0.25 nit straight down (a dark grey floor far away), 0.6 at the top.
  const float t = 0.5f * (d.y + 1.0f);
  float radiance = 0.25f + 0.35f * t * t * (3.0f - 2.0f * t);
  radiance += soft_light(d, {-0.55f, 0.6f, 0.6f}, 1.5f, 30.0f);  // key: front, above, left
  radiance += soft_light(d, {0.8f, 0.15f, 0.45f}, 0.6f, 35.0f);  // fill: right, low
  radiance += soft_light(d, {0.1f, 0.45f, -0.9f}, 0.8f, 20.0f);  // rim: behind, above
  return glm::vec3(radiance);
}

Environment make_studio_environment(uint32_t width) {
  Environment env;
  env.path = kStudioEnvironmentName;
  env.width = width;
  env.height = width / 2;
  env.texels.resize(size_t(env.width) * env.height);
  for (uint32_t row = 0; row < env.height; ++row)
    for (uint32_t column = 0; column < env.width; ++column)
      env.texels[size_t(row) * env.width + column] =
          studio_radiance(texel_direction(env.width, env.height, column, row));
  return env;
}

// --- Sky -------------------------------------------------------------------------------------

namespace {

// Perez et al.'s luminance distribution (1993) with Preetham's coefficients for Y, x and y,
// each linear in the turbidity T (the paper's appendix).
struct Perez {
  double a, b, c, d, e;
  double operator()(double theta, double gamma) const {
    const double cos_gamma = std::cos(gamma);
    return (1.0 + a * std::exp(b / std::cos(theta))) *
           (1.0 + c * std::exp(d * gamma) + e * cos_gamma * cos_gamma);
  }
};

Perez perez_Y(double t) {
  return {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771,
          -0.0670 * t + 0.3703};
}
Perez perez_x(double t) {
  return {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989,
          -0.0033 * t + 0.0452};
}
Perez perez_y(double t) {
  return {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537,
          -0.0109 * t + 0.0529};
}

// Zenith chromaticity: T^2, T and 1 times a cubic in the sun's zenith angle.
double zenith_chromaticity(const double (&m)[3][4], double t, double theta_sun) {
  const double th[4] = {theta_sun * theta_sun * theta_sun, theta_sun * theta_sun, theta_sun, 1.0};
  double row[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) row[i] += m[i][j] * th[j];
  return t * t * row[0] + t * row[1] + row[2];
}

constexpr double kZenithX[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                   {-0.02903, 0.06377, -0.03202, 0.00394},
                                   {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double kZenithY[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                   {-0.04214, 0.08970, -0.04153, 0.00516},
                                   {0.15346, -0.26756, 0.06670, 0.26688}};

// CIE XYZ -> linear Rec.709 (sRGB primaries, D65).
glm::dvec3 xyz_to_rec709(glm::dvec3 xyz) {
  return {3.2406 * xyz.x - 1.5372 * xyz.y - 0.4986 * xyz.z,
          -0.9689 * xyz.x + 1.8758 * xyz.y + 0.0415 * xyz.z,
          0.0557 * xyz.x - 0.2040 * xyz.y + 1.0570 * xyz.z};
}

glm::dvec3 xyY_to_rec709(glm::dvec3 xyY) {
  if (xyY.y <= 0.0) return glm::dvec3(0.0);
  const double scale = xyY.z / xyY.y;
  return glm::max(xyz_to_rec709({xyY.x * scale, xyY.z, (1.0 - xyY.x - xyY.y) * scale}),
                  glm::dvec3(0.0));
}

// The sun: 128,000 lux outside the atmosphere (taken as white); through the atmosphere,
// Rayleigh and aerosol optical depths at 680, 550 and 440 nm (Angstrom: beta = 0.04608 T -
// 0.04586, alpha 1.3, as Preetham et al. relate haze to turbidity) along Kasten and Young's
// relative air mass.
constexpr double kSunIlluminance = 128000.0;

glm::dvec3 sun_illuminance(const SkyParameters& sky) {
  const double elevation = std::max(double(sky.sun_elevation_degrees), 0.0);
  const double air_mass =
      1.0 / (std::sin(glm::radians(elevation)) + 0.50572 * std::pow(elevation + 6.07995, -1.6364));
  const double beta = 0.04608 * sky.turbidity - 0.04586;
  const glm::dvec3 wavelength_um(0.680, 0.550, 0.440);
  glm::dvec3 transmittance;
  for (int c = 0; c < 3; ++c) {
    const double l = wavelength_um[c], l2 = l * l, l4 = l2 * l2;
    const double rayleigh = 0.008569 / l4 * (1.0 + 0.0113 / l2 + 0.00013 / l4);
    const double aerosol = beta * std::pow(l, -1.3);
    transmittance[c] = std::exp(-air_mass * (rayleigh + aerosol));
  }
  return kSunIlluminance * transmittance;
}

}  // namespace

glm::vec3 sun_direction(const SkyParameters& sky) {
  const float e = glm::radians(sky.sun_elevation_degrees),
              a = glm::radians(sky.sun_azimuth_degrees);
  return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

void check_sky(const SkyParameters& sky) {
  if (!(sky.sun_elevation_degrees >= 0.0f && sky.sun_elevation_degrees <= 90.0f))
    throw InputError("the sun's elevation must be between 0 and 90 degrees");
  if (!std::isfinite(sky.sun_azimuth_degrees)) throw InputError("the sun's azimuth must be finite");
  if (!(sky.turbidity >= kMinTurbidity && sky.turbidity <= kMaxTurbidity))
    throw InputError("the turbidity must be between 1.7 and 10");
}

glm::dvec3 preetham_sky_xyY(glm::vec3 direction, const SkyParameters& sky) {
  const glm::dvec3 d = glm::normalize(glm::dvec3(direction));
  const glm::dvec3 sun = glm::dvec3(sun_direction(sky));
  const double t = sky.turbidity;
  // The model holds above the horizon; its 1/cos(theta) term diverges there, so directions
  // within half a degree of it take the value half a degree up.
  const double theta = std::min(std::acos(std::clamp(d.y, -1.0, 1.0)), glm::radians(89.5));
  const double theta_sun = std::acos(std::clamp(sun.y, 0.0, 1.0));
  const double gamma = std::acos(std::clamp(glm::dot(d, sun), -1.0, 1.0));
  const double chi = (4.0 / 9.0 - t / 120.0) * (3.14159265358979323846 - 2.0 * theta_sun);
  const double zenith_Y =
      1000.0 * ((4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192);  // kcd/m^2 -> nits
  const Perez fY = perez_Y(t), fx = perez_x(t), fy = perez_y(t);
  return {zenith_chromaticity(kZenithX, t, theta_sun) * fx(theta, gamma) / fx(0.0, theta_sun),
          zenith_chromaticity(kZenithY, t, theta_sun) * fy(theta, gamma) / fy(0.0, theta_sun),
          zenith_Y * fY(theta, gamma) / fY(0.0, theta_sun)};
}

Environment make_sky_environment(const SkyParameters& sky, uint32_t width) {
  Environment env;
  env.path = kSkyEnvironmentName;
  env.sky = sky;
  env.width = width;
  env.height = width / 2;
  env.texels.assign(size_t(env.width) * env.height, glm::vec3(0.0f));
  // Sky above the horizon; its irradiance on the ground on the way.
  double ground_irradiance = 0.0;
  for (uint32_t row = 0; row < env.height / 2; ++row) {
    for (uint32_t column = 0; column < env.width; ++column) {
      const glm::vec3 d = texel_direction(env.width, env.height, column, row);
      const glm::dvec3 rgb = xyY_to_rec709(preetham_sky_xyY(d, sky));
      env.texels[size_t(row) * env.width + column] = glm::vec3(rgb);
      ground_irradiance += luminance(rgb) * d.y * texel_solid_angle(env.width, env.height, row);
    }
  }
  // The sun's disc (0.53 degrees) is smaller than a texel at any useful resolution: its
  // illuminance goes into the texel that holds its centre (the power is right; the disc is a
  // texel wide, 0.35 degrees at the default 1024 columns).
  const glm::vec3 sun = sun_direction(sky);
  const glm::dvec3 sun_rgb = sun_illuminance(sky);
  if (sun.y > 0.0f) {
    const float u = std::atan2(sun.x, -sun.z) / (2.0f * kPi) + 0.5f, v = std::acos(sun.y) / kPi;
    const uint32_t column = std::min(uint32_t(u * float(env.width)), env.width - 1);
    const uint32_t row = std::min(uint32_t(v * float(env.height)), env.height - 1);
    env.texels[size_t(row) * env.width + column] +=
        glm::vec3(sun_rgb / texel_solid_angle(env.width, env.height, row));
    ground_irradiance += luminance(sun_rgb) * double(sun.y);
  }
  // Ground: grey, albedo 0.2, Lambertian under that irradiance.
  const glm::vec3 ground(float(0.2 * ground_irradiance / kPi));
  for (uint32_t row = env.height / 2; row < env.height; ++row)
    for (uint32_t column = 0; column < env.width; ++column)
      env.texels[size_t(row) * env.width + column] = ground;
  return env;
}

std::string environment_description(const Scene& scene) {
  if (!scene.environment) return "none";
  if (scene.environment->path == kStudioEnvironmentName) return "studio (built in)";
  if (scene.environment->path == kSkyEnvironmentName) return "sky (built in)";
  return scene.environment->path.filename().string();
}

std::string environment_flags(const Scene& scene) {
  if (!scene.environment) return std::string("--env ") + kNoEnvironment;
  const Environment& env = *scene.environment;
  const auto number = [](float value) {
    std::ostringstream out;
    out << value;
    return out.str();
  };
  std::string flags = "--env ";
  if (env.path == kSkyEnvironmentName)
    flags += std::string(kSkyEnvironmentName) + " --sun-elevation " +
             number(env.sky.sun_elevation_degrees) + " --sun-azimuth " +
             number(env.sky.sun_azimuth_degrees) + " --turbidity " + number(env.sky.turbidity);
  else if (env.path == kStudioEnvironmentName)
    flags += kStudioEnvironmentName;
  else
    flags += env.path.string();
  if (env.intensity != 1.0f) flags += " --env-intensity " + number(env.intensity);
  if (env.rotation != 0.0f) flags += " --env-rotation " + number(glm::degrees(env.rotation));
  return flags;
}

bool is_environment_name(const std::filesystem::path& source) {
  return source == kStudioEnvironmentName || source == kSkyEnvironmentName ||
         source == kNoEnvironment;
}

std::optional<Environment> make_environment(const std::filesystem::path& source,
                                            const SkyParameters& sky) {
  if (source == kNoEnvironment) return std::nullopt;
  if (source == kStudioEnvironmentName) return make_studio_environment();
  if (source == kSkyEnvironmentName) return make_sky_environment(sky);
  return load_environment(source);
}

SceneLighting scene_lighting(const Scene& scene) {
  SceneLighting lighting;
  lighting.punctual_lights = scene.light_nodes().size();
  for (const Instance& instance : scene.instances()) {
    if (!instance.visible) continue;
    for (const MeshPrimitive& p : scene.meshes[instance.mesh].primitives) {
      const MaterialParameters& m = scene.materials[p.material].params;
      for (int c = 0; c < 3; ++c) {
        const float emission = m.emission_color[c] * m.emission_luminance;
        if (std::isfinite(emission))
          lighting.brightest_emission = std::max(lighting.brightest_emission, emission);
      }
    }
  }
  return lighting;
}

}  // namespace hipr
