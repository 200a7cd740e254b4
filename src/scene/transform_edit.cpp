// Transform edits' rotate and scale (include/hipr/edits.h, transformed_local).
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "hipr/edits.h"

namespace hipr {

glm::mat4 euler_rotation(const glm::vec3& degrees) {
  const glm::mat4 identity(1.0f);
  // Fixed axes, x first: R = Rz * Ry * Rx.
  return glm::rotate(identity, glm::radians(degrees.z), glm::vec3(0.0f, 0.0f, 1.0f)) *
         glm::rotate(identity, glm::radians(degrees.y), glm::vec3(0.0f, 1.0f, 0.0f)) *
         glm::rotate(identity, glm::radians(degrees.x), glm::vec3(1.0f, 0.0f, 0.0f));
}

glm::mat4 transformed_local(const glm::mat4& local, const TransformEdit& edit) {
  if (edit.matrix) return *edit.matrix;
  if (edit.scale)
    for (int axis = 0; axis < 3; ++axis) {
      const float factor = std::abs((*edit.scale)[axis]);
      if (!(factor >= 1e-6f && factor <= 1e6f))
        throw InputError("transform " + edit.node + ": a scale factor must be nonzero, finite " +
                         "and between 1e-6 and 1e6 in size (got " +
                         std::to_string((*edit.scale)[axis]) + ")");
    }
  glm::mat4 rest = local;  // L: the local transform without its translation
  rest[3] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  glm::vec3 origin = glm::vec3(local[3]);
  if (edit.translate) origin += *edit.translate;
  glm::mat4 out = rest;
  if (edit.scale) out = out * glm::scale(glm::mat4(1.0f), *edit.scale);
  if (edit.rotate) out = euler_rotation(*edit.rotate) * out;
  out[3] = glm::vec4(origin, 1.0f);
  return out;
}

LocalPose local_pose(const glm::mat4& local) {
  LocalPose pose;
  pose.translation = glm::vec3(local[3]);
  glm::mat3 rotation(local);
  for (int axis = 0; axis < 3; ++axis) {
    pose.scale[axis] = glm::length(rotation[axis]);
    if (pose.scale[axis] > 0.0f) rotation[axis] /= pose.scale[axis];
  }
  if (glm::determinant(rotation) < 0.0f) {  // a mirror: carried by the x scale
    pose.scale.x = -pose.scale.x;
    rotation[0] = -rotation[0];
  }
  // R = Rz(c) Ry(b) Rx(a); glm indexes [column][row]: row 2 of column 0 is -sin(b).
  const float sin_b = std::clamp(-rotation[0][2], -1.0f, 1.0f);
  float a, b = std::asin(sin_b), c;
  if (std::abs(sin_b) < 0.99999f) {
    a = std::atan2(rotation[1][2], rotation[2][2]);
    c = std::atan2(rotation[0][1], rotation[0][0]);
  } else {  // gimbal lock: z's turn folds into x's
    a = std::atan2(-rotation[2][1], rotation[1][1]);
    c = 0.0f;
  }
  pose.rotation_degrees = glm::degrees(glm::vec3(a, b, c));
  return pose;
}

glm::mat4 compose_pose(const LocalPose& pose) {
  glm::mat4 out = euler_rotation(pose.rotation_degrees) * glm::scale(glm::mat4(1.0f), pose.scale);
  out[3] = glm::vec4(pose.translation, 1.0f);
  return out;
}

}  // namespace hipr
