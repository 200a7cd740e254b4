#pragma once
// Each mesh's build order (traversal_order.h), kept from one geometry upload to the next. Every
// upload rebuilds the scene's index buffers whole, but an edit changes one mesh: a deform or an
// import of one mesh sorts that mesh alone (a deform of one of MetalRoughSpheresNoTextures'
// spheres updated the scene in 0.44-0.56 s sorting them all, 0.06-0.11 s so). Kept by
// Mesh::revision, a fingerprint of the positions and indices the order is made from, so a mesh that
// moves to another slot (a removal before it) keeps its order. What an upload stops asking for is
// kept one upload more: an undo right after a deform or a removal brings back a mesh of the
// revision before, and finds its order (the undo of a deform of a 1M-triangle mesh shown in the
// viewer 1.34 s after the key, 0.82-0.84 s so).
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "hipr/scene.h"

namespace hipr {

class TriangleOrders {
 public:
  // Per primitive of mesh, spatial_triangle_order of its triangles: the order one of the last
  // two uploads used for a mesh of this revision, else sorted now. A mesh whose revision was never
  // set (0, a scene made by hand) is sorted every time.
  const std::vector<std::vector<uint32_t>>& of(const Mesh& mesh);

  // Ends an upload: what neither it nor the one before asked for is forgotten (memory follows
  // the scene and the last edit's dropped meshes).
  void end_upload();

  // How many primitives were sorted since construction: what the keeping saved, for tests.
  size_t primitives_sorted() const { return m_primitives_sorted; }

 private:
  struct Kept {
    std::vector<std::vector<uint32_t>> orders;
    uint64_t asked = 0;  // the last upload that asked for it
  };
  std::unordered_map<uint64_t, Kept> m_kept;    // by Mesh::revision
  uint64_t m_upload = 0;                        // the upload in progress
  std::vector<std::vector<uint32_t>> m_unkept;  // the last mesh without a revision
  size_t m_primitives_sorted = 0;
};

}  // namespace hipr
