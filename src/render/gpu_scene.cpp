#include "render/gpu_scene.h"

#include <cstring>

#include "core/error.h"
#include "render/environment_tables.h"

namespace hipr {
namespace {

constexpr VkBufferUsageFlags kBuildInput = VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;

struct PrimitiveRange {
  uint32_t first_index;
  uint32_t vertex_offset;
  uint32_t triangle_count;
  uint32_t vertex_count;
};

std::array<float, 12> row_major_3x4(const glm::mat4& m) {
  return {m[0][0], m[1][0], m[2][0], m[3][0], m[0][1], m[1][1], m[2][1], m[3][1], m[0][2], m[1][2], m[2][2], m[3][2]};
}

}  // namespace

GpuScene::GpuScene(const vk::Context& ctx, const Scene& scene) {
  // Shared vertex data: each mesh primitive once, however many instances use it.
  std::vector<glm::vec3> all_positions, all_normals;
  std::vector<glm::vec4> all_tangents;
  std::vector<glm::vec2> all_uvs;
  std::vector<uint32_t> all_indices;
  std::vector<std::vector<PrimitiveRange>> ranges(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    for (const MeshPrimitive& p : scene.meshes[m].primitives) {
      if (all_positions.size() + p.positions.size() > UINT32_MAX || all_indices.size() + p.indices.size() > UINT32_MAX)
        throw InputError("scene is too large (more than 4G vertices or indices)");
      ranges[m].push_back({uint32_t(all_indices.size()), uint32_t(all_positions.size()),
                           uint32_t(p.indices.size() / 3), uint32_t(p.positions.size())});
      all_positions.insert(all_positions.end(), p.positions.begin(), p.positions.end());
      all_normals.insert(all_normals.end(), p.normals.begin(), p.normals.end());
      all_tangents.insert(all_tangents.end(), p.tangents.begin(), p.tangents.end());
      all_uvs.insert(all_uvs.end(), p.uvs.begin(), p.uvs.end());
      all_indices.insert(all_indices.end(), p.indices.begin(), p.indices.end());
    }
  }
  positions = vk::make_storage_buffer(ctx, all_positions, kBuildInput);
  normals = vk::make_storage_buffer(ctx, all_normals);
  tangents = vk::make_storage_buffer(ctx, all_tangents);
  uvs = vk::make_storage_buffer(ctx, all_uvs);
  indices = vk::make_storage_buffer(ctx, all_indices, kBuildInput);

  // One BLAS per mesh, one geometry per non-empty primitive. Indices in the BLAS are relative
  // to the primitive's first vertex, which is why the vertex address carries the offset.
  m_blas.resize(scene.meshes.size());
  std::vector<bool> has_blas(scene.meshes.size(), false);
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    std::vector<vk::TriangleGeometry> geometry;
    for (const PrimitiveRange& r : ranges[m]) {
      geometry.push_back({positions.address() + VkDeviceAddress(r.vertex_offset) * sizeof(glm::vec3), r.vertex_count,
                          indices.address() + VkDeviceAddress(r.first_index) * sizeof(uint32_t), r.triangle_count});
    }
    if (geometry.empty()) continue;
    m_blas[m] = vk::build_blas(ctx, geometry);
    has_blas[m] = true;
  }

  const std::vector<Instance> instances = scene.instances();
  const auto [lo, hi] = scene.bounds();
  m_info.scene_radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);

  std::vector<abi::GeometryRecord> records;
  std::vector<uint32_t> record_base(instances.size());
  std::vector<vk::TlasInstance> tlas_instances;
  for (size_t i = 0; i < instances.size(); ++i) {
    const Instance& instance = instances[i];
    record_base[i] = uint32_t(records.size());
    const Mesh& mesh = scene.meshes[instance.mesh];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const PrimitiveRange& r = ranges[instance.mesh][p];
      records.push_back({mesh.primitives[p].material, r.first_index, r.vertex_offset, abi::kInvalidIndex});
      m_info.triangle_count += r.triangle_count;
    }
    if (!has_blas[instance.mesh]) continue;
    // Mirroring transforms flip the winding; we compute facing from object-space normals in
    // the shader, so the TLAS flag only keeps the hardware's notion consistent.
    const bool mirrored = glm::determinant(glm::mat3(instance.world)) < 0.0f;
    tlas_instances.push_back({row_major_3x4(instance.world), record_base[i], m_blas[instance.mesh].address(), !mirrored});
  }
  m_info.instance_count = tlas_instances.size();

  m_lights = build_light_tables(scene, instances, record_base, uint32_t(records.size()), m_info.scene_radius);
  for (size_t r = 0; r < records.size(); ++r) records[r].lightOffset = m_lights.record_light_offset[r];
  m_info.light_count = m_lights.lights.size();
  m_info.emissive_triangles = m_lights.emissive_triangle_count;

  geometries = vk::make_storage_buffer(ctx, records);
  std::vector<abi::MaterialBlock> blocks;
  for (const Material& m : scene.materials) blocks.push_back(m.params);
  materials = vk::make_storage_buffer(ctx, blocks);

  std::vector<abi::TextureInfo> infos;
  std::vector<uint32_t> packed;
  for (const Texture& t : scene.textures) {
    infos.push_back({uint32_t(packed.size()), t.width, t.height, t.flags});
    const size_t start = packed.size();
    packed.resize(start + t.rgba8.size() / 4);
    std::memcpy(packed.data() + start, t.rgba8.data(), t.rgba8.size() / 4 * 4);
  }
  textures = vk::make_storage_buffer(ctx, infos);
  texels = vk::make_storage_buffer(ctx, packed);
  lights = vk::make_storage_buffer(ctx, m_lights.lights);
  light_cdf = vk::make_storage_buffer(ctx, m_lights.cdf);
  environment = vk::make_storage_buffer(ctx, scene.environment ? build_environment_buffer(*scene.environment)
                                                               : std::vector<float>{});
  // An empty TLAS is valid and makes every ray miss.
  m_tlas = vk::build_tlas(ctx, tlas_instances);
}

}  // namespace hipr
