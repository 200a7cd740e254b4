#include "render/triangle_orders.h"

#include <utility>

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

TriangleOrders::Orders* TriangleOrders::take(std::unordered_map<uint64_t, Orders>& from,
                                             const Mesh& mesh) {
  auto found = from.find(mesh.revision);
  if (found == from.end() || !fits(found->second, mesh)) return nullptr;
  Orders& orders = m_used[mesh.revision];
  orders = std::move(found->second);
  from.erase(found);
  return &orders;
}

const std::vector<std::vector<uint32_t>>& TriangleOrders::of(const Mesh& mesh) {
  if (mesh.revision == 0) {
    m_unkept = sort_primitives(mesh);
    m_primitives_sorted += mesh.primitives.size();
    return m_unkept;
  }
  if (auto used = m_used.find(mesh.revision); used != m_used.end() && fits(used->second, mesh))
    return used->second;
  if (Orders* kept = take(m_kept, mesh)) return *kept;
  if (Orders* dropped = take(m_dropped, mesh)) return *dropped;
  Orders& orders = m_used[mesh.revision];
  orders = sort_primitives(mesh);
  m_primitives_sorted += mesh.primitives.size();
  return orders;
}

void TriangleOrders::end_upload() {
  m_dropped = std::move(m_kept);
  m_kept = std::move(m_used);
  m_used.clear();
  m_unkept.clear();
}

}  // namespace hipr
