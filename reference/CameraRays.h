#pragma once
// The view ray of each pixel of a full-screen pass, in double, as the built-in full-screen vertex
// shader builds it: the far-plane point rm_InvViewProjection * (ndc, 1, 1) minus the camera
// position, from the workspace's orbit camera settings (independently of runtime/OrbitCamera).

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include "model/Workspace.h"

namespace rmfx::test {

class CameraRays {
public:
    CameraRays(const OrbitCameraSettings& camera, int width, int height) : width_(width), height_(height) {
        const double degrees = 3.14159265358979323846 / 180.0;
        double yaw = camera.yawDegrees * degrees, pitch = camera.pitchDegrees * degrees;
        glm::dvec3 target(camera.target);
        eye_ = target + double(camera.distance) *
                            glm::dvec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
        view_ = glm::lookAt(eye_, target, glm::dvec3(0, 1, 0));
        projection_ = glm::perspective(camera.fovYDegrees * degrees, double(width) / height,
                                       double(camera.nearPlane), double(camera.farPlane));
        invViewProjection_ = glm::inverse(projection_ * view_);
    }

    const glm::dmat4& view() const { return view_; }
    const glm::dmat4& projection() const { return projection_; }

    // Unit ray through the centre of pixel (x, y), y counted from the bottom.
    glm::dvec3 ray(int x, int y) const {
        glm::dvec2 ndc((x + 0.5) / width_ * 2.0 - 1.0, (y + 0.5) / height_ * 2.0 - 1.0);
        glm::dvec4 far = invViewProjection_ * glm::dvec4(ndc, 1.0, 1.0);
        return glm::normalize(glm::dvec3(far) / far.w - eye_);
    }

private:
    int width_, height_;
    glm::dvec3 eye_;
    glm::dmat4 view_, projection_, invViewProjection_;
};

}  // namespace rmfx::test
