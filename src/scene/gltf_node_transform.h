#pragma once
// A glTF node's local transform, computed one way for the loader and for the writer (which must
// know, to the bit, what a node's numbers load as, to leave unedited nodes untouched).
#include <glm/glm.hpp>
#include <vector>

namespace hipr::gltf {

// `matrix` when it holds 16 numbers (column-major), else T * R * S from `translation` (3),
// `rotation` (quaternion x, y, z, w; normalised) and `scale` (3); a part of another size is the
// identity.
glm::mat4 local_transform(const std::vector<double>& matrix, const std::vector<double>& translation,
                          const std::vector<double>& rotation, const std::vector<double>& scale);

}  // namespace hipr::gltf
