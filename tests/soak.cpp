// The edit soak (tools/soak.sh): N random edits of every op on a scene, one scheduling step each
// (edits in a row, as a viewer's drags make them), then converged: the displayed image must be
// the full-frame render of the final scene bit for bit, and the process's memory must stay flat.
// On lavapipe device memory is host memory, so the resident set size counts both.
// usage: hipr_soak [EDITS] [SEED]   (prints one JSON object; exit 1 when the image differs)
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/log.h"
#include "core/memory_usage.h"
#include "hipr/edit_pipeline.h"
#include "hipr/edits.h"
#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "hipr/scheduler.h"
#include "vk/context.h"

namespace {

using namespace hipr;

// A hostile edit: huge, tiny and degenerate transforms, a lamp or emitter squashed to no area,
// values beyond the scene limits, NaN. Those beyond the limits must be refused (the scene as it
// was); the others are scenes the renderer must draw without a NaN.
Edit hostile_edit(std::mt19937& rng) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const auto scaled = [](glm::vec3 s) { return glm::scale(glm::mat4(1.0f), s); };
  switch (rng() % 10) {
    case 0:
      return TransformEdit{"sphere", std::nullopt, scaled(glm::vec3(3e38f))};
    case 1:
      return TransformEdit{"tall_block", std::nullopt, scaled(glm::vec3(1e-30f))};
    case 2:
      return TransformEdit{"tall_block", std::nullopt, scaled(glm::vec3(1.0f, 0.0f, 1.0f))};
    case 3:
      return TransformEdit{"sphere", glm::vec3(3e38f, 0.0f, 0.0f), std::nullopt};
    case 4:
      return TransformEdit{"lamp", glm::vec3(0.0f, nan, 0.0f), std::nullopt};
    case 5:
      return DeformEdit{"light", scaled(glm::vec3(0.0f, 1.0f, 1.0f)), nullptr};
    case 6:
      return LightEdit{"lamp", 1e30f, std::nullopt, std::nullopt};
    case 7:
      return MaterialEdit{"light", {{"emission_luminance", {3e38f}}}};
    case 8:
      return MaterialEdit{"white", {{"base_color", {nan, 0.5f, 0.5f}}}};
    default:
      return CameraEdit{std::nullopt, glm::mat4(0.0f)};
  }
}

// One edit of a random op with random values in range (names of the shipped cornell_sphere;
// the geometry ops duplicate a node as "copy" or delete the copy, and deform the sphere), or
// one time in twenty a hostile one.
Edit random_edit(std::mt19937& rng, const Scene& scene) {
  if (rng() % 20 == 0) return hostile_edit(rng);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const auto pick = [&](std::initializer_list<const char*> names) {
    return std::string(names.begin()[rng() % names.size()]);
  };
  const glm::vec3 step = (glm::vec3(u(rng), u(rng), u(rng)) - 0.5f) * 0.02f;
  switch (rng() % 11) {
    case 0:
      return TransformEdit{pick({"sphere", "tall_block", "light", "lamp"}), step, std::nullopt};
    case 1:
      return MaterialEdit{pick({"white", "red", "green"}),
                          {{"base_color", {u(rng), u(rng), u(rng)}}}};
    case 2:
      return MaterialEdit{pick({"white", "red", "green"}), {{"specular_roughness", {u(rng)}}}};
    case 3:
      return LightEdit{"lamp", 0.05f + u(rng),
                       glm::vec3(0.2f + u(rng), 0.2f + u(rng), 0.2f + u(rng)), std::nullopt};
    case 4:
      return MaterialEdit{"light", {{"emission_luminance", {1.0f + 30.0f * u(rng)}}}};
    case 5:
      return VisibilityEdit{pick({"sphere", "tall_block", "light"}), u(rng) < 0.7f};
    case 6:
      return CameraEdit{step * 0.5f, std::nullopt};
    case 7:
      return EnvironmentEdit{.intensity = 0.01f * u(rng), .rotation = 6.0f * u(rng)};
    case 9: {
      bool has_copy = false;
      const std::vector<bool> in_scene = scene.reachable_nodes();
      for (size_t n = 0; n < scene.nodes.size(); ++n)
        has_copy = has_copy || (in_scene[n] && scene.nodes[n].name == "copy");
      if (has_copy) return DeleteEdit{"copy"};
      return DuplicateEdit{pick({"sphere", "tall_block", "lamp"}), "copy", step * 10.0f};
    }
    case 10: {
      const float scale = 1.0f + 0.1f * (u(rng) - 0.5f);
      return DeformEdit{"sphere", glm::scale(glm::mat4(1.0f), glm::vec3(scale, 1.0f / scale, 1.0f)),
                        nullptr};
    }
    default:
      return EnvironmentEdit{.source = std::filesystem::path(pick({"studio", "sky", "studio"})),
                             .intensity = 0.001f + 0.01f * u(rng)};
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int edits = argc > 1 ? std::stoi(argv[1]) : 10000;
  const unsigned seed = argc > 2 ? unsigned(std::stoul(argv[2])) : 1u;
  log::set_quiet(true);
  const vk::Context ctx(vk::ContextOptions{});
  Scene scene =
      load_scene(std::string(HIPR_ASSETS_DIR) + "/cornell_sphere.glb", {.environment = "studio"});
  RenderSettings settings;
  settings.width = settings.height = 32;
  settings.tile_size = 8;
  settings.max_depth = 4;
  const uint32_t spp = 4;
  Renderer renderer(ctx, scene, settings);
  renderer.add_samples_full_frame(spp);
  Scheduler scheduler(renderer, Policy::Hipr, 4);
  EditPipeline pipeline(scene, scheduler);
  std::mt19937 rng(seed);
  std::string samples;  // resident KiB every tenth of the run
  long first = 0, last = 0;
  int refused = 0;
  for (int e = 1; e <= edits; ++e) {
    try {
      pipeline.apply(random_edit(rng, scene));
    } catch (const InputError&) {
      ++refused;  // a hostile value: the scene stays as it was
    }
    scheduler.step();
    if (e % std::max(edits / 10, 1) == 0) {
      last = long(resident_bytes() / 1024);
      if (!first) first = last;
      samples += (samples.empty() ? "" : ", ") + std::to_string(last);
    }
  }
  while (scheduler.work_since_edit() < double(spp)) scheduler.step();
  Renderer fresh(ctx, scene, settings);
  fresh.add_samples_full_frame(spp);
  const bool same = scheduler.displayed_image().rgb == fresh.image().rgb;
  const bool finite = renderer.counters().non_finite_samples == 0;
  std::printf(
      "{\"edits\": %d, \"seed\": %u, \"traversal\": \"%s\", \"refused\": %d, \"bit_identical\": "
      "%s, "
      "\"nonfinite_samples\": %llu, \"resident_kib\": [%s], \"growth_kib_after_first_tenth\": "
      "%ld}\n",
      edits, seed, ctx.traversal_name(), refused, same ? "true" : "false",
      (unsigned long long)renderer.counters().non_finite_samples, samples.c_str(), last - first);
  return same && finite ? 0 : 1;
}
