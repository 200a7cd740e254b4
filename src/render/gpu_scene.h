#pragma once
// The scene as the kernels see it: shared vertex/index buffers, one BLAS per mesh, a TLAS of
// instances, material/texture/light tables and the environment. Geometry is uploaded once;
// edits update only what they touch (materials, instances + lights, or lights alone).
#include <vector>

#include "hipr/scene.h"
#include "render/light_tables.h"
#include "vk/acceleration.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace hipr {

struct GpuSceneInfo {
  size_t instance_count = 0;
  size_t triangle_count = 0;  // over all visible instances
  size_t light_count = 0;
  size_t cutout_geometries = 0;  // BLAS geometries without VK_GEOMETRY_OPAQUE_BIT_KHR (alpha-tested)
  float scene_radius = 1.0f;
};

class GpuScene {
 public:
  GpuScene(const vk::Context& ctx, const Scene& scene);

  // Re-uploads the material blocks (same count: edits change parameters, not the table). An
  // edit that makes a material need the alpha test, or no longer need it, rebuilds the BLAS of
  // the meshes using it and the TLAS.
  void update_materials(const Scene& scene);
  // Rebuilds the TLAS (transforms, visibility) and the light tables that depend on them.
  void update_instances(const Scene& scene);
  // Rebuilds the light tables alone (punctual lights, emission strengths).
  void update_lights(const Scene& scene);

  const GpuSceneInfo& info() const { return m_info; }
  const LightTables& light_tables() const { return m_lights; }
  VkAccelerationStructureKHR tlas() const { return m_tlas.handle(); }
  // Instance index of each GeometryRecord (records are grouped per instance).
  const std::vector<uint32_t>& record_instance() const { return m_record_instance; }
  uint32_t record_count() const { return uint32_t(m_records.size()); }

  vk::Buffer positions, normals, tangents, uvs, indices;
  vk::Buffer geometries, materials, textures, texels;
  vk::Buffer lights, light_cdf, environment;

 private:
  struct PrimitiveRange {
    uint32_t first_index;
    uint32_t vertex_offset;
    uint32_t triangle_count;
    uint32_t vertex_count;
  };
  void upload_geometry(const Scene& scene);
  void upload_textures(const Scene& scene);
  // (Re)builds the BLAS of every mesh whose per-primitive opacity flags differ from the built
  // ones; returns whether any was rebuilt.
  bool build_blases(const Scene& scene);

  const vk::Context& m_ctx;
  GpuSceneInfo m_info;
  LightTables m_lights;
  std::vector<std::vector<PrimitiveRange>> m_ranges;  // per mesh, per primitive
  std::vector<vk::AccelerationStructure> m_blas;      // one per mesh (empty meshes: none)
  std::vector<bool> m_has_blas;
  std::vector<std::vector<bool>> m_blas_opaque;       // per mesh, per primitive, as built
  std::vector<abi::GeometryRecord> m_records;
  std::vector<uint32_t> m_record_base;      // per instance
  std::vector<uint32_t> m_record_instance;  // per record
  vk::AccelerationStructure m_tlas;
};

}  // namespace hipr
