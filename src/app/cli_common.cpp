#include "app/cli_common.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/error.h"
#include "shaders/shared/abi.h"

namespace hipr::app {

void add_common_options(CLI::App& app, CommonOptions& o) {
  app.add_option("--width", o.render.width, "Image width in pixels")->capture_default_str();
  app.add_option("--height", o.render.height, "Image height in pixels")->capture_default_str();
  app.add_option("--spp", o.spp, "Samples per pixel to converge to")->capture_default_str();
  app.add_option("--seed", o.render.seed, "Random seed")->capture_default_str();
  app.add_option("--sampler", o.sampler,
                 "Random numbers of paths: sobol (scrambled Sobol, lower error) or random "
                 "(independent hashes)")
      ->capture_default_str();
  app.add_option("--light-selection", o.light_selection,
                 "How a point picks the light it samples: tree (the light tree: the lights that "
                 "can reach it) or power (every light by its power alone)")
      ->capture_default_str();
  app.add_flag("--guiding", o.render.guiding,
               "Path guiding: learn where light comes from at each scene state (a training pass) "
               "and sample directions from it too");
  app.add_option("--guide-training-spp", o.render.guide_training_spp,
                 "--guiding: training paths per pixel at each scene state")
      ->capture_default_str();
  app.add_option("--max-depth", o.render.max_depth, "Maximum number of bounces (0 = emitters only)")
      ->capture_default_str();
  app.add_option("--tile", o.render.tile_size, "Tile size n (tiles are n x n pixels)")
      ->capture_default_str();
  o.load.environment = kAutoEnvironment;
  app.add_option("--env", o.load.environment,
                 "Environment light: auto (the built-in studio when the scene has no light), "
                 "studio, sky (daylight "
                 "with a sun), none, or an equirectangular .hdr/.exr")
      ->capture_default_str();
  app.add_option("--sun-elevation", o.load.sky.sun_elevation_degrees,
                 "--env sky: sun above the horizon, degrees (0-90)")
      ->capture_default_str();
  app.add_option("--sun-azimuth", o.load.sky.sun_azimuth_degrees,
                 "--env sky: sun azimuth, degrees (0: behind the default camera, 90: toward +X)")
      ->capture_default_str();
  app.add_option("--turbidity", o.load.sky.turbidity, "--env sky: haze, 1.7 (clear) to 10 (murky)")
      ->capture_default_str();
  app.add_option("--env-intensity", o.load.environment_intensity, "Environment radiance multiplier")
      ->capture_default_str();
  app.add_option("--env-rotation", o.load.environment_rotation_degrees,
                 "Environment rotation about +Y, degrees")
      ->capture_default_str();
  app.add_option("--camera", o.load.camera,
                 "Look through this camera: its index in `hipr info`'s list, or its node's or glTF "
                 "camera's name (default: the first)");
  app.add_option("--variant", o.load.variant,
                 "Show this KHR_materials_variants variant: its name or its index in `hipr info`'s "
                 "list (default: the file's default materials)");
  app.add_option("--preset", o.preset, "HiPR weights preset: default, lookdev, glass, mirror");
  app.add_option("--w-lobe", o.w_lobe, "HiPR lobe weights: diffuse,glossy,specular,transmission")
      ->delimiter(',')
      ->expected(4);
  app.add_option("--w-path", o.w_path, "HiPR path weights: direct,indirect,caustic")
      ->delimiter(',')
      ->expected(3);
  app.add_option("--w-occlusion", o.render.hipr.w_occlusion, "HiPR occlusion priority")
      ->capture_default_str();
  app.add_option("--eps", o.render.hipr.depth_epsilon, "HiPR relative depth tolerance")
      ->capture_default_str();
  app.add_flag("--uber-kernel", o.uber_kernel,
               "Compile every kernel feature (BSDF lobes, textures, light kinds, cutout...) "
               "instead of only those "
               "the scene uses");
  app.add_flag("--trace-background-tiles", o.trace_background_tiles,
               "Trace the camera rays of tiles that can only see background too (for comparison)");
  app.add_option("--light-groups", o.light_groups,
                 "Light groups kept apart so that light edits are relit at once (0-8, 24 bytes per "
                 "pixel each; "
                 "default 8, render 0)");
  app.add_flag("--validate", o.validate,
               "Enable Vulkan validation layers; any validation error fails the run");
  app.add_option("--device", o.device, "Use the Vulkan device whose name contains this text");
  app.add_option(
         "--traversal", o.traversal,
         "How rays are traced: auto (ray queries where the device has them), ray-query or software "
         "(hipr's own BVH; default from HIPR_TRAVERSAL)")
      ->check(CLI::IsMember({"auto", "ray-query", "software"}));
  app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors and warnings");
}

void validate_common_options(CommonOptions& o) {
  o.render.specialize_kernel = !o.uber_kernel;
  o.render.skip_background_tiles = !o.trace_background_tiles;
  const auto require = [](bool ok, const std::string& message) {
    if (!ok) throw InputError(message);
  };
  require(o.render.width >= 1 && o.render.width <= 16384, "--width must be between 1 and 16384");
  require(o.render.height >= 1 && o.render.height <= 16384, "--height must be between 1 and 16384");
  require(o.spp >= 1 && o.spp <= (1u << 24), "--spp must be between 1 and 16777216");
  const std::optional<Sampler> sampler = parse_sampler(o.sampler);
  require(sampler.has_value(), "--sampler must be sobol or random, not '" + o.sampler + "'");
  o.render.sampler = *sampler;
  const std::optional<LightSelection> selection = parse_light_selection(o.light_selection);
  require(selection.has_value(),
          "--light-selection must be tree or power, not '" + o.light_selection + "'");
  o.render.light_selection = *selection;
  require(o.render.guide_training_spp >= 1 && o.render.guide_training_spp <= 1024,
          "--guide-training-spp must be between 1 and 1024");
  require(o.render.max_depth <= 1024, "--max-depth must be at most 1024");
  require(o.render.tile_size >= 1 && o.render.tile_size <= 256, "--tile must be between 1 and 256");
  require(std::isfinite(o.load.environment_intensity) && o.load.environment_intensity >= 0.0f,
          "--env-intensity must be a finite non-negative number");
  require(std::isfinite(o.load.environment_rotation_degrees), "--env-rotation must be finite");
  validate_sky(o.load.sky);
  require(o.light_groups >= -1 && o.light_groups <= int(abi::kMaxLightGroups),
          "--light-groups must be between 0 and 8");
  if (o.light_groups >= 0) o.render.light_groups = uint32_t(o.light_groups);
  HiprParameters& h = o.render.hipr;
  require(std::isfinite(h.w_occlusion) && h.w_occlusion >= 0.0f,
          "--w-occlusion must be finite and non-negative");
  require(std::isfinite(h.depth_epsilon) && h.depth_epsilon > 0.0f && h.depth_epsilon < 1.0f,
          "--eps must be between 0 and 1 (relative depth)");
  apply_hipr_preset(o.preset, h);
  if (!o.w_lobe.empty()) set_hipr_weights(o.w_lobe, h.w_lobe, "--w-lobe");
  if (!o.w_path.empty()) set_hipr_weights(o.w_path, h.w_path, "--w-path");
}

void validate_sky(const SkyParameters& sky) {
  if (!(sky.sun_elevation_degrees >= 0.0f && sky.sun_elevation_degrees <= 90.0f))
    throw InputError("--sun-elevation must be between 0 and 90 degrees");
  if (!std::isfinite(sky.sun_azimuth_degrees)) throw InputError("--sun-azimuth must be finite");
  if (!(sky.turbidity >= kMinTurbidity && sky.turbidity <= kMaxTurbidity))
    throw InputError("--turbidity must be between 1.7 and 10");
}

vk::ContextOptions context_options(const CommonOptions& o) {
  vk::ContextOptions ctx;
  const char* env = std::getenv("HIPR_VALIDATION");
  ctx.validation = o.validate || (env && std::string(env) == "1");
  ctx.preferred_device = o.device;
  if (o.traversal == "ray-query") ctx.traversal = vk::Traversal::RayQuery;
  if (o.traversal == "software") ctx.traversal = vk::Traversal::Software;
  return ctx;
}

void check_validation(const vk::Context& ctx) {
  if (ctx.validation_errors() > 0)
    throw InternalError("Vulkan validation reported " + std::to_string(ctx.validation_errors()) +
                        " error(s)");
}

}  // namespace hipr::app
