#pragma once
// The scene as the kernels see it: shared vertex/index buffers, one BLAS per mesh, a TLAS of
// instances (or, without ray queries, hipr's own two-level BVH), material/texture/light tables, the
// environment, the BSDF tables and the frame parameters, all in one descriptor set (set 1 of every
// kernel that reads the scene: shaders/shared/bindings/scene.h). Edits update only what they touch
// (geometry, materials, instances + lights, or lights alone) and the set follows.
//
// Records (one per instance and primitive) keep their index while their instance stays in the
// scene: the G-buffers and the display name surfaces by record, and must go on meaning the same
// surface after an edit adds or removes others. A removed instance's records are free for a
// later one; records are grouped per instance, in no particular order.
#include <memory>
#include <unordered_map>
#include <vector>

#include "hipr/renderer.h"
#include "hipr/scene.h"
#include "render/light_groups.h"
#include "render/light_tables.h"
#include "render/software_bvh.h"
#include "render/triangle_orders.h"
#include "vk/acceleration.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/descriptor_set.h"

namespace hipr {

class GpuScene {
 public:
  // `light_group_budget`: see RenderSettings::light_groups.
  GpuScene(const vk::Context& ctx, const Scene& scene, uint32_t light_group_budget = 0);
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  // Re-uploads the material blocks (same count: edits change parameters, not the table). An
  // edit that makes a material need the alpha test, or no longer need it, rebuilds the BLAS of
  // the meshes using it and the TLAS.
  void update_materials(const Scene& scene);
  // Rebuilds the TLAS (transforms, visibility, instances added or removed: records follow) and
  // the light tables that depend on them.
  void update_instances(const Scene& scene);
  // After meshes were added, removed or deformed (ChangeSet::geometry): uploads the vertices,
  // textures and material tables again, builds the BLAS of each new or changed mesh (the others
  // keep theirs), then updates the instances.
  void update_geometry(const Scene& scene);
  // Rebuilds the light tables alone (punctual lights, emission strengths).
  void update_lights(const Scene& scene);
  // Uploads another environment map (or none) and its sampling tables. Its entry in the light
  // tables follows with update_lights (a new map is a light-table change: ChangeSet::light_tables).
  void update_environment(const Scene& scene);

  // The light groups, chosen when the scene was uploaded; their material table (uint per material).
  const LightGroups& light_groups() const { return m_groups; }
  vk::Buffer material_groups;

  // The frame parameters the kernels read (camera, image and tiles, HiPR weights).
  void set_frame(const abi::FrameParams& params);
  const abi::FrameParams& frame() const { return m_frame_params; }
  // Set 1 of the kernels that read the scene; its buffers are rebound after every update.
  const vk::DescriptorSet& descriptor_set() const { return *m_set; }

  const SceneStats& info() const { return m_info; }
  // Starts counting the BLAS builds of an update (SceneStats::blas_builds) from zero.
  void reset_build_stats() {
    m_info.blas_builds = 0;
    m_info.blas_build_seconds = 0.0;
  }
  const LightTables& light_tables() const { return m_lights; }
  // Instance index of each GeometryRecord (records are grouped per instance; kInvalidIndex for a
  // free record, which no instance of the scene holds).
  const std::vector<uint32_t>& record_instance() const { return m_record_instance; }
  // Node of each GeometryRecord (the viewer outlines a selected node; kInvalidIndex when free).
  const std::vector<uint32_t>& record_node() const { return m_record_node; }
  uint32_t record_count() const { return uint32_t(m_records.size()); }
  // Whether a record's material is view-dependent (material_is_view_dependent), as of the last
  // material update.
  bool record_view_dependent(uint32_t record) const {
    return m_material_view_dependent[m_records[record].materialIndex] != 0;
  }

  vk::Buffer positions, normals, tangents, uvs, indices;
  // Ray queries only: the triangles as the BLASes were built from them (each primitive's in
  // spatial order) and, per built triangle, the index of the triangle in its primitive.
  vk::Buffer blas_indices, triangle_order;
  vk::Buffer geometries, materials, textures, texels;
  vk::Buffer lights, light_cdf, light_tree, environment;
  vk::Buffer bsdf_tables, frame_buffer;
  // Path guiding (render/guide_pass.h): the training's sums (kGuideSumSlots per cell) and the
  // guide (kGuideSlots per cell).
  vk::Buffer guide_counts, guide;
  // Makes the guide's buffers large enough for kGuideMaxCells cells (a render that guides).
  void reserve_guide();

  // How the buffers other passes bind besides the set (material_groups) and the record count
  // changed: a counter that grows when they are replaced, so passes know to bind them again.
  uint64_t layout_generation() const { return m_layout_generation; }
  // Grows when instances were added or removed (record_instance and record_node changed).
  uint64_t records_generation() const { return m_records_generation; }

 private:
  // The records of one instance: [base, base + count), for as long as its node shows that mesh.
  struct Slot {
    uint32_t base;
    uint32_t count;
    uint32_t mesh;
  };
  struct PrimitiveRange {
    uint32_t first_index;
    uint32_t vertex_offset;
    uint32_t triangle_count;
    uint32_t vertex_count;
  };
  void upload_geometry(const Scene& scene);
  void upload_textures(const Scene& scene);
  void upload_environment(const Scene& scene);
  void upload_material_groups(const Scene& scene);
  void upload_materials(const Scene& scene);
  // Gives every instance its slot (keeping those of instances still there), frees the others'
  // and fills the records.
  void assign_records(const Scene& scene, const std::vector<Instance>& instances);
  uint32_t allocate_records(uint32_t count);
  // (Re)builds the BLAS of every mesh whose per-primitive opacity flags differ from the built
  // ones; returns whether any was rebuilt.
  bool build_blases(const Scene& scene);
  // Points the descriptor set at the current buffers (updates replace some of them).
  void bind_set();

  const vk::Context& m_ctx;
  SceneStats m_info;
  LightTables m_lights;
  LightGroups m_groups;
  float m_environment_mean =
      0.0f;  // environment_mean_luminance of the map uploaded last (light power)
  std::vector<std::vector<PrimitiveRange>> m_ranges;  // per mesh, per primitive
  TriangleOrders m_triangle_orders;                   // ray queries: each mesh's build order
  std::vector<vk::AccelerationStructure> m_blas;      // one per mesh (empty meshes: none)
  std::vector<bool> m_has_blas;
  std::vector<std::vector<bool>> m_blas_opaque;  // per mesh, per primitive, as built
  std::vector<uint64_t> m_blas_revision;         // per mesh: Mesh::revision as built
  std::vector<uint32_t> m_image_offset;          // per image: its first texel in `texels`
  std::vector<uint64_t> m_image_revision;  // per image: Image::revision of what `texels` holds
  std::vector<glm::uvec2> m_image_size;    // per image: its size in `texels` (maybe halved)
  bool m_textures_reduced = false;         // some image halved to fit the device (texture_fit.h)
  uint64_t m_layout_generation = 0, m_records_generation = 0;
  std::unordered_map<uint32_t, Slot> m_slots;         // per node with an instance
  std::vector<std::pair<uint32_t, uint32_t>> m_free;  // free records: (base, count)
  std::vector<abi::GeometryRecord> m_records;
  std::vector<uint32_t> m_record_base;             // per instance
  std::vector<uint32_t> m_record_instance;         // per record
  std::vector<uint32_t> m_record_node;             // per record
  std::vector<uint8_t> m_material_view_dependent;  // per material
  vk::Tlas m_tlas;
  SoftwareBvh m_software;  // instead of m_blas and m_tlas on a device without ray queries
  abi::FrameParams m_frame_params{};
  std::unique_ptr<vk::DescriptorSet> m_set;
};

}  // namespace hipr
