#include "editor/CameraControl.h"

#include <cmath>

#include <glm/vec4.hpp>
#include <gtest/gtest.h>

namespace rmfx::editor {
namespace {

OrbitCamera camera(CameraConvention convention = CameraConvention::OpenGL) {
    OrbitCameraSettings s;
    s.convention = convention;
    s.yawDegrees = 30.0f;
    s.pitchDegrees = 15.0f;
    s.distance = 4.0f;
    s.target = {0.2f, 0.1f, -0.3f};
    s.fovYDegrees = 50.0f;
    return OrbitCamera(s);
}

// Where a world point appears in a width × height window: pixels, x right, y down.
glm::vec2 windowPixel(const OrbitCamera& c, glm::vec3 point, glm::ivec2 size) {
    glm::vec4 clip = c.projection(float(size.x) / float(size.y)) * c.view() * glm::vec4(point, 1.0f);
    glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y};
}

}  // namespace

// In either convention (a Direct3D camera's picture is OpenGL's mirrored, so its yaw turns the
// other way), the drag turns the scene with the cursor and the pan keeps the point under it.
TEST(EditorCameraControl, DraggingRightTurnsTheSceneRightAndDownRaisesTheCamera) {
    for (const CameraConvention convention : {CameraConvention::OpenGL, CameraConvention::Direct3D}) {
        SCOPED_TRACE(convention == CameraConvention::OpenGL ? "OpenGL" : "Direct3D");
        OrbitCamera c = camera(convention);
        orbitByDrag(c, {100.0f, 20.0f});
        const float turn = (convention == CameraConvention::OpenGL ? -100.0f : 100.0f) * orbitDegreesPerPixel;
        EXPECT_NEAR(c.settings().yawDegrees, 30.0f + turn, 1e-4f);
        EXPECT_NEAR(c.settings().pitchDegrees, 15.0f + 20.0f * orbitDegreesPerPixel, 1e-4f);
        // The scene turned with the drag: the side of it that faced the camera moved right of centre.
        OrbitCamera before = camera(convention);
        glm::vec2 old = windowPixel(c, before.position() * 0.5f + before.settings().target * 0.5f, {400, 300});
        EXPECT_GT(old.x, 200.0f);
    }
}

TEST(EditorCameraControl, PanKeepsThePointUnderTheCursor) {
    for (const CameraConvention convention : {CameraConvention::OpenGL, CameraConvention::Direct3D}) {
        SCOPED_TRACE(convention == CameraConvention::OpenGL ? "OpenGL" : "Direct3D");
        const glm::ivec2 size(400, 300);
        OrbitCamera c = camera(convention);
        const glm::vec3 target = c.settings().target;
        EXPECT_NEAR(windowPixel(c, target, size).x, 200.0f, 1e-3f);
        const glm::vec2 drag(37.0f, -22.0f);
        panByDrag(c, drag, size.y);
        glm::vec2 now = windowPixel(c, target, size);
        EXPECT_NEAR(now.x, 200.0f + drag.x, 1e-2f);
        EXPECT_NEAR(now.y, 150.0f + drag.y, 1e-2f);
        EXPECT_EQ(c.settings().distance, 4.0f);
    }
}

TEST(EditorCameraControl, WheelForwardComesCloser) {
    OrbitCamera c = camera();
    zoomByWheel(c, 1.0f);
    EXPECT_NEAR(c.settings().distance, 4.0f * 0.9f, 1e-5f);
    zoomByWheel(c, -3.0f);
    EXPECT_NEAR(c.settings().distance, 4.0f * 0.9f / (0.9f * 0.9f * 0.9f), 1e-4f);
}

}  // namespace rmfx::editor
