#pragma once
// The order in which a primitive's triangles go to the device's acceleration-structure build.
// Lavapipe's builder halves the triangle list as it comes, at (first + last) / 2, down to single
// triangles: a mesh whose triangles lie in no spatial order (TransmissionTest's cloth backdrop)
// got a hierarchy whose boxes all overlap, and its rays ran 30x slower. Listed so that each such
// halving is a median cut of the centroids along their longest extent, it gets an object-median
// BVH, whatever order the file had. Builders that sort for themselves (GPU drivers) lose
// nothing. The kernels see the triangles in their own order: the index the ray query reports is
// mapped back through the order (shaders/common/scene_trace.glsl).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace hipr {

// The primitive's triangles (`indices`, three per triangle, into `positions`) in that order:
// entry k is the triangle built k-th. Ties go by index, so the result depends on the geometry
// alone. Triangles without a finite centroid (a NaN vertex, an index past the vertices) go
// last, in their own order.
std::vector<uint32_t> spatial_triangle_order(std::span<const glm::vec3> positions,
                                             std::span<const uint32_t> indices);

}  // namespace hipr
