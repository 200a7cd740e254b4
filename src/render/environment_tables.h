#pragma once
#include <vector>

#include "hipr/scene.h"

namespace hipr {

// The environment buffer layout the kernels expect (see shaders/common/scene_bindings.glsl):
// RGB texels, the marginal CDF over rows (height + 1), then a conditional CDF per row
// (width + 1 each). Texel weights are luminance x sin(theta), so sampling follows what the
// sphere actually receives; an all-black map falls back to uniform weights.
std::vector<float> build_environment_buffer(const Environment& env);

}  // namespace hipr
