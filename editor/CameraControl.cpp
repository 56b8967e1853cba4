#include "editor/CameraControl.h"

#include <cmath>

namespace rmfx::editor {

void orbitByDrag(OrbitCamera& camera, glm::vec2 deltaPixels) {
    // A Direct3D camera's picture is mirrored left to right: the yaw turns the other way so that
    // the model still follows the cursor.
    const float side = camera.settings().convention == CameraConvention::Direct3D ? 1.0f : -1.0f;
    camera.orbit(side * deltaPixels.x * orbitDegreesPerPixel, deltaPixels.y * orbitDegreesPerPixel);
}

void panByDrag(OrbitCamera& camera, glm::vec2 deltaPixels, int viewportHeight) {
    if (viewportHeight < 1) return;
    // OrbitCamera::pan moves the target by fractions of the visible height at the target; the
    // scene moves the other way, so the cursor keeps its point: x negated, y down is up negated.
    const float h = static_cast<float>(viewportHeight);
    camera.pan({-deltaPixels.x / h, deltaPixels.y / h});
}

void zoomByWheel(OrbitCamera& camera, float wheelSteps) { camera.zoom(std::pow(zoomFactorPerWheelStep, wheelSteps)); }

}  // namespace rmfx::editor
