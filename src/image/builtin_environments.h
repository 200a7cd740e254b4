#pragma once
// Environments made by hipr's own code, for scenes that bring no light (most glTF assets expect
// a viewer's image-based lighting). Built as equirectangular maps so that they are sampled,
// edited (intensity, rotation) and shown exactly as a loaded .hdr is.
#include <filesystem>
#include <optional>
#include <string>

#include "hipr/scene.h"
#include "hipr/scene_loader.h"

namespace hipr {

// The names built-in environments carry as their Environment::path.
inline constexpr const char* kStudioEnvironmentName = "studio";
inline constexpr const char* kSkyEnvironmentName = "sky";

// Radiance (nits, linear RGB, grey) of the neutral studio toward `direction` (unit, +Y up,
// the camera's default view along -Z): a soft grey surround brighter above than below, a large
// key light in front, above and to the left, a dimmer fill on the right and a rim light behind.
// Low contrast (brightest to darkest about 8:1) and colour-neutral; a white diffuse surface
// facing up reflects about 1 nit, so images come out well exposed at --exposure 0.
glm::vec3 studio_radiance(glm::vec3 direction);

// studio_radiance sampled at the centres of a width x width/2 equirectangular map.
Environment make_studio_environment(uint32_t width = 1024);

// A clear daylight sky (SkyParameters, hipr/scene.h): Preetham, Shirley and Smits, "A
// Practical Analytic Model for Daylight" (SIGGRAPH 1999), and a sun attenuated by the same
// atmosphere; physical units (nits).
glm::vec3 sun_direction(const SkyParameters& sky);

// Throws InputError unless the sun is 0-90 degrees above the horizon, its azimuth finite and the
// turbidity within the model's range (kMinTurbidity..kMaxTurbidity).
void check_sky(const SkyParameters& sky);

// CIE xyY of the sky toward `direction` (above the horizon), Y in nits: the Perez distribution
// scaled by the model's zenith luminance and chromaticity.
glm::dvec3 preetham_sky_xyY(glm::vec3 direction, const SkyParameters& sky);

// A width x width/2 equirectangular map of linear Rec.709 radiance (nits): the sky above the
// horizon, the sun in the texel that holds its centre, and below the horizon a grey ground of
// albedo 0.2 lit by both.
Environment make_sky_environment(const SkyParameters& sky, uint32_t width = 1024);

// What lights the scene from afar, for logs and `hipr info`: "none", "studio (built in)",
// "sky (built in)" or the map's file name.
std::string environment_description(const Scene& scene);

// The command-line flags that bring the scene's environment back on reopening (glTF cannot hold
// it): --env NAME|FILE, the sky's parameters, and --env-intensity / --env-rotation where they
// differ from the defaults. "--env none" without one.
std::string environment_flags(const Scene& scene);

// Whether `source` names no file: "studio", "sky" or "none".
bool is_environment_name(const std::filesystem::path& source);

// The environment `source` names: "studio", "sky" (made with `sky`), "none" (nullopt) or an
// equirectangular .hdr/.exr file (InputError when it cannot be read). Intensity 1, rotation 0.
std::optional<Environment> make_environment(const std::filesystem::path& source,
                                            const SkyParameters& sky);

// What the scene brings to light itself: punctual lights on nodes, and the brightest emissive
// material of a visible instance (the largest channel of emission_color x emission_luminance,
// nits; textures not counted).
struct SceneLighting {
  size_t punctual_lights = 0;
  float brightest_emission = 0.0f;

  bool emits() const { return punctual_lights > 0 || brightest_emission > 0.0f; }
  // Whether the scene was made to be lit by its own lights: a punctual light, or an emitter
  // brighter than 1 nit. glTF's emissiveFactor stops at 1, so brighter emission was asked for
  // (KHR_materials_emissive_strength, or an exporter's area light); emission up to 1 nit is a
  // glow (a screen, the DamagedHelmet's decals) that expects the viewer's lighting besides.
  bool lights_itself() const { return punctual_lights > 0 || brightest_emission > 1.0f; }
};
SceneLighting scene_lighting(const Scene& scene);

}  // namespace hipr
