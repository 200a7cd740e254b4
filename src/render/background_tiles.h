#pragma once
// Tiles that see only background: no camera ray through any point of their pixels (the
// jittered rays of trace_tiles.comp) can reach the world bounds of a visible instance. The
// trace kernel gives their samples what a miss gives (the environment's radiance in the ray's
// direction, or nothing) without a ray query. Conservative: a tile that might show geometry is
// never marked, with a pixel of margin around every projected box.
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "hipr/scene.h"

namespace hipr {

class BackgroundTiles {
 public:
  // Object-space bounds of every mesh, once: geometry never changes after loading.
  explicit BackgroundTiles(const Scene& scene);

  // One entry per tile, row-major (tiles of tile_size x tile_size pixels over width x height):
  // 1 where only background can be seen, for the scene's current camera and instances.
  std::vector<uint32_t> mask(const Scene& scene, uint32_t width, uint32_t height, uint32_t tile_size) const;

 private:
  using Box = std::pair<glm::dvec3, glm::dvec3>;  // min, max
  struct MeshBounds {
    bool empty = true;  // no triangle: nothing in the BLAS
    Box whole;
    // Boxes of runs of consecutive triangles: much tighter than the whole box for round or
    // sprawling meshes (a sphere's box covers the frame corners its triangles leave empty).
    std::vector<Box> chunks;
  };
  std::vector<MeshBounds> m_meshes;
};

}  // namespace hipr
