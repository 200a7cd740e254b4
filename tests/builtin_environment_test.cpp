// The built-in environments (src/image/builtin_environments.h) and `--env auto`: the studio and
// the daylight sky as numbers, and which scenes the studio lights.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <glm/gtc/constants.hpp>
#include <utility>

#include "hipr/scene_loader.h"
#include "image/builtin_environments.h"
#include "test_support.h"

namespace hipr {
namespace {

constexpr float kPi = glm::pi<float>();

// Direction of texel (column, row)'s centre, written from the kernels' convention
// (shaders/common/environment.glsl: u = atan2(x, -z) / 2pi + 1/2, v = acos(y) / pi).
glm::vec3 texel_direction(const Environment& env, uint32_t column, uint32_t row) {
  const float theta = kPi * (float(row) + 0.5f) / float(env.height);
  const float phi = 2.0f * kPi * (float(column) + 0.5f) / float(env.width) - kPi;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

// Irradiance on a surface with normal n from the map as the kernels see it (texel-constant).
double irradiance(const Environment& env, glm::vec3 n) {
  double sum = 0.0;
  for (uint32_t row = 0; row < env.height; ++row) {
    const double solid_angle =
        (2.0 * kPi / env.width) * (kPi / env.height) * std::sin(kPi * (row + 0.5) / env.height);
    for (uint32_t column = 0; column < env.width; ++column) {
      const double c = glm::dot(n, texel_direction(env, column, row));
      if (c > 0.0) sum += env.texels[size_t(row) * env.width + column].x * c * solid_angle;
    }
  }
  return sum;
}

TEST(StudioEnvironment, IsNeutralFiniteAndLowContrast) {
  float low = 1e30f, high = 0.0f;
  for (int i = 0; i < 20000; ++i) {
    // A Fibonacci sphere of directions.
    const float y = 1.0f - 2.0f * (float(i) + 0.5f) / 20000.0f;
    const float r = std::sqrt(1.0f - y * y), phi = float(i) * 2.39996323f;
    const glm::vec3 radiance = studio_radiance({r * std::cos(phi), y, r * std::sin(phi)});
    ASSERT_TRUE(std::isfinite(radiance.x));
    EXPECT_EQ(radiance.x, radiance.y);
    EXPECT_EQ(radiance.y, radiance.z);
    low = std::min(low, radiance.x);
    high = std::max(high, radiance.x);
  }
  EXPECT_GT(low, 0.0f);
  EXPECT_LT(high / low, 10.0f);  // soft: no point light, no black region
  EXPECT_GT(high / low, 3.0f);   // but it has a key light: shapes read
}

TEST(StudioEnvironment, MapHoldsTheFunctionAtTexelCentres) {
  const Environment env = make_studio_environment(64);
  ASSERT_EQ(env.width, 64u);
  ASSERT_EQ(env.height, 32u);
  EXPECT_EQ(env.path, kStudioEnvironmentName);
  for (uint32_t row = 0; row < env.height; row += 3)
    for (uint32_t column = 0; column < env.width; column += 5)
      EXPECT_NEAR(env.texels[size_t(row) * env.width + column].x,
                  studio_radiance(texel_direction(env, column, row)).x, 1e-5f);
}

TEST(StudioEnvironment, AWhiteFloorReflectsAboutOneNit) {
  // What --exposure 0 shows well: a white diffuse surface facing up reflects E / pi.
  const double reflected = irradiance(make_studio_environment(), {0.0f, 1.0f, 0.0f}) / kPi;
  EXPECT_GT(reflected, 0.7);
  EXPECT_LT(reflected, 1.4);
}

// Preetham et al.'s published model, evaluated by hand (T = 2, sun 30 degrees from the zenith):
// zenith luminance (4.0453 T - 4.9710) tan(chi) - 0.2155 T + 2.4192 = 5.8867 kcd/m^2 with
// chi = (4/9 - T/120)(pi - 2 theta_s); zenith chromaticity from the appendix's cubics
// (0.25142, 0.25592); toward the horizon opposite the sun (zenith angle 80, gamma 110 degrees)
// the Perez ratio F(80, 110) / F(0, 30) = 1.86630.
TEST(SkyEnvironment, MatchesThePublishedModel) {
  SkyParameters sky;
  sky.turbidity = 2.0f;
  sky.sun_elevation_degrees = 60.0f;
  sky.sun_azimuth_degrees = 0.0f;
  const glm::dvec3 zenith = preetham_sky_xyY({0.0f, 1.0f, 0.0f}, sky);
  EXPECT_NEAR(zenith.z, 5886.74, 0.05);
  EXPECT_NEAR(zenith.x, 0.251421, 1e-6);
  EXPECT_NEAR(zenith.y, 0.255924, 1e-6);
  const float e = glm::radians(10.0f);
  const glm::dvec3 horizon = preetham_sky_xyY({0.0f, std::sin(e), -std::cos(e)}, sky);
  EXPECT_NEAR(horizon.z, 5886.74 * 1.866303, 0.1);
  // A clear sky is blue overhead.
  const Environment env = make_sky_environment(sky, 256);
  const glm::vec3 top = env.texels[size_t(0) * env.width + 3];
  EXPECT_GT(top.b, 1.2f * top.r);
}

// Illuminance (lux) on a horizontal plane from the map's upper half: all of it, and the part
// from texels dimmer than 10^6 nits (the sky without the sun's texel).
std::pair<double, double> horizontal_illuminance(const Environment& env) {
  double all = 0.0, sky = 0.0;
  for (uint32_t row = 0; row < env.height / 2; ++row) {
    const double solid_angle =
        (2.0 * kPi / env.width) * (kPi / env.height) * std::sin(kPi * (row + 0.5) / env.height);
    for (uint32_t column = 0; column < env.width; ++column) {
      const glm::vec3 t = env.texels[size_t(row) * env.width + column];
      const double e = (0.2126 * t.r + 0.7152 * t.g + 0.0722 * t.b) *
                       texel_direction(env, column, row).y * solid_angle;
      all += e;
      sky += t.g < 1e6f ? e : 0.0;
    }
  }
  return {all, sky};
}

TEST(SkyEnvironment, DaylightOnTheGroundIsPhysical) {
  SkyParameters sky;
  // The sun overhead through air of turbidity 3: ~96,000 lux direct (measured clear days:
  // 90,000-100,000).
  sky.sun_elevation_degrees = 90.0f;
  const auto [overhead, overhead_sky] = horizontal_illuminance(make_sky_environment(sky));
  EXPECT_GT(overhead - overhead_sky, 85000.0);
  EXPECT_LT(overhead - overhead_sky, 105000.0);
  // The sun 60 degrees up in clear air: about 100,000 lux in all, as measured. (Preetham's
  // skylight is brighter than measured skies, the more so with a high sun in hazy air:
  // Zotti, Wilkie and Purgathofer, "A Critical Review of the Preetham Skylight Model", 2007.
  // Overhead at turbidity 3 it gives 40,000 lux of skylight against some 20,000 measured.)
  sky.sun_elevation_degrees = 60.0f;
  sky.turbidity = 2.0f;
  const double clear = horizontal_illuminance(make_sky_environment(sky)).first;
  EXPECT_GT(clear, 85000.0);
  EXPECT_LT(clear, 130000.0);
  // Low sun, hazy air: much less, and warmer (red over blue).
  sky.sun_elevation_degrees = 10.0f;
  sky.turbidity = 6.0f;
  const Environment evening = make_sky_environment(sky, 512);
  EXPECT_LT(horizontal_illuminance(evening).first, 0.25 * clear);
  glm::vec3 brightest(0.0f);
  for (const glm::vec3& t : evening.texels)
    if (t.g > brightest.g) brightest = t;
  EXPECT_GT(brightest.r, 1.3f * brightest.b);  // the sun's texel
  for (const glm::vec3& t : evening.texels)
    ASSERT_TRUE(std::isfinite(t.r) && t.r >= 0.0f && t.b >= 0.0f);
}

TEST(EnvironmentChoice, AutoLightsOnlyScenesWithoutLight) {
  SceneLoadOptions options;
  options.environment = kAutoEnvironment;
  const Scene unlit = load_scene(test::asset("furnace_sphere.gltf"), options);
  EXPECT_FALSE(scene_lighting(unlit).emits());
  ASSERT_TRUE(unlit.environment.has_value());
  EXPECT_EQ(environment_description(unlit), "studio (built in)");

  const Scene lit = load_scene(test::asset("cornell_box.gltf"), options);
  EXPECT_TRUE(scene_lighting(lit).lights_itself());
  EXPECT_FALSE(lit.environment.has_value());
  EXPECT_EQ(environment_description(lit), "none");

  options.environment = kStudioEnvironmentName;
  EXPECT_TRUE(load_scene(test::asset("cornell_box.gltf"), options).environment.has_value());
  options.environment = kSkyEnvironmentName;
  EXPECT_EQ(environment_description(load_scene(test::asset("furnace_sphere.gltf"), options)),
            "sky (built in)");
  options.environment = kNoEnvironment;
  EXPECT_FALSE(load_scene(test::asset("furnace_sphere.gltf"), options).environment.has_value());
  // Emission up to 1 nit is a glow, not a light: the studio lights the scene besides.
  Scene glowing = load_scene(test::asset("furnace_sphere.gltf"));
  for (Material& m : glowing.materials) {
    m.params.emission_color = glm::vec3(1.0f);
    m.params.emission_luminance = 1.0f;
  }
  EXPECT_TRUE(scene_lighting(glowing).emits());
  EXPECT_FALSE(scene_lighting(glowing).lights_itself());
  for (Material& m : glowing.materials) m.params.emission_luminance = 1.5f;
  EXPECT_TRUE(scene_lighting(glowing).lights_itself());
  // The library's default is no environment, as before.
  EXPECT_FALSE(load_scene(test::asset("furnace_sphere.gltf")).environment.has_value());
}

TEST(EnvironmentChoice, EverySharedSceneIsLitWithNoFlags) {
  // The shared real scenes (skipped when ../shared is not there): each brings its own light or
  // gets the studio, so none renders black.
  const std::filesystem::path shared = HIPR_SHARED_SCENES_DIR;
  if (!std::filesystem::is_directory(shared)) GTEST_SKIP() << "no shared scenes at " << shared;
  SceneLoadOptions options;
  options.environment = kAutoEnvironment;
  int scenes = 0;
  for (const auto& folder : std::filesystem::directory_iterator(shared)) {
    if (!folder.is_directory() || folder.path().filename() == "InvalidInputs") continue;
    for (const auto& file : std::filesystem::directory_iterator(folder.path())) {
      const std::string extension = file.path().extension().string();
      if (extension != ".gltf" && extension != ".glb") continue;
      const Scene scene = load_scene(file.path(), options);
      EXPECT_TRUE(scene.environment.has_value() || scene_lighting(scene).lights_itself())
          << file.path();
      ++scenes;
    }
  }
  EXPECT_GT(scenes, 5);
}

TEST(EnvironmentChoice, StudioIntensityAndRotationApply) {
  SceneLoadOptions options;
  options.environment = kStudioEnvironmentName;
  options.environment_intensity = 2.5f;
  options.environment_rotation_degrees = 90.0f;
  const Scene scene = load_scene(test::asset("furnace_sphere.gltf"), options);
  ASSERT_TRUE(scene.environment.has_value());
  EXPECT_EQ(scene.environment->intensity, 2.5f);
  EXPECT_NEAR(scene.environment->rotation, kPi / 2.0f, 1e-6f);
}

TEST(EnvironmentChoice, FlagsBringTheEnvironmentBack) {
  // What the viewer tells after a save (glTF holds no environment).
  SceneLoadOptions options;
  options.environment = kSkyEnvironmentName;
  options.sky.sun_elevation_degrees = 25.0f;
  options.sky.turbidity = 4.5f;
  Scene scene = load_scene(test::asset("furnace_sphere.gltf"), options);
  EXPECT_EQ(environment_flags(scene),
            "--env sky --sun-elevation 25 --sun-azimuth 30 --turbidity 4.5");
  scene.environment->intensity = 2.0f;
  scene.environment->rotation = kPi / 2.0f;
  EXPECT_EQ(environment_flags(scene),
            "--env sky --sun-elevation 25 --sun-azimuth 30 --turbidity 4.5 --env-intensity 2 "
            "--env-rotation 90");
  options.environment = kAutoEnvironment;
  EXPECT_EQ(environment_flags(load_scene(test::asset("furnace_sphere.gltf"), options)),
            "--env studio");
  EXPECT_EQ(environment_flags(load_scene(test::asset("cornell_box.gltf"), options)), "--env none");
}

TEST(EnvironmentChoice, StudioFurnace) {
  // A white Lambert sphere under the studio: convex, so every point reflects its irradiance
  // over pi once. The pixels at the centre see the point facing the camera (normal +Z).
  SceneLoadOptions options;
  options.environment = kStudioEnvironmentName;
  const Scene scene = load_scene(test::asset("furnace_sphere.gltf"), options);
  RenderSettings s;
  s.width = s.height = 32;
  s.max_depth = 8;
  s.seed = 5;
  const ImageRGB image = test::render_finite(scene, s, 256);
  double centre = 0.0;
  for (uint32_t y = 15; y <= 16; ++y)
    for (uint32_t x = 15; x <= 16; ++x)
      for (int c = 0; c < 3; ++c) centre += image.rgb[(size_t(y) * 32 + x) * 3 + c] / 12.0;
  const double expected = irradiance(*scene.environment, {0.0f, 0.0f, 1.0f}) / kPi;
  EXPECT_NEAR(centre, expected, 0.04 * expected);
}

}  // namespace
}  // namespace hipr
