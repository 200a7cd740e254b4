#pragma once
// "Skip what a scene doesn't need": the optional parts of the path-tracing kernel, as its
// compile-time HIPR_FEATURE_* defines (shaders/common/features.glsl, same names, same order).
// Material features (BSDF lobes, textures, emission, cutout, volumes) are needed when a
// material some primitive uses needs them; scene features (environment, punctual lights) when
// the scene has them. The renderer compiles the kernel with only what the scene needs, and an
// edit that brings in a feature recompiles it (features only grow).
#include <cstdint>
#include <string>
#include <vector>

#include "hipr/scene.h"
#include "vk/shader_compiler.h"

namespace hipr {

struct KernelFeature {
  uint32_t bit;
  const char* define;  // HIPR_FEATURE_...
  const char* name;    // as `hipr info` prints it
  // Exactly one of these decides whether a scene needs the feature.
  bool (*material_needs)(const MaterialParameters&);  // any material a primitive uses
  bool (*scene_needs)(const Scene&);                  // the scene as a whole
  bool bsdf_lobe;  // a part of the BSDF (`hipr info` lists these apart)
};

// Every feature, in the order of features.glsl.
const std::vector<KernelFeature>& kernel_feature_table();

// All feature bits: the uber kernel.
uint32_t all_kernel_features();

// Bits of the features the scene needs.
uint32_t kernel_features(const Scene& scene);

// The bit of the feature with this define (HIPR_FEATURE_...); throws InternalError if none.
uint32_t kernel_feature_bit(const std::string& define);

// HIPR_FEATURE_* = 0/1 for each feature.
vk::ShaderDefines kernel_feature_defines(uint32_t features);

}  // namespace hipr
