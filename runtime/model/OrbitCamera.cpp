#include "model/OrbitCamera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace rmfx {

std::optional<OrbitCameraSettings> orbitLookingAt(glm::vec3 eye, glm::vec3 target, glm::vec3 up,
                                                  const OrbitCameraSettings& base) {
    const glm::vec3 offset = eye - target;
    const float distance = glm::length(offset);
    if (!(distance > 1e-6f)) return std::nullopt;
    OrbitCameraSettings s = base;
    s.target = target;
    s.distance = distance;
    s.yawDegrees = glm::degrees(std::atan2(offset.x, offset.z));
    s.pitchDegrees = std::clamp(glm::degrees(std::asin(std::clamp(offset.y / distance, -1.0f, 1.0f))), -89.0f, 89.0f);
    // The roll that turns +Y made perpendicular to the view into `up`'s part across it, as view()
    // applies it.
    s.rollDegrees = 0.0f;
    const glm::vec3 forward = -offset / distance;
    const glm::vec3 plainUp = glm::vec3(0, 1, 0) - forward * forward.y;
    const glm::vec3 given = up - forward * glm::dot(up, forward);
    if (glm::length(plainUp) > 1e-4f && glm::length(given) > 1e-4f) {
        const glm::vec3 u = glm::normalize(plainUp), right = glm::cross(forward, u);
        s.rollDegrees = glm::degrees(std::atan2(glm::dot(given, right), glm::dot(given, u)));
        if (std::abs(s.rollDegrees) < 1e-3f) s.rollDegrees = 0.0f;
    }
    return s;
}

glm::vec3 OrbitCamera::position() const {
    float yaw = glm::radians(settings_.yawDegrees), pitch = glm::radians(settings_.pitchDegrees);
    // yaw 0 puts the camera on +Z looking down -Z.
    glm::vec3 offset(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
    return settings_.target + offset * settings_.distance;
}

glm::mat4 OrbitCamera::view() const {
    const glm::vec3 eye = position();
    glm::vec3 up(0, 1, 0);
    if (settings_.rollDegrees != 0.0f) {
        // +Y made perpendicular to the viewing direction (pitch stays within ±89°), then turned
        // toward cross(forward, up) by the roll (OpenGL's right; Direct3D's left).
        const glm::vec3 forward = glm::normalize(settings_.target - eye);
        const glm::vec3 plain = glm::normalize(glm::vec3(0, 1, 0) - forward * forward.y);
        const glm::vec3 right = glm::cross(forward, plain);
        const float roll = glm::radians(settings_.rollDegrees);
        up = plain * std::cos(roll) + right * std::sin(roll);
    }
    return settings_.convention == CameraConvention::Direct3D ? glm::lookAtLH(eye, settings_.target, up)
                                                               : glm::lookAtRH(eye, settings_.target, up);
}

glm::mat4 OrbitCamera::projection(float aspect) const {
    const float fov = glm::radians(settings_.fovYDegrees);
    return settings_.convention == CameraConvention::Direct3D
               ? glm::perspectiveLH_ZO(fov, aspect, settings_.nearPlane, settings_.farPlane)
               : glm::perspectiveRH_NO(fov, aspect, settings_.nearPlane, settings_.farPlane);
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
