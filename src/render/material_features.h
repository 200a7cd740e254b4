#pragma once
// Which optional parts of the OpenPBR BSDF a scene's materials use, as the kernel's compile-time
// HIPR_FEATURE_* defines (shaders/common/features.glsl): the kernel is specialized per scene and
// leaves out what no material needs.
#include <cstdint>
#include <string>
#include <vector>

#include "hipr/scene.h"
#include "vk/shader_compiler.h"

namespace hipr {

struct MaterialFeature {
  uint32_t bit;
  const char* define;  // HIPR_FEATURE_...
  const char* name;    // as `hipr info` prints it
  bool (*used_by)(const abi::MaterialBlock&);
};

// Every feature, in the order of features.glsl.
const std::vector<MaterialFeature>& material_feature_table();

// All feature bits: the uber kernel.
uint32_t all_material_features();

// Bits of the features that any material a primitive uses needs.
uint32_t material_features(const Scene& scene);

// HIPR_FEATURE_* = 0/1 for each feature.
vk::ShaderDefines material_feature_defines(uint32_t features);

// Names of the features in `features` (or, with `present` false, of those not in it).
std::vector<std::string> material_feature_names(uint32_t features, bool present = true);

}  // namespace hipr
