#pragma once
// Options shared by every subcommand (the CLI contract in DESIGN.md) and their validation.
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
  uint32_t spp = 64;
  SceneLoadOptions load;
  bool validate = false;
  bool quiet = false;
  std::string device;
};

// Adds --width --height --spp --seed --max-depth --tile --env --env-intensity --env-rotation
// --validate --device --quiet.
void add_common_options(CLI::App& app, CommonOptions& options);

// Checks ranges CLI11 cannot express; throws InputError.
void validate_common_options(const CommonOptions& options);

vk::ContextOptions context_options(const CommonOptions& options);

// Throws InternalError when the validation layer reported errors (tests rely on it).
void check_validation(const vk::Context& ctx);

}  // namespace hipr::app
