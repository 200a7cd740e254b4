#pragma once
// Options shared by every subcommand and their validation (the CLI contract:
// docs/method.md#command-line-and-edit-scripts).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>

#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "vk/context.h"

namespace hipr::app {

struct CommonOptions {
  std::filesystem::path scene;
  RenderSettings render;
  // HiPR weights as given on the command line (normalized to sum 1 when applied).
  std::vector<float> w_lobe, w_path;
  std::string preset;
  std::string sampler = "sobol";
  std::string light_selection = "tree";
  uint32_t spp = 64;
  SceneLoadOptions load;
  bool validate = false;
  bool uber_kernel =
      false;  // every kernel feature compiled in (RenderSettings::specialize_kernel off)
  bool trace_background_tiles = false;  // RenderSettings::skip_background_tiles off
  bool quiet = false;
  std::string device;
  std::string traversal = "auto";  // --traversal: auto, ray-query or software (vk::Traversal)
  int light_groups =
      -1;  // --light-groups; -1: the command's default (RenderSettings' 8; render: 0)
};

// Adds --width --height --spp --seed --sampler --light-selection --guiding --guide-training-spp
// --max-depth --tile --env
// --env-intensity
// --env-rotation
// --uber-kernel --trace-background-tiles --validate --device --traversal --quiet.
void add_common_options(CLI::App& app, CommonOptions& options);

// Checks ranges CLI11 cannot express and applies the HiPR preset/weights; throws InputError.
void validate_common_options(CommonOptions& options);
// --sun-elevation, --sun-azimuth, --turbidity in range (InputError otherwise).
void validate_sky(const SkyParameters& sky);

// The HiPR weight presets (--preset): names, and setting w_lobe / w_path from one (throws
// InputError for an unknown name). The viewer offers the same presets.

vk::ContextOptions context_options(const CommonOptions& options);

// Throws InternalError when the validation layer reported errors (tests rely on it).
void check_validation(const vk::Context& ctx);

}  // namespace hipr::app
