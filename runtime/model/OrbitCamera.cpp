#include "model/OrbitCamera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace rmfx {

glm::vec3 OrbitCamera::position() const {
    float yaw = glm::radians(settings_.yawDegrees), pitch = glm::radians(settings_.pitchDegrees);
    // yaw 0 puts the camera on +Z looking down -Z.
    glm::vec3 offset(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
    return settings_.target + offset * settings_.distance;
}

glm::mat4 OrbitCamera::view() const {
    const glm::vec3 eye = position();
    if (settings_.rollDegrees == 0.0f) return glm::lookAt(eye, settings_.target, glm::vec3(0, 1, 0));
    // +Y made perpendicular to the viewing direction (pitch stays within ±89°), then turned toward
    // the camera's right by the roll.
    const glm::vec3 forward = glm::normalize(settings_.target - eye);
    const glm::vec3 up = glm::normalize(glm::vec3(0, 1, 0) - forward * forward.y);
    const glm::vec3 right = glm::cross(forward, up);
    const float roll = glm::radians(settings_.rollDegrees);
    return glm::lookAt(eye, settings_.target, up * std::cos(roll) + right * std::sin(roll));
}

glm::mat4 OrbitCamera::projection(float aspect) const {
    return glm::perspective(glm::radians(settings_.fovYDegrees), aspect, settings_.nearPlane, settings_.farPlane);
}

void OrbitCamera::orbit(float yawDegrees, float pitchDegrees) {
    settings_.yawDegrees = std::fmod(settings_.yawDegrees + yawDegrees, 360.0f);
    settings_.pitchDegrees = std::clamp(settings_.pitchDegrees + pitchDegrees, -89.0f, 89.0f);
}

void OrbitCamera::pan(glm::vec2 viewFractions) {
    glm::mat4 v = view();
    glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
    float extent = settings_.distance * std::tan(glm::radians(settings_.fovYDegrees) * 0.5f) * 2.0f;
    settings_.target += (right * viewFractions.x + up * viewFractions.y) * extent;
}

void OrbitCamera::zoom(float factor) {
    if (factor > 0.0f && std::isfinite(factor)) settings_.distance = std::max(1e-3f, settings_.distance * factor);
}

}  // namespace rmfx
