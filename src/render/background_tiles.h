#pragma once
// Tiles that see only background: no camera ray through any point of their pixels (the
// jittered rays of trace_tiles.comp) can reach the world bounds of a visible instance. The
// trace kernel gives their samples what a miss gives (the environment's radiance in the ray's
// direction, or nothing) without a ray query. Conservative: a tile that might show geometry is
// never marked, with a pixel of margin around every projected box.
// Cost: one pass over the triangles when made; each mask then projects a few boxes per visible
// instance (more only along silhouettes near empty tiles).
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "hipr/scene.h"

namespace hipr {

class BackgroundTiles {
 public:
  // Object-space bounds of every mesh.
  explicit BackgroundTiles(const Scene& scene);
  // Bounds again for the meshes an edit added or deformed (by Mesh::revision).
  void update_meshes(const Scene& scene);

  // One entry per tile, row-major (tiles of tile_size x tile_size pixels over width x height):
  // 1 where only background can be seen, for the scene's current camera and instances.
  std::vector<uint32_t> mask(const Scene& scene, uint32_t width, uint32_t height,
                             uint32_t tile_size) const;

 private:
  using Box = std::pair<glm::vec3, glm::vec3>;  // min, max (of float vertices: exact in float)
  // A mesh's triangles bounded by a binary tree of boxes (median splits along the longest
  // axis; leaves of a few triangles). A box is refined only where it covers tiles not yet
  // known to show geometry, so round or sprawling meshes (a sphere, whose whole box covers the
  // frame's corners) leave their empty tiles to the background.
  struct Node {
    Box box;
    uint32_t left = 0, right = 0;  // children; none for a leaf
    bool leaf = true;
  };
  struct MeshTree {
    std::vector<Node> nodes;  // nodes[0] is the root; empty for meshes without triangles
    bool unbounded = false;   // a vertex is not finite: assume it may be seen anywhere
  };
  struct Triangle {
    Box box;
    glm::vec3 centre;
  };
  // Appends the subtree over triangles [first, last) (reordered) to `nodes`; returns its index.
  static uint32_t build_tree(std::vector<Node>& nodes, size_t leaf_size,
                             std::vector<Triangle>::iterator first,
                             std::vector<Triangle>::iterator last);

  static MeshTree build_mesh_tree(const Mesh& mesh);

  std::vector<MeshTree> m_meshes;
  std::vector<uint64_t> m_revisions;  // per mesh: Mesh::revision of its tree
};

}  // namespace hipr
