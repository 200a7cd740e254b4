#pragma once
// A binned-SAH bounding volume hierarchy over boxes, for the software traversal
// (shaders/common/bvh_traversal.glsl): built on the host, uploaded as abi::BvhNode arrays. One
// builder serves both levels: triangles of a mesh, instances of the scene.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shaders/shared/abi.h"

namespace hipr {

struct Box {
  glm::vec3 lo{3.0e38f};
  glm::vec3 hi{-3.0e38f};
  void grow(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  float half_area() const;  // 0 for an empty box
};

struct Bvh {
  // Root first. Leaves' `first` indexes `order`'s slots; interior nodes' `first` their left child.
  std::vector<abi::BvhNode> nodes;
  // The item in each leaf slot: leaves cover contiguous runs of it.
  std::vector<uint32_t> order;
};

// Deterministic for the same boxes. Leaves hold at most kBvhMaxLeafItems items unless the tree
// reached abi::kBvhMaxDepth (or the items cannot be told apart); no items: one empty leaf.
constexpr uint32_t kBvhMaxLeafItems = 4;
Bvh build_bvh(const std::vector<Box>& boxes);

}  // namespace hipr
