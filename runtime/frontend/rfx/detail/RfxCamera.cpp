#include "frontend/rfx/detail/RfxCamera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace rmfx::rfx {

OrbitCameraSettings orbitFromRmCamera(const RfxElement& camera) {
    OrbitCameraSettings s;
    s.where = camera.where();
    auto vec = [&](const char* x, const char* y, const char* z, glm::vec3 fallback) {
        auto a = camera.number(x), b = camera.number(y), c = camera.number(z);
        return a && b && c ? glm::vec3(*a, *b, *c) : fallback;
    };
    glm::vec3 position = vec("CAMERA_POSITION_X", "CAMERA_POSITION_Y", "CAMERA_POSITION_Z", {0, 0, 4});
    glm::vec3 lookAt = vec("LOOK_AT_VECTOR_X", "LOOK_AT_VECTOR_Y", "LOOK_AT_VECTOR_Z", {0, 0, 0});
    glm::vec3 up = vec("UP_VECTOR_X", "UP_VECTOR_Y", "UP_VECTOR_Z", {0, 1, 0});
    glm::vec3 offset = position - lookAt;
    float distance = glm::length(offset);
    if (!(distance > 1e-6f)) {
        camera.error("the camera position and its look-at point are the same: it looks nowhere");
        return s;
    }
    s.target = lookAt;
    s.distance = distance;
    s.yawDegrees = glm::degrees(std::atan2(offset.x, offset.z));
    s.pitchDegrees = std::clamp(glm::degrees(std::asin(std::clamp(offset.y / distance, -1.0f, 1.0f))), -89.0f, 89.0f);
    // The roll that turns the orbit camera's up (+Y made perpendicular to the view) into
    // UP_VECTOR's, as OrbitCamera::view() applies it.
    const glm::vec3 forward = -offset / distance;
    const glm::vec3 plainUp = glm::vec3(0, 1, 0) - forward * forward.y;
    const glm::vec3 given = up - forward * glm::dot(up, forward);
    if (glm::length(plainUp) > 1e-4f && glm::length(given) > 1e-4f) {
        const glm::vec3 u = glm::normalize(plainUp), right = glm::cross(forward, u);
        s.rollDegrees = glm::degrees(std::atan2(glm::dot(given, right), glm::dot(given, u)));
        if (std::abs(s.rollDegrees) < 1e-3f) s.rollDegrees = 0.0f;
    } else if (glm::length(given) <= 1e-4f) {
        camera.warning("UP_VECTOR lies along the viewing direction: it says nothing of the roll, which stays 0");
    }
    if (auto fov = camera.number("FOV")) {
        if (*fov > 0 && *fov < 180) s.fovYDegrees = *fov;
        else camera.error("FOV " + std::to_string(*fov) + " is not an angle in (0, 180) degrees");
    }
    auto nearPlane = camera.number("NEAR_CLIP_PLANE"), farPlane = camera.number("FAR_CLIP_PLANE");
    if (nearPlane && farPlane) {
        if (*nearPlane > 0 && *farPlane > *nearPlane) {
            s.nearPlane = *nearPlane;
            s.farPlane = *farPlane;
        } else {
            camera.error("NEAR_CLIP_PLANE must be above 0 and below FAR_CLIP_PLANE");
        }
    }
    return s;
}

}  // namespace rmfx::rfx
