#include "app/viewer/camera_controller.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace hipr::viewer {
namespace {

constexpr float kPi = 3.14159265358979f;
// Just short of straight up or down: lookAt with +Y up degenerates at the poles.
constexpr float kMaxPitch = 0.49f * kPi;

// Unit vector from the pivot to the eye.
glm::vec3 eye_direction(float yaw, float pitch) {
  return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}

}  // namespace

void CameraController::reset(const glm::mat4& camera_to_world, float pivot_distance) {
  const glm::vec3 eye(camera_to_world[3]);
  glm::vec3 forward = -glm::vec3(camera_to_world[2]);
  forward = glm::length(forward) > 0.0f ? glm::normalize(forward) : glm::vec3(0.0f, 0.0f, -1.0f);
  m_distance = std::max(pivot_distance, 1e-6f);
  m_pivot = eye + forward * m_distance;
  const glm::vec3 back = -forward;
  m_pitch = std::clamp(std::asin(std::clamp(back.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
  m_yaw = std::atan2(back.x, back.z);
}

void CameraController::orbit(glm::vec2 delta, float viewport_height) {
  const float radians_per_pixel = kPi / std::max(viewport_height, 1.0f);
  m_yaw -= delta.x * radians_per_pixel;
  m_pitch = std::clamp(m_pitch + delta.y * radians_per_pixel, -kMaxPitch, kMaxPitch);
}

void CameraController::pan(glm::vec2 delta, float viewport_height, float tan_half_fov) {
  const glm::mat4 frame = camera_to_world();
  // World units per pixel at the pivot's depth.
  const float scale = 2.0f * m_distance * tan_half_fov / std::max(viewport_height, 1.0f);
  m_pivot += (-delta.x * glm::vec3(frame[0]) + delta.y * glm::vec3(frame[1])) * scale;
}

void CameraController::zoom(float steps) {
  // Bounded both ways: any number of wheel steps leaves a finite, positive distance.
  m_distance = std::clamp(m_distance * std::pow(0.85f, steps), 1e-6f, 1e9f);
}

glm::mat4 CameraController::camera_to_world() const {
  const glm::vec3 eye = m_pivot + m_distance * eye_direction(m_yaw, m_pitch);
  return glm::inverse(glm::lookAt(eye, m_pivot, glm::vec3(0.0f, 1.0f, 0.0f)));
}

}  // namespace hipr::viewer
