#include "scene/gltf_node_transform.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace hipr::gltf {

glm::mat4 local_transform(const std::vector<double>& matrix, const std::vector<double>& translation,
                          const std::vector<double>& rotation, const std::vector<double>& scale) {
  glm::mat4 m(1.0f);
  if (matrix.size() == 16) {
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = float(matrix[size_t(i)]);
    return m;
  }
  glm::vec3 t(0.0f), s(1.0f);
  glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
  if (translation.size() == 3) t = {translation[0], translation[1], translation[2]};
  if (scale.size() == 3) s = {scale[0], scale[1], scale[2]};
  if (rotation.size() == 4)
    r = glm::quat(float(rotation[3]), float(rotation[0]), float(rotation[1]), float(rotation[2]));
  const float len = glm::length(r);
  if (std::isfinite(len) && len > 0.0f) r /= len;
  return glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
}

}  // namespace hipr::gltf
