#pragma once
// HiPR's discovery parameters (the paper's w_lobe, w_path, occlusion priority and epsilon) and
// their presets (docs/method.md#the-method).
#include <string>
#include <vector>

namespace hipr {

// Defaults follow the paper's order: specular and direct ahead of diffuse, indirect and caustic
// trailing.
struct HiprParameters {
  float w_lobe[4] = {0.2f, 0.25f, 0.4f, 0.15f};  // diffuse, glossy, specular, transmission
  float w_path[3] = {0.6f, 0.25f, 0.15f};        // direct, indirect, caustic
  float w_occlusion = 0.5f;
  float depth_epsilon = 0.01f;  // relative to the G-buffer depth
};

// default, lookdev, glass, mirror.
const std::vector<std::string>& hipr_preset_names();
// Sets w_lobe and w_path to a preset's ("" is the default); InputError for an unknown name.
void apply_hipr_preset(const std::string& name, HiprParameters& parameters);
// Copies `values` into `out` scaled to sum 1 (the weights are a distribution); InputError,
// naming `what`, for a negative or non-finite weight or weights that are all zero.
void set_hipr_weights(const std::vector<float>& values, float* out, const std::string& what);

}  // namespace hipr
