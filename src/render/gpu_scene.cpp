#include "render/gpu_scene.h"

#include <algorithm>
#include <cstring>
#include <span>

#include "core/error.h"
#include "core/log.h"
#include "core/timer.h"
#include "render/bsdf_tables.h"
#include "render/environment_tables.h"
#include "render/material_packing.h"
#include "render/texture_fit.h"
#include "shaders/shared/bindings/scene.h"

namespace hipr {
namespace {

// Rounded up: a limit below 1 MiB (tests reach the limits with small scenes) is not "0 MiB".
std::string mib(uint64_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20); }

// A scene whose data one storage buffer of this device cannot address is bad input for this
// device (one line, exit 2), not a crash or a validation error: say what and by how much.

void check_fits(const vk::Context& ctx, uint64_t bytes, const char* what) {
  if (bytes <= ctx.max_storage_range()) return;
  throw InputError("the scene's " + std::string(what) + " take " + mib(bytes) +
                   " MiB, more than this device addresses in one buffer (" +
                   mib(ctx.max_storage_range()) + " MiB, maxStorageBufferRange): the scene does " +
                   "not fit " + ctx.device_name());
}

}  // namespace

GpuScene::GpuScene(const vk::Context& ctx, const Scene& scene, uint32_t light_group_budget)
    : m_ctx(ctx), m_groups(assign_light_groups(scene, light_group_budget)) {
  upload_material_groups(scene);
  upload_geometry(scene);
  upload_textures(scene);
  upload_materials(scene);
  build_blases(scene);
  upload_environment(scene);
  bsdf_tables = vk::make_storage_buffer(ctx, bsdf_table_data());
  // No guide until a GuidePass asks for one (reserve_guide): one slot each, never read.
  guide_counts = vk::make_storage_buffer(ctx, std::vector<uint64_t>(1));
  guide = vk::make_storage_buffer(ctx, std::vector<float>(1));
  frame_buffer =
      vk::make_storage_buffer(ctx, std::vector<abi::FrameParams>(1), 0, vk::MemoryUse::Shared);
  std::vector<vk::BindingSlot> slots;
  if (!ctx.software_traversal()) {
    slots.push_back({abi::kSceneTlas, vk::BindingKind::AccelerationStructure});
    slots.push_back({abi::kSceneTriangleOrder});
  }
  for (uint32_t b = abi::kScenePositions; b <= abi::kSceneFrame; ++b) slots.push_back({b});
  slots.push_back({abi::kSceneLightTree});
  slots.push_back({abi::kSceneGuideCounts});
  slots.push_back({abi::kSceneGuide});
  if (ctx.software_traversal())
    for (uint32_t b = abi::kSceneBlasNodes; b <= abi::kSceneTlasInstances; ++b)
      slots.push_back({b});
  m_set = std::make_unique<vk::DescriptorSet>(ctx, slots);
  update_instances(scene);  // gives the instances their records: in a fresh upload, in order
}

void GpuScene::upload_material_groups(const Scene& scene) {
  // Materials an edit brought in emit into no group (light_groups.h). Never empty: a buffer of
  // no bytes cannot be bound.
  std::vector<uint32_t> table(std::max<size_t>(scene.materials.size(), 1), kNoLightGroup);
  for (size_t m = 0; m < std::min(table.size(), m_groups.material.size()); ++m)
    table[m] = m_groups.material[m];
  if (vk::write_storage_buffer(m_ctx, material_groups, table)) ++m_layout_generation;
}

void GpuScene::update_geometry(const Scene& scene) {
  upload_geometry(scene);
  upload_textures(scene);  // the images an import brought, only
  upload_material_groups(scene);
  upload_materials(scene);
  build_blases(scene);
  update_instances(scene);
}

uint32_t GpuScene::allocate_records(uint32_t count) {
  for (auto it = m_free.begin(); it != m_free.end(); ++it) {
    if (it->second < count) continue;
    const uint32_t base = it->first;
    it->first += count;
    it->second -= count;
    if (it->second == 0) m_free.erase(it);
    return base;
  }
  const uint32_t base = uint32_t(m_records.size());
  m_records.resize(base + count, {0, 0, 0, abi::kInvalidIndex, abi::kInvalidIndex});
  m_record_instance.resize(base + count, abi::kInvalidIndex);
  m_record_node.resize(base + count, abi::kInvalidIndex);
  return base;
}

void GpuScene::assign_records(const Scene& scene, const std::vector<Instance>& instances) {
  // Instances still showing the mesh they had keep their records.
  std::unordered_map<uint32_t, Slot> kept;
  for (const Instance& instance : instances) {
    const auto it = m_slots.find(instance.node);
    if (it != m_slots.end() && it->second.mesh == instance.mesh &&
        it->second.count == m_ranges[instance.mesh].size()) {
      kept.emplace(instance.node, it->second);
      m_slots.erase(it);
    }
  }
  if (!m_slots.empty() || kept.size() != instances.size()) ++m_records_generation;
  for (const auto& [node, slot] : m_slots) {  // the rest left: their records are free
    for (uint32_t r = slot.base; r < slot.base + slot.count; ++r) {
      m_records[r] = {0, 0, 0, abi::kInvalidIndex, abi::kInvalidIndex};
      m_record_instance[r] = m_record_node[r] = abi::kInvalidIndex;
    }
    if (slot.count > 0) m_free.emplace_back(slot.base, slot.count);
  }
  // Neighbouring free ranges merge, so that a later instance of any size fits where they were.
  std::sort(m_free.begin(), m_free.end());
  std::vector<std::pair<uint32_t, uint32_t>> merged;
  for (const auto& range : m_free) {
    if (!merged.empty() && merged.back().first + merged.back().second == range.first)
      merged.back().second += range.second;
    else
      merged.push_back(range);
  }
  m_free = std::move(merged);
  m_slots = std::move(kept);

  const size_t capacity = m_records.size();
  m_record_base.assign(instances.size(), 0);
  uint32_t identity = 0;  // the record's index in a fresh upload
  for (size_t i = 0; i < instances.size(); ++i) {
    const Instance& instance = instances[i];
    const uint32_t count = uint32_t(m_ranges[instance.mesh].size());
    auto it = m_slots.find(instance.node);
    if (it == m_slots.end())
      it =
          m_slots.emplace(instance.node, Slot{allocate_records(count), count, instance.mesh}).first;
    m_record_base[i] = it->second.base;
    const Mesh& mesh = scene.meshes[instance.mesh];
    for (uint32_t p = 0; p < count; ++p) {
      const PrimitiveRange& range = m_ranges[instance.mesh][p];
      const uint32_t r = it->second.base + p;
      m_records[r] = {mesh.primitives[p].material, range.first_index, range.vertex_offset,
                      abi::kInvalidIndex, identity++};
      m_record_instance[r] = uint32_t(i);
      m_record_node[r] = instance.node;
    }
  }
  if (!geometries || m_records.size() != capacity) {
    // Never empty: a buffer of no bytes cannot be bound.
    geometries = vk::make_storage_buffer(
        m_ctx, m_records.empty() ? std::vector<abi::GeometryRecord>(1) : m_records, 0,
        vk::MemoryUse::Shared);
    ++m_layout_generation;
  }
}

void GpuScene::set_frame(const abi::FrameParams& params) {
  m_frame_params = params;
  frame_buffer.upload(&params, sizeof params);
}

void GpuScene::bind_set() {
  if (!m_set) return;  // during construction: bound once everything exists
  if (m_ctx.software_traversal()) {
    m_set->bind_buffer(abi::kSceneBlasNodes, m_software.blas_nodes);
    m_set->bind_buffer(abi::kSceneBlasTriangles, m_software.blas_triangles);
    m_set->bind_buffer(abi::kSceneTlasNodes, m_software.tlas_nodes);
    m_set->bind_buffer(abi::kSceneTlasInstances, m_software.tlas_instances);
  } else {
    m_set->bind_acceleration_structure(abi::kSceneTlas, m_tlas.structure.handle());
    m_set->bind_buffer(abi::kSceneTriangleOrder, triangle_order);
  }
  const std::pair<uint32_t, const vk::Buffer*> buffers[] = {
      {abi::kScenePositions, &positions},
      {abi::kSceneNormals, &normals},
      {abi::kSceneTangents, &tangents},
      {abi::kSceneUvs, &uvs},
      {abi::kSceneIndices, &indices},
      {abi::kSceneGeometries, &geometries},
      {abi::kSceneMaterials, &materials},
      {abi::kSceneTextures, &textures},
      {abi::kSceneTexels, &texels},
      {abi::kSceneLights, &lights},
      {abi::kSceneLightCdf, &light_cdf},
      {abi::kSceneEnvironment, &environment},
      {abi::kSceneBsdfTables, &bsdf_tables},
      {abi::kSceneFrame, &frame_buffer},
      {abi::kSceneLightTree, &light_tree},
      {abi::kSceneGuideCounts, &guide_counts},
      {abi::kSceneGuide, &guide},
  };
  for (const auto& [binding, buffer] : buffers) m_set->bind_buffer(binding, *buffer);
}

void GpuScene::upload_geometry(const Scene& scene) {
  // Shared vertex data: each mesh primitive once, however many instances use it.
  std::vector<glm::vec3> all_positions, all_normals;
  std::vector<glm::vec4> all_tangents;
  std::vector<glm::vec4> all_uvs;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw
  std::vector<uint32_t> all_indices;
  m_ranges.assign(scene.meshes.size(), {});
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    for (const MeshPrimitive& p : scene.meshes[m].primitives) {
      if (all_positions.size() + p.positions.size() > UINT32_MAX ||
          all_indices.size() + p.indices.size() > UINT32_MAX)
        throw InputError("scene is too large (more than 4G vertices or indices)");
      m_ranges[m].push_back({uint32_t(all_indices.size()), uint32_t(all_positions.size()),
                             uint32_t(p.indices.size() / 3), uint32_t(p.positions.size())});
      all_positions.insert(all_positions.end(), p.positions.begin(), p.positions.end());
      all_normals.insert(all_normals.end(), p.normals.begin(), p.normals.end());
      all_tangents.insert(all_tangents.end(), p.tangents.begin(), p.tangents.end());
      for (size_t v = 0; v < p.uvs.size(); ++v)
        all_uvs.emplace_back(p.uvs[v], v < p.uvs1.size() ? p.uvs1[v] : glm::vec2(0.0f));
      all_indices.insert(all_indices.end(), p.indices.begin(), p.indices.end());
    }
  }
  // Ray queries: each primitive's triangles in spatial order for the BLAS builds, and the
  // way back to the triangle's own index, at the triangle's place in the scene's index buffer
  // (traversal_order.h; primitives hold whole triangles: complete_primitive). hipr's own BVH
  // sorts its own.
  std::vector<uint32_t> built_indices, built_order;
  if (!m_ctx.software_traversal()) {
    built_indices = all_indices;
    built_order.assign(all_indices.size() / 3, 0);
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
      const std::vector<std::vector<uint32_t>>& orders = m_triangle_orders.of(scene.meshes[m]);
      for (size_t p = 0; p < m_ranges[m].size(); ++p) {
        const PrimitiveRange& r = m_ranges[m][p];
        const std::span<const uint32_t> triangles(all_indices.data() + r.first_index,
                                                  size_t(r.triangle_count) * 3);
        const std::vector<uint32_t>& order = orders[p];
        for (size_t k = 0; k < order.size(); ++k) {
          built_order[r.first_index / 3 + k] = order[k];
          std::copy_n(triangles.begin() + 3 * order[k], 3,
                      built_indices.begin() + r.first_index + 3 * k);
        }
      }
    }
    m_triangle_orders.end_upload();
  }
  // Acceleration-structure builds read positions and indices (ray queries only).
  const VkBufferUsageFlags build_input =
      m_ctx.software_traversal()
          ? 0
          : VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;
  check_fits(m_ctx, all_positions.size() * sizeof(all_positions[0]), "vertex positions");
  check_fits(m_ctx, all_normals.size() * sizeof(all_normals[0]), "vertex normals");
  check_fits(m_ctx, all_tangents.size() * sizeof(all_tangents[0]), "vertex tangents");
  check_fits(m_ctx, all_uvs.size() * sizeof(all_uvs[0]), "texture coordinates");
  check_fits(m_ctx, all_indices.size() * sizeof(all_indices[0]), "triangle indices");
  positions = vk::make_storage_buffer(m_ctx, all_positions, build_input);
  normals = vk::make_storage_buffer(m_ctx, all_normals);
  tangents = vk::make_storage_buffer(m_ctx, all_tangents);
  uvs = vk::make_storage_buffer(m_ctx, all_uvs);
  indices = vk::make_storage_buffer(m_ctx, all_indices);
  if (!m_ctx.software_traversal()) {
    built_indices.resize(std::max<size_t>(built_indices.size(), 1));  // a buffer needs bytes
    built_order.resize(std::max<size_t>(built_order.size(), 1));
    blas_indices = vk::make_storage_buffer(m_ctx, built_indices, build_input);
    triangle_order = vk::make_storage_buffer(m_ctx, built_order);
  }

  // The BLASes hold their own copy of the triangles: meshes that stay keep theirs.
  m_blas.resize(scene.meshes.size());
  m_has_blas.resize(scene.meshes.size(), false);
  m_blas_opaque.resize(scene.meshes.size());
  m_blas_revision.resize(scene.meshes.size(), 0);
}

bool GpuScene::build_blases(const Scene& scene) {
  // One BLAS per mesh, one geometry per primitive. BLAS indices are relative to the
  // primitive's first vertex, which is why the vertex address carries the offset. The software
  // traversal builds its own mesh BVH at the same moments.
  bool rebuilt = false;
  m_info.cutout_geometries = 0;
  const Timer timer;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    std::vector<bool> opaque;
    for (const MeshPrimitive& p : scene.meshes[m].primitives)
      opaque.push_back(material_is_opaque(scene.materials[p.material].params));
    m_info.cutout_geometries += size_t(std::count(opaque.begin(), opaque.end(), false));
    if (m_ranges[m].empty()) {
      m_has_blas[m] = false;
      continue;
    }
    if (m_has_blas[m] && opaque == m_blas_opaque[m] &&
        m_blas_revision[m] == scene.meshes[m].revision)
      continue;
    rebuilt = true;
    if (m_ctx.software_traversal()) {
      m_software.set_mesh(m, scene.meshes[m], opaque);
    } else {
      std::vector<vk::TriangleGeometry> geometry;
      for (size_t p = 0; p < m_ranges[m].size(); ++p) {
        const PrimitiveRange& r = m_ranges[m][p];
        geometry.push_back(
            {positions.address() + VkDeviceAddress(r.vertex_offset) * sizeof(glm::vec3),
             r.vertex_count,
             blas_indices.address() + VkDeviceAddress(r.first_index) * sizeof(uint32_t),
             r.triangle_count, opaque[p]});
      }
      m_blas[m] = vk::build_blas(m_ctx, geometry);
    }
    m_has_blas[m] = true;
    ++m_info.blas_builds;
    m_blas_opaque[m] = std::move(opaque);
    m_blas_revision[m] = scene.meshes[m].revision;
  }
  if (rebuilt && m_ctx.software_traversal()) m_software.upload_meshes(m_ctx);
  if (rebuilt) m_info.blas_build_seconds += timer.seconds();
  return rebuilt;
}

void GpuScene::upload_textures(const Scene& scene) {
  // Texels once per image, one image after another; every texture reference on it points at
  // the same offset. Images only come and go at the end of the list (imports and their undo):
  // the leading ones the buffer holds already (same revision) stay where they are, on the device.
  // Where they do not fit one buffer of this device, the largest images are halved on the
  // device (texture_fit.h); a reduced buffer is rebuilt whole.
  const uint64_t max_texels =
      std::min<uint64_t>(m_ctx.max_storage_range() / sizeof(uint32_t), UINT32_MAX);
  const std::vector<uint8_t> halvings = texture_halvings(scene.images, max_texels);
  const bool reduced = std::any_of(halvings.begin(), halvings.end(), [](uint8_t h) { return h; });
  size_t kept = 0;
  while (!reduced && !m_textures_reduced &&
         kept < std::min(m_image_revision.size(), scene.images.size()) &&
         m_image_revision[kept] == scene.images[kept].revision)
    ++kept;
  if (reduced) {
    size_t halved = 0;
    for (uint8_t h : halvings) halved += h > 0;
    log::warn("the scene's textures do not fit one buffer of " + m_ctx.device_name() + " (" +
              mib(m_ctx.max_storage_range()) + " MiB): " + std::to_string(halved) + " of " +
              std::to_string(scene.images.size()) + " images are shown at reduced resolution");
  }
  m_textures_reduced = reduced;
  const size_t kept_texels =
      kept == 0
          ? 0
          : m_image_offset[kept - 1] + size_t(m_image_size[kept - 1].x) * m_image_size[kept - 1].y;
  m_image_offset.resize(kept);
  m_image_revision.resize(kept);
  m_image_size.resize(kept);
  std::vector<uint32_t> added;  // the texels of the images after the kept ones
  for (size_t i = kept; i < scene.images.size(); ++i) {
    const Image& image = scene.images[i];
    m_image_offset.push_back(uint32_t(kept_texels + added.size()));
    m_image_revision.push_back(image.revision);
    uint32_t width = image.width, height = image.height;
    if (halvings[i] == 0) {
      const size_t start = added.size();
      added.resize(start + image.rgba8.size() / 4);
      std::memcpy(added.data() + start, image.rgba8.data(), image.rgba8.size() / 4 * 4);
    } else {
      const std::vector<uint32_t> texels_of_image =
          halved_texels(image, halvings[i], width, height);
      added.insert(added.end(), texels_of_image.begin(), texels_of_image.end());
    }
    m_image_size.push_back({width, height});
  }
  if (!texels || !added.empty()) {
    vk::Buffer grown(m_ctx, VkDeviceSize(kept_texels + added.size()) * sizeof(uint32_t),
                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (kept_texels > 0)
      m_ctx.submit_and_wait([&](VkCommandBuffer cmd) {
        const VkBufferCopy region{0, 0, VkDeviceSize(kept_texels) * sizeof(uint32_t)};
        vkCmdCopyBuffer(cmd, texels.handle(), grown.handle(), 1, &region);
      });
    if (!added.empty())
      grown.upload(added.data(), added.size() * sizeof(uint32_t),
                   VkDeviceSize(kept_texels) * sizeof(uint32_t));
    texels = std::move(grown);
  }
  std::vector<abi::TextureInfo> infos;
  for (const Texture& t : scene.textures) {
    if (t.image >= scene.images.size()) throw InternalError("texture references a missing image");
    const glm::uvec2 size = m_image_size[t.image];
    infos.push_back(
        {m_image_offset[t.image], size.x, size.y, t.flags, t.uv_transform_u, t.uv_transform_v});
  }
  textures = vk::make_storage_buffer(m_ctx, infos);
}

void GpuScene::update_materials(const Scene& scene) {
  upload_materials(scene);
  if (build_blases(scene)) update_instances(scene);  // new BLAS addresses need a new TLAS
  bind_set();
}

void GpuScene::upload_materials(const Scene& scene) {
  std::vector<abi::MaterialBlock> blocks;
  m_material_view_dependent.clear();
  for (const Material& m : scene.materials) {
    blocks.push_back(pack_material(m.params));
    m_material_view_dependent.push_back(material_is_view_dependent(m.params) ? 1 : 0);
  }
  vk::write_storage_buffer(m_ctx, materials, blocks);  // update_materials binds the set again
}

void GpuScene::update_instances(const Scene& scene) {
  const std::vector<Instance> instances = scene.instances();
  assign_records(scene, instances);
  const auto [lo, hi] = scene.bounds();
  m_info.scene_radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
  m_info.triangle_count = 0;
  m_info.instance_count = 0;
  std::vector<vk::TlasInstance> tlas_instances;
  std::vector<SoftwareBvh::Placement> placements;
  for (size_t i = 0; i < instances.size(); ++i) {
    const Instance& instance = instances[i];
    if (!m_has_blas[instance.mesh]) continue;
    if (m_ctx.software_traversal() && instance.visible)
      placements.push_back({instance.world, instance.mesh, m_record_base[i]});
    // Facing is computed from object-space normals in the shader; the flag keeps the
    // hardware's notion of front faces consistent for mirroring transforms.
    const bool mirrored = glm::determinant(glm::mat3(instance.world)) < 0.0f;
    if (!m_ctx.software_traversal())
      tlas_instances.push_back({affine_rows(instance.world), m_record_base[i],
                                m_blas[instance.mesh].address(), !mirrored, instance.visible});
    if (!instance.visible) continue;
    m_info.instance_count += 1;
    for (const PrimitiveRange& r : m_ranges[instance.mesh])
      m_info.triangle_count += r.triangle_count;
  }
  // An empty TLAS is valid and makes every ray miss.
  if (m_ctx.software_traversal())
    m_software.upload_instances(m_ctx, placements);
  else
    vk::build_tlas(m_ctx, tlas_instances, m_tlas);
  update_lights(scene);
}

void GpuScene::upload_environment(const Scene& scene) {
  m_environment_mean = scene.environment ? environment_mean_luminance(*scene.environment) : 0.0f;
  environment = vk::make_storage_buffer(m_ctx, scene.environment
                                                   ? build_environment_buffer(*scene.environment)
                                                   : std::vector<float>{});
}

void GpuScene::update_environment(const Scene& scene) {
  upload_environment(scene);
  bind_set();
}

void GpuScene::update_lights(const Scene& scene) {
  m_lights = build_light_tables(scene, scene.instances(), m_record_base, uint32_t(m_records.size()),
                                m_info.scene_radius, m_environment_mean, m_groups);
  for (size_t r = 0; r < m_records.size(); ++r)
    m_records[r].lightOffset = m_lights.record_light_offset[r];
  geometries.upload(m_records.data(), m_records.size() * sizeof(abi::GeometryRecord));
  m_info.light_count = m_lights.lights.size();
  vk::write_storage_buffer(m_ctx, lights, m_lights.lights);
  vk::write_storage_buffer(m_ctx, light_cdf, m_lights.cdf);
  vk::write_storage_buffer(m_ctx, light_tree, m_lights.tree);
  bind_set();
}

void GpuScene::reserve_guide() {
  const size_t slots = size_t(abi::kGuideMaxCells) * abi::kGuideSlots;
  if (guide.size() >= slots * sizeof(float)) return;
  guide_counts = vk::make_storage_buffer(
      m_ctx, std::vector<uint64_t>(size_t(abi::kGuideMaxCells) * abi::kGuideSumSlots));
  guide = vk::make_storage_buffer(m_ctx, std::vector<float>(slots));
  bind_set();
}

}  // namespace hipr
