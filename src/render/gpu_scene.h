#pragma once
// The scene as the kernels see it: shared vertex/index buffers, one BLAS per mesh, a TLAS of
// instances, material/texture/light tables and the environment. Built once per scene.
#include <vector>

#include "hipr/scene.h"
#include "render/light_tables.h"
#include "vk/acceleration.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace hipr {

struct GpuSceneInfo {
  size_t instance_count = 0;
  size_t triangle_count = 0;  // over all instances
  size_t light_count = 0;
  double emissive_triangles = 0;
  float scene_radius = 1.0f;
};

class GpuScene {
 public:
  GpuScene(const vk::Context& ctx, const Scene& scene);

  const GpuSceneInfo& info() const { return m_info; }
  const LightTables& light_tables() const { return m_lights; }
  VkAccelerationStructureKHR tlas() const { return m_tlas.handle(); }

  vk::Buffer positions, normals, tangents, uvs, indices;
  vk::Buffer geometries, materials, textures, texels;
  vk::Buffer lights, light_cdf, environment;

 private:
  GpuSceneInfo m_info;
  LightTables m_lights;
  std::vector<vk::AccelerationStructure> m_blas;  // one per mesh (empty meshes: none)
  vk::AccelerationStructure m_tlas;
};

}  // namespace hipr
