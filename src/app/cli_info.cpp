// `hipr info SCENE`: what the scene contains and which renderer features it uses.
#include <algorithm>
#include <cstdio>
#include <set>

#include "app/cli_common.h"
#include "app/commands.h"
#include "core/error.h"
#include "core/log.h"
#include "image/builtin_environments.h"
#include "render/background_tiles.h"
#include "render/kernel_features.h"
#include "render/light_groups.h"
#include "scene/default_camera.h"

namespace hipr::app {
namespace {

struct InfoOptions {
  std::filesystem::path scene;
  SceneLoadOptions load;
  RenderSettings render;  // image and tile size: which tiles see only background
};

std::string joined(const std::vector<std::string>& items, const char* none) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text.empty() ? none : text;
}

const char* light_type_name(LightType type) {
  switch (type) {
    case LightType::Point:
      return "point";
    case LightType::Spot:
      return "spot";
    case LightType::Directional:
      return "directional";
  }
  return "?";
}

int run_info(const InfoOptions& o) {
  validate_sky(o.load.sky);
  const Scene scene = load_scene(o.scene, o.load);
  const std::vector<Instance> instances = scene.instances();

  size_t unique_triangles = 0, scene_triangles = 0, emissive_triangles = 0;
  for (const Mesh& mesh : scene.meshes)
    for (const MeshPrimitive& p : mesh.primitives) unique_triangles += p.indices.size() / 3;
  std::set<uint32_t> used_materials;
  for (const Instance& instance : instances) {
    if (!instance.visible) continue;
    for (const MeshPrimitive& p : scene.meshes[instance.mesh].primitives) {
      scene_triangles += p.indices.size() / 3;
      used_materials.insert(p.material);
      const MaterialParameters& m = scene.materials[p.material].params;
      if (material_emits(m)) emissive_triangles += p.indices.size() / 3;
    }
  }
  const size_t punctual = scene.light_nodes().size();

  std::printf("scene      %s\n", o.scene.string().c_str());
  std::printf("hash       %s\n", scene.content_hash.c_str());
  std::printf("nodes      %zu (%zu mesh instances)\n", scene.nodes.size(), instances.size());
  std::printf("meshes     %zu\n", scene.meshes.size());
  std::printf("triangles  %zu in the scene, %zu unique\n", scene_triangles, unique_triangles);
  std::printf("materials  %zu (%zu used)\n", scene.materials.size() - 1, used_materials.size());
  for (uint32_t index : used_materials) {
    const Material& m = scene.materials[index];
    std::printf("  %-24s base_color %.3g %.3g %.3g  metalness %.3g  roughness %.3g%s%s\n",
                m.name.c_str(), m.params.base_color.x, m.params.base_color.y, m.params.base_color.z,
                m.params.base_metalness, m.params.specular_roughness,
                material_emits(m.params) ? "  emissive" : "",
                (m.params.flags & kMaterialDoubleSided) ? "  double-sided" : "");
  }
  std::printf("textures   %zu (on %zu images)\n", scene.textures.size(), scene.images.size());
  std::printf("lights     %zu punctual, %zu emissive triangles\n", punctual, emissive_triangles);
  std::printf("env        %s\n", environment_description(scene).c_str());
  for (uint32_t n : scene.light_nodes()) {
    const PunctualLight& l = scene.lights[size_t(scene.nodes[n].light)];
    std::printf("  %-24s %s, intensity %g\n", scene.nodes[n].name.c_str(), light_type_name(l.type),
                l.intensity);
  }
  // Emitters whose light edits the hipr policy relights at once (render/light_groups.h).
  const LightGroups groups = assign_light_groups(scene, RenderSettings{}.light_groups);
  std::printf(
      "groups     %s%s\n", joined(groups.names, "none").c_str(),
      groups.pooled.empty() ? "" : ("; pooled, not relit: " + joined(groups.pooled, "")).c_str());
  // Every camera the scene defines, as --camera counts them; the one the image uses marked.
  const int camera = scene.camera_node();
  const std::vector<uint32_t> cameras = scene.camera_nodes();
  if (cameras.empty()) std::printf("camera     none (a default camera frames the scene)\n");
  for (size_t i = 0; i < cameras.size(); ++i) {
    const Camera& c = scene.cameras[size_t(scene.nodes[cameras[i]].camera)];
    std::string lens = "pinhole";
    if (c.aperture_radius > 0.0f)
      lens = "lens radius " + std::to_string(c.aperture_radius) + ", focus " +
             std::to_string(c.focus_distance);
    std::printf("%s %zu %s: yfov %.1f deg, %s%s\n", i == 0 ? "cameras   " : "          ", i,
                camera_label(scene, cameras[i]).c_str(), double(glm::degrees(c.yfov)), lens.c_str(),
                int(cameras[i]) == camera ? " (used)" : "");
  }
  for (size_t v = 0; v < scene.material_variants.size(); ++v)
    std::printf("%s %zu '%s'%s\n", v == 0 ? "variants  " : "          ", v,
                scene.material_variants[v].c_str(),
                int(v) == scene.active_variant ? " (shown)" : "");
  // Each extension the file uses, and whether hipr reads it (README, "glTF extensions").
  std::string extensions;
  const std::vector<std::string>& supported = supported_gltf_extensions();
  for (const std::string& e : scene.extensions_used) {
    const bool read = std::find(supported.begin(), supported.end(), e) != supported.end();
    extensions += (extensions.empty() ? "" : ", ") + e + (read ? " (used)" : " (ignored)");
  }
  std::printf("extensions %s\n", extensions.empty() ? "none" : extensions.c_str());

  // The kernel is compiled with the features the scene needs and nothing else (kernel_features.h).
  const uint32_t features = kernel_features(scene);
  std::vector<std::string> lobes = {"diffuse"}, others, skipped;
  for (const KernelFeature& f : kernel_feature_table())
    ((features & f.bit) ? (f.bsdf_lobe ? lobes : others) : skipped).emplace_back(f.name);
  std::printf("bsdf       %s\n", joined(lobes, "").c_str());
  std::printf("kernel     %s\n", joined(others, "no other feature").c_str());
  std::printf("skipped    %s\n", joined(skipped, "nothing").c_str());

  // Rays nobody needs (trace_tiles.comp).
  const auto has = [&](const char* define) { return (features & kernel_feature_bit(define)) != 0; };
  std::vector<std::string> rays;
  if (!has("HIPR_FEATURE_EMISSION") && !has("HIPR_FEATURE_PUNCTUAL_LIGHTS") &&
      !has("HIPR_FEATURE_ENVIRONMENT"))
    rays.emplace_back("all of them (nothing emits, no light to sample: the image is black)");
  else if (!has("HIPR_FEATURE_EMISSION") && !has("HIPR_FEATURE_ENVIRONMENT"))
    rays.emplace_back("segments to the last vertex (nothing emits there)");
  const RenderSettings& r = o.render;
  const std::vector<uint32_t> background =
      BackgroundTiles(scene).mask(scene, r.width, r.height, r.tile_size);
  const size_t empty = size_t(std::count(background.begin(), background.end(), 1u));
  if (empty > 0)
    rays.push_back("camera rays of " + std::to_string(empty) + " of " +
                   std::to_string(background.size()) + " tiles (background only at " +
                   std::to_string(r.width) + "x" + std::to_string(r.height) + ", tile " +
                   std::to_string(r.tile_size) + ")");
  std::printf("rays       %s\n",
              rays.empty() ? "every ray is needed" : ("skipped: " + joined(rays, "")).c_str());
  return kExitOk;
}

}  // namespace

Command add_info_command(CLI::App& app) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* cmd =
      app.add_subcommand("info", "Print what a scene contains and what the renderer will use");
  cmd->add_option("scene", options->scene, "Scene file (.gltf or .glb)")->required();
  options->load.environment = kAutoEnvironment;
  cmd->add_option("--env", options->load.environment,
                  "Environment light: auto (the built-in studio when the scene has no light), "
                  "studio, sky (daylight "
                  "with a sun), none, or an equirectangular .hdr/.exr")
      ->capture_default_str();
  cmd->add_option("--sun-elevation", options->load.sky.sun_elevation_degrees,
                  "--env sky: sun elevation, degrees");
  cmd->add_option("--sun-azimuth", options->load.sky.sun_azimuth_degrees,
                  "--env sky: sun azimuth, degrees");
  cmd->add_option("--turbidity", options->load.sky.turbidity, "--env sky: haze, 1.7 to 10");
  cmd->add_option("--camera", options->load.camera,
                  "Look through this camera: its index in the list below, or its node's or "
                  "glTF camera's name (default: the first)");
  cmd->add_option("--variant", options->load.variant,
                  "Show this material variant: its name or its index in the list below");
  cmd->add_option("--width", options->render.width, "Image width in pixels (for background tiles)")
      ->capture_default_str()
      ->check(CLI::Range(1u, 16384u));
  cmd->add_option("--height", options->render.height,
                  "Image height in pixels (for background tiles)")
      ->capture_default_str()
      ->check(CLI::Range(1u, 16384u));
  cmd->add_option("--tile", options->render.tile_size, "Tile size n (for background tiles)")
      ->capture_default_str()
      ->check(CLI::Range(1u, 256u));
  return {cmd, [options] { return run_info(*options); }};
}

}  // namespace hipr::app
