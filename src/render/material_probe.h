#pragma once
// An inspection pass (material_probe.comp): what shaders/common/material_inputs.glsl gives the
// BSDF at a point of a triangle (factor x texture channel, UV set, transform, frames), so tests
// check material inputs on the very code the kernels run. Not used when rendering.
#include <cstdint>

#include "hipr/scene.h"
#include "render/gpu_scene.h"
#include "shaders/shared/abi.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class MaterialProbe {
 public:
  MaterialProbe(const vk::Context& ctx, const Scene& scene);

  // At `barycentrics` of triangle `primitive` of GeometryRecord `record` (object space, seen
  // from its front).
  abi::MaterialInputsProbe at(uint32_t record, uint32_t primitive, glm::vec2 barycentrics) const;

 private:
  const vk::Context& m_ctx;
  GpuScene m_scene;
  vk::Buffer m_output;
  vk::ComputePipeline m_probe;
};

}  // namespace hipr
