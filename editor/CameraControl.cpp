#include "editor/CameraControl.h"

#include <cmath>

namespace rmfx::editor {

void orbitByDrag(OrbitCamera& camera, glm::vec2 deltaPixels) {
    camera.orbit(-deltaPixels.x * orbitDegreesPerPixel, deltaPixels.y * orbitDegreesPerPixel);
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
