#pragma once
// The pose a glTF file describes, baked into its meshes at load: morph targets at their default
// weights (the node's "weights", else the mesh's) and skins at their joints' transforms, as a
// viewer shows the file before any animation plays. hipr has no animation: edits of joint nodes
// afterwards move them, not the skin.
#include <tiny_gltf.h>

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "hipr/scene.h"

namespace hipr::gltf {

class MeshPoses {
 public:
  // Finds, per mesh, the node that shows it (the first in node order with a skin or weights)
  // and every node's world transform. Throws InputError for a skin or weights that are malformed.
  MeshPoses(const tinygltf::Model& model, const std::string& name);

  // Applies mesh `mesh`'s pose to primitive `source`'s vertices in `p` (still as the accessors
  // hold them: before triangulation or flat normals), in the mesh's own frame.
  void apply(size_t mesh, const tinygltf::Primitive& source, MeshPrimitive& p,
             const std::string& what) const;

 private:
  struct Pose {
    std::vector<float> weights;  // morph target weights
    int skin = -1;
    int node = -1;  // the node showing the skinned mesh
  };
  void morph(const Pose& pose, const tinygltf::Primitive& source, MeshPrimitive& p,
             const std::string& what) const;
  void skin(const Pose& pose, const tinygltf::Primitive& source, MeshPrimitive& p,
            const std::string& what) const;
  glm::mat4 world(int node) const;

  const tinygltf::Model& m_model;
  std::string m_name;
  std::vector<Pose> m_poses;   // per mesh
  std::vector<int> m_parents;  // per node, -1 for roots
  std::vector<glm::mat4> m_locals;
};

}  // namespace hipr::gltf
