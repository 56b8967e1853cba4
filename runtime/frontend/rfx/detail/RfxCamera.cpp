#include "frontend/rfx/detail/RfxCamera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "model/OrbitCamera.h"

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
    std::optional<OrbitCameraSettings> looking = orbitLookingAt(position, lookAt, up, s);
    if (!looking) {
        camera.error("the camera position and its look-at point are the same: it looks nowhere");
        return s;
    }
    s = *looking;
    if (glm::length(up - glm::normalize(position - lookAt) * glm::dot(up, glm::normalize(position - lookAt))) <= 1e-4f)
        camera.warning("UP_VECTOR lies along the viewing direction: it says nothing of the roll, which stays 0");
    // RenderMonkey's viewer stored whatever angle its zoom reached, past 180 degrees too, and D3DX
    // used it as it was: cot(FOV / 2) < 0 turns the picture 180 degrees, at 360 - FOV. 180 (a
    // scale of 0) and 360 (an infinite one) draw nothing.
    if (auto fov = camera.number("FOV")) {
        if (*fov > 0 && *fov < 360 && *fov != 180) s.fovYDegrees = *fov;
        else camera.error("FOV " + std::to_string(*fov) + " is not an angle in (0, 360) degrees other than 180");
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
