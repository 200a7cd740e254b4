#pragma once
// The software traversal's scene: one BVH per mesh (object space, triangles gathered into its
// leaves) and a top-level BVH over the visible instances (world space), uploaded for
// shaders/common/bvh_traversal.glsl (the scene set's kSceneBlas*/kSceneTlas* bindings). What
// GpuScene builds instead of acceleration structures on a device without ray queries; the
// two levels are rebuilt when the acceleration structures would be (opacity changes: a mesh;
// transforms and visibility: the top level).
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "hipr/scene.h"
#include "render/bvh_builder.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace hipr {

// The affine part of a transform as a row-major 3x4 matrix: how TLAS instances and the
// software BVH's instances both store it.
std::array<float, 12> affine_rows(const glm::mat4& m);

class SoftwareBvh {
 public:
  // The BVH of one mesh from its primitives; `opaque[p]` false sends primitive p's triangles
  // through the opacity test (BvhTriangle::geometry's kBvhTriangleCutout).
  void set_mesh(size_t mesh_index, const Mesh& mesh, const std::vector<bool>& opaque);
  // Concatenates every mesh's tree (after set_mesh) into blas_nodes and blas_triangles.
  void upload_meshes(const vk::Context& ctx);

  struct Placement {
    glm::mat4 world;
    uint32_t mesh;
    uint32_t custom_index;  // first GeometryRecord of the instance
  };
  // The top level over `visible` (hidden instances are left out: no ray can hit them). An
  // instance whose transform cannot be inverted (a zero scale) is left out too.
  void upload_instances(const vk::Context& ctx, const std::vector<Placement>& visible);

  vk::Buffer blas_nodes, blas_triangles, tlas_nodes, tlas_instances;

 private:
  struct MeshTree {
    std::vector<abi::BvhNode> nodes;  // indices relative to the mesh's own arrays
    std::vector<abi::BvhTriangle> triangles;
    Box bounds;
  };
  std::vector<MeshTree> m_meshes;
  std::vector<uint32_t> m_roots;  // each mesh's root in blas_nodes
};

}  // namespace hipr
