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

glm::mat4 OrbitCamera::view() const { return glm::lookAt(position(), settings_.target, glm::vec3(0, 1, 0)); }

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
