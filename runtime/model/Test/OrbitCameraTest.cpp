#include "model/OrbitCamera.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>
#include <gtest/gtest.h>

namespace rmfx {
namespace {

OrbitCameraSettings settings(float yaw, float pitch, float distance, glm::vec3 target = glm::vec3(0.0f)) {
    OrbitCameraSettings s;
    s.yawDegrees = yaw;
    s.pitchDegrees = pitch;
    s.distance = distance;
    s.target = target;
    s.fovYDegrees = 60.0f;
    return s;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

}  // namespace

TEST(OrbitCamera, PositionIsOnTheSphereAroundTheTarget) {
    expectNear(OrbitCamera(settings(0, 0, 2)).position(), {0, 0, 2});  // yaw 0: on +Z
    expectNear(OrbitCamera(settings(90, 0, 2)).position(), {2, 0, 0});
    expectNear(OrbitCamera(settings(0, 30, 2, {1, 1, 1})).position(), {1, 1 + 2 * 0.5f, 1 + 2 * std::sqrt(3.0f) / 2});
}

// A roll turns the camera's up toward its right: the view equals glm::lookAt with that up, built
// here from the eye, the target and the roll by hand.
TEST(OrbitCamera, RollTurnsTheUpVectorAboutTheViewingDirection) {
    OrbitCameraSettings rolled = settings(0, 0, 2);
    rolled.rollDegrees = 90.0f;
    // On +Z looking down -Z, the right is +X: rolled 90°, up is +X and world +X is the view's up.
    glm::vec4 x = OrbitCamera(rolled).view() * glm::vec4(1, 0, 0, 0);
    expectNear(glm::vec3(x), {0, 1, 0});
    for (float roll : {-135.0f, -30.0f, 10.0f, 170.0f}) {
        OrbitCameraSettings s = settings(35, 20, 3, {0.5f, -1, 2});
        s.rollDegrees = roll;
        OrbitCamera camera(s);
        const glm::dvec3 eye = camera.position(), target = s.target;
        const glm::dvec3 forward = glm::normalize(target - eye);
        const glm::dvec3 up0 = glm::normalize(glm::dvec3(0, 1, 0) - forward * forward.y);
        const glm::dvec3 right = glm::cross(forward, up0);
        const double r = glm::radians(static_cast<double>(roll));
        const glm::dmat4 expected = glm::lookAt(eye, target, up0 * std::cos(r) + right * std::sin(r));
        const glm::mat4 actual = camera.view();
        for (int c = 0; c < 4; ++c)
            for (int row = 0; row < 4; ++row) EXPECT_NEAR(actual[c][row], expected[c][row], 1e-5) << roll << " " << c << "," << row;
    }
}

TEST(OrbitCamera, ViewLooksAtTheTarget) {
    OrbitCamera camera(settings(35, 20, 3, {0.5f, -1, 2}));
    glm::vec4 target = camera.view() * glm::vec4(0.5f, -1, 2, 1);
    expectNear(glm::vec3(target), {0, 0, -3});
}

TEST(OrbitCamera, OrbitAddsDegreesWrapsYawAndStopsPitchShortOfThePoles) {
    OrbitCamera camera(settings(350, 10, 2));
    camera.orbit(20, 50);
    EXPECT_NEAR(camera.settings().yawDegrees, 10.0f, 1e-4f);
    EXPECT_EQ(camera.settings().pitchDegrees, 60.0f);
    camera.orbit(0, 100);
    EXPECT_EQ(camera.settings().pitchDegrees, 89.0f);
    camera.orbit(0, -500);
    EXPECT_EQ(camera.settings().pitchDegrees, -89.0f);
    EXPECT_EQ(camera.settings().distance, 2.0f);
}

TEST(OrbitCamera, PanMovesTheTargetInTheViewPlaneByVisibleHeights) {
    // yaw 0, pitch 0: right is +X, up is +Y; the visible height at distance 2, fov 60° is 2·2·tan 30°.
    OrbitCamera camera(settings(0, 0, 2));
    const float height = 4.0f * std::tan(glm::radians(30.0f));
    camera.pan({0.5f, -0.25f});
    expectNear(camera.settings().target, {0.5f * height, -0.25f * height, 0});
    EXPECT_EQ(camera.settings().distance, 2.0f);
    EXPECT_EQ(camera.settings().yawDegrees, 0.0f);  // the camera moves with its target
    expectNear(camera.position() - camera.settings().target, {0, 0, 2});
}

TEST(OrbitCamera, ZoomScalesTheDistanceAndIgnoresNonsense) {
    OrbitCamera camera(settings(0, 0, 2));
    camera.zoom(0.5f);
    EXPECT_EQ(camera.settings().distance, 1.0f);
    camera.zoom(0.0f);
    camera.zoom(-2.0f);
    camera.zoom(std::numeric_limits<float>::quiet_NaN());
    camera.zoom(std::numeric_limits<float>::infinity());
    EXPECT_EQ(camera.settings().distance, 1.0f);
    camera.zoom(1e-9f);
    EXPECT_EQ(camera.settings().distance, 1e-3f);  // never reaches the target
}

}  // namespace rmfx
