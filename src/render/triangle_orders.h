#pragma once
// Each mesh's build order (traversal_order.h), kept from one geometry upload to the next. Every
// upload rebuilds the scene's index buffers whole, but an edit changes one mesh: a deform or an
// import of one mesh sorts that mesh alone (a deform of one of MetalRoughSpheresNoTextures'
// spheres updated the scene in 0.44-0.56 s sorting them all, 0.06-0.11 s so). Kept by
// Mesh::revision, a fingerprint of the positions and indices the order is made from, so a mesh that
// moves to another slot (a removal before it) keeps its order.
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "hipr/scene.h"

namespace hipr {

class TriangleOrders {
 public:
  // Per primitive of mesh, spatial_triangle_order of its triangles: the order the last upload
  // used for a mesh of this revision, else sorted now. A mesh whose revision was never set (0,
  // a scene made by hand) is sorted every time.
  const std::vector<std::vector<uint32_t>>& of(const Mesh& mesh);

  // Ends an upload: the orders of meshes it did not ask for are forgotten.
  void end_upload();

  // How many primitives were sorted since construction: what the keeping saved, for tests.
  size_t primitives_sorted() const { return m_primitives_sorted; }

 private:
  std::unordered_map<uint64_t, std::vector<std::vector<uint32_t>>> m_kept, m_used;
  std::vector<std::vector<uint32_t>> m_unkept;  // the last mesh without a revision
  size_t m_primitives_sorted = 0;
};

}  // namespace hipr
