#include "render/material_probe.h"

#include "core/error.h"
#include "shaders/shared/bindings/probe.h"

namespace hipr {

MaterialProbe::MaterialProbe(const vk::Context& ctx, const Scene& scene)
    : m_ctx(ctx),
      m_scene(ctx, scene),
      m_output(ctx, sizeof(abi::MaterialInputsProbe), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      m_probe(ctx, "material_probe.comp", {}, {{abi::kProbeOutput, &m_output}},
              sizeof(abi::ProbePush), &m_scene.descriptor_set()) {}

abi::MaterialInputsProbe MaterialProbe::at(uint32_t record, uint32_t primitive,
                                           glm::vec2 barycentrics) const {
  if (record >= m_scene.record_count()) throw InternalError("probe of a missing geometry record");
  const abi::ProbePush push{record, primitive, barycentrics};
  m_ctx.submit_and_wait([&](VkCommandBuffer cmd) { m_probe.dispatch(cmd, &push, 1); });
  return m_output.download_all<abi::MaterialInputsProbe>()[0];
}

}  // namespace hipr
