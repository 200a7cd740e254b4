#include "render/triangle_orders.h"

#include "render/traversal_order.h"

namespace hipr {
namespace {

std::vector<std::vector<uint32_t>> sort_primitives(const Mesh& mesh) {
  std::vector<std::vector<uint32_t>> orders;
  for (const MeshPrimitive& p : mesh.primitives)
    orders.push_back(spatial_triangle_order(p.positions, p.indices));
  return orders;
}

// Whether orders fits mesh's primitives, one entry per triangle: two meshes of one fingerprint
// are the same geometry, and this keeps a fingerprint collision from reading past a buffer.
bool fits(const std::vector<std::vector<uint32_t>>& orders, const Mesh& mesh) {
  if (orders.size() != mesh.primitives.size()) return false;
  for (size_t p = 0; p < orders.size(); ++p)
    if (orders[p].size() != mesh.primitives[p].indices.size() / 3) return false;
  return true;
}

}  // namespace

const std::vector<std::vector<uint32_t>>& TriangleOrders::of(const Mesh& mesh) {
  if (mesh.revision == 0) {
    m_unkept = sort_primitives(mesh);
    m_primitives_sorted += mesh.primitives.size();
    return m_unkept;
  }
  Kept& kept = m_kept[mesh.revision];
  if (!fits(kept.orders, mesh)) {  // new here, or a fingerprint collision
    kept.orders = sort_primitives(mesh);
    m_primitives_sorted += mesh.primitives.size();
  }
  kept.asked = m_upload;
  return kept.orders;
}

void TriangleOrders::end_upload() {
  // Asked by this upload or the last one: kept (an undo of the last edit asks for those).
  std::erase_if(m_kept, [&](const auto& entry) { return entry.second.asked + 1 < m_upload; });
  ++m_upload;
  m_unkept.clear();
}

}  // namespace hipr
