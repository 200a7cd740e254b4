#pragma once
// Many-light sampling: a binary tree over the lights at finite distance (emissive triangles,
// point and spot lights), in the spirit of Conty Estevez and Kulla's light BVH (2018) and
// pbrt-v4's BVHLightSampler. Each node bounds its lights in space (a box), in the directions
// they emit toward (a cone of normals plus how far past them light leaves) and in intensity, so
// a shading point can weigh the two halves of a node by how much light each could send it and
// walk down to one light (common/light_tree.glsl). Built on the CPU, deterministically from the
// scene alone: every schedule samples the same lights with the same probabilities.
#include <cstdint>
#include <vector>

#include "shaders/shared/abi.h"

namespace hipr {

// What the tree needs of one light: its bounds and the light index it stands for.
struct LightBounds {
  glm::vec3 lo{0.0f}, hi{0.0f};
  float power = 0.0f;  // intensity toward a point in front of it (luminance)
  glm::vec3 axis{0.0f, 0.0f, 1.0f};
  float cos_spread = 1.0f;  // cos theta_o
  float cos_reach = 0.0f;   // cos theta_e
  bool two_sided = false;
  // A one-sided surface light (a triangle): it emits only toward dot(axis, x) > dot(axis, y) of
  // its points y. The tree bounds a group of such lights facing the same way by a plane
  // (abi::kLightTreeFacing).
  bool one_sided_surface = false;
  uint32_t light = 0;
};

// The bounds of a light of the table; power 0 for lights the tree does not hold (at infinity,
// degenerate, black). `emitted_luminance`: a triangle's emitted radiance (luminance).
LightBounds light_bounds(const abi::Light& light, float emitted_luminance, bool two_sided);

// The tree, root first (empty when no light has power). Sets each held light's `treeLeaf`;
// every other light's becomes kInvalidIndex.
std::vector<abi::LightTreeNode> build_light_tree(std::vector<LightBounds> bounds,
                                                 std::vector<abi::Light>& lights);

// A node's cone as the walk decodes it (abi::LightTreeNode::cone and the flags of `child`).
struct LightTreeNodeCone {
  float cos_spread = 1.0f;  // cos theta_o
  float cos_reach = 0.0f;   // cos theta_e
  float front = 0.0f;       // -inf: no plane
  bool two_sided = false;
};
LightTreeNodeCone light_tree_node_cone(const abi::LightTreeNode& node);

}  // namespace hipr
