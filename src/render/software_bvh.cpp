#include "render/software_bvh.h"

#include <cmath>
#include <cstring>

namespace hipr {
namespace {

void store_rows(const glm::mat4& m, glm::vec4 rows[3]) {
  static_assert(sizeof(glm::vec4[3]) == sizeof(std::array<float, 12>));
  std::memcpy(rows, affine_rows(m).data(), sizeof(glm::vec4[3]));
}

Box transformed(const Box& box, const glm::mat4& m) {
  Box out;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                      (corner & 4) ? box.hi.z : box.lo.z);
    out.grow(glm::vec3(m * glm::vec4(p, 1.0f)));
  }
  return out;
}

}  // namespace

std::array<float, 12> affine_rows(const glm::mat4& m) {
  return {m[0][0], m[1][0], m[2][0], m[3][0], m[0][1], m[1][1],
          m[2][1], m[3][1], m[0][2], m[1][2], m[2][2], m[3][2]};
}

void SoftwareBvh::set_mesh(size_t mesh_index, const Mesh& mesh, const std::vector<bool>& opaque) {
  if (m_meshes.size() <= mesh_index) m_meshes.resize(mesh_index + 1);
  std::vector<abi::BvhTriangle> triangles;
  std::vector<Box> boxes;
  for (size_t p = 0; p < mesh.primitives.size(); ++p) {
    const MeshPrimitive& primitive = mesh.primitives[p];
    const uint32_t geometry = uint32_t(p) | (opaque[p] ? 0u : abi::kBvhTriangleCutout);
    for (size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
      abi::BvhTriangle tri{};
      tri.v0 = primitive.positions[primitive.indices[t]];
      tri.v1 = primitive.positions[primitive.indices[t + 1]];
      tri.v2 = primitive.positions[primitive.indices[t + 2]];
      tri.geometry = geometry;
      tri.primitive = uint32_t(t / 3);
      Box box;
      box.grow(tri.v0);
      box.grow(tri.v1);
      box.grow(tri.v2);
      triangles.push_back(tri);
      boxes.push_back(box);
    }
  }
  const Bvh bvh = build_bvh(boxes);
  MeshTree& tree = m_meshes[mesh_index];
  tree.nodes = bvh.nodes;
  tree.triangles.clear();
  tree.triangles.reserve(triangles.size());
  for (uint32_t item : bvh.order) tree.triangles.push_back(triangles[item]);
  tree.bounds = Box{bvh.nodes[0].lo, bvh.nodes[0].hi};
}

void SoftwareBvh::upload_meshes(const vk::Context& ctx) {
  std::vector<abi::BvhNode> nodes;
  std::vector<abi::BvhTriangle> triangles;
  m_roots.assign(m_meshes.size(), 0);
  for (size_t m = 0; m < m_meshes.size(); ++m) {
    const uint32_t node_base = uint32_t(nodes.size());
    const uint32_t triangle_base = uint32_t(triangles.size());
    m_roots[m] = node_base;
    for (abi::BvhNode node : m_meshes[m].nodes) {
      node.first += node.count != 0 ? triangle_base : node_base;
      nodes.push_back(node);
    }
    triangles.insert(triangles.end(), m_meshes[m].triangles.begin(), m_meshes[m].triangles.end());
  }
  // Never empty: a buffer of no bytes cannot be bound.
  if (nodes.empty()) nodes.push_back({glm::vec3(0.0f), 0u, glm::vec3(0.0f), abi::kBvhLeaf});
  if (triangles.empty()) triangles.push_back({});
  blas_nodes = vk::make_storage_buffer(ctx, nodes);
  blas_triangles = vk::make_storage_buffer(ctx, triangles);
}

void SoftwareBvh::upload_instances(const vk::Context& ctx, const std::vector<Placement>& visible) {
  std::vector<abi::BvhInstance> instances;
  std::vector<Box> boxes;
  for (const Placement& placement : visible) {
    const float determinant = glm::determinant(glm::mat3(placement.world));
    if (!(std::abs(determinant) > 0.0f) || !std::isfinite(determinant)) continue;
    abi::BvhInstance instance{};
    store_rows(placement.world, instance.objectToWorld);
    store_rows(glm::inverse(placement.world), instance.worldToObject);
    instance.blasRoot = m_roots.at(placement.mesh);
    instance.customIndex = placement.custom_index;
    instances.push_back(instance);
    boxes.push_back(transformed(m_meshes.at(placement.mesh).bounds, placement.world));
  }
  const Bvh bvh = build_bvh(boxes);
  std::vector<abi::BvhInstance> ordered;
  ordered.reserve(instances.size());
  for (uint32_t item : bvh.order) ordered.push_back(instances[item]);
  if (ordered.empty()) ordered.push_back({});
  // Rebuilt at every edit that moves an instance: written in place where it fits.
  vk::write_storage_buffer(ctx, tlas_nodes, bvh.nodes);
  vk::write_storage_buffer(ctx, tlas_instances, ordered);
}

}  // namespace hipr
