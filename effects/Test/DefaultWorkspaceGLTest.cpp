// The built-in default workspace (effects/default.xml) renders, and its sky matches a CPU port of
// skyRadiance seen through the workspace's camera, exposed and tone mapped as the tonemap pass does.

#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include "reference/CameraRays.h"
#include "tests/support/GlTestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

class DefaultWorkspaceGLTest : public GlTest {};

constexpr int kSize = 128;

// skyRadiance from effects/default.xml, in double, with the workspace's defaults.
glm::dvec3 skyRadiance(glm::dvec3 d, double* cosAngleOut = nullptr) {
    const glm::dvec3 sunDirection(-0.35, 0.12, -0.93);
    const double sunIntensity = 2000;
    glm::dvec3 sun = glm::normalize(sunDirection);
    if (d.y < 0.0) return glm::dvec3(0.2, 0.17, 0.14) * (1.0 + d.y);
    glm::dvec3 zenith(0.1, 0.25, 0.9), horizon(0.9, 1.1, 1.5);
    glm::dvec3 sky = glm::mix(horizon, zenith, std::pow(d.y, 0.5));
    double cosAngle = glm::dot(d, sun);
    if (cosAngleOut) *cosAngleOut = cosAngle;
    sky += glm::dvec3(1.0, 0.8, 0.5) * std::pow(std::max(cosAngle, 0.0), 64.0) * 4.0;
    if (cosAngle > 0.9995) sky += glm::dvec3(1.0, 0.95, 0.85) * sunIntensity;
    return sky;
}

// <camera target="0 0 0" distance="3.2" yaw="35" pitch="12" fov="50"/>, near 0.05, far 100.
CameraRays workspaceCamera() {
    OrbitCameraSettings camera;
    camera.target = glm::vec3(0.0f);
    camera.distance = 3.2f;
    camera.yawDegrees = 35.0f;
    camera.pitchDegrees = 12.0f;
    camera.fovYDegrees = 50.0f;
    return CameraRays(camera, kSize, kSize);
}

// The tonemap pass: max(c, 0) × exposure, then Reinhard c / (1 + c).
glm::dvec3 toneMapped(glm::dvec3 radiance, double exposure = 0.8) {
    glm::dvec3 c = glm::max(radiance, 0.0) * exposure;
    return c / (1.0 + c);
}

GlRun renderDefault(const std::vector<std::pair<std::string, std::string>>& overrides = {}) {
    Result<Workspace> loaded = loadDefaultWorkspace();
    if (!loaded) {
        ADD_FAILURE() << formatAll(loaded.diagnostics());
        return {};
    }
    auto ws = std::make_unique<Workspace>(std::move(*loaded));
    Result<void> set = applyOverrides(*ws, overrides);
    if (!set) {
        ADD_FAILURE() << formatAll(set.diagnostics());
        return {};
    }
    return runWorkspace(std::move(ws), {{kSize, kSize}, 1, 1.0f / 60.0f});
}

TEST_F(DefaultWorkspaceGLTest, RendersWithoutErrors) {
    GlRun run = renderDefault();
    ASSERT_TRUE(run.exec);
    EXPECT_FALSE(hasErrors(run.diagnostics)) << formatAll(run.diagnostics);
    EXPECT_EQ(run.ws->outputTargetName(), "output");
    Image out = readBack(*run.exec, "output");
    EXPECT_EQ(out.width, kSize);
    EXPECT_EQ(out.height, kSize);
    EXPECT_EQ(out.channels, 4);
    for (float v : out.pixels) ASSERT_TRUE(std::isfinite(v));
}

TEST_F(DefaultWorkspaceGLTest, TopCornersShowTheSkyFunction) {
    GlRun run = renderDefault();
    ASSERT_TRUE(run.exec);
    Image out = readBack(*run.exec, "output");
    ASSERT_EQ(out.width, kSize);
    CameraRays camera = workspaceCamera();
    for (int x : {0, kSize - 1}) {
        SCOPED_TRACE("corner x=" + std::to_string(x));
        int y = kSize - 1;  // the top row
        glm::dvec3 d = camera.ray(x, y);
        ASSERT_GT(d.y, 0.05) << "the corner should see the sky above the horizon";
        double cosAngle = 0;
        glm::dvec3 expected = toneMapped(skyRadiance(d, &cosAngle));
        ASSERT_GT(std::abs(cosAngle - 0.9995), 1e-4) << "too close to the sun's edge to compare";
        // rgba16f twice (hdr, then the output): half precision, 1e-3 relative, for each rounding.
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(atGl(out, x, y, c), expected[c], 2e-3 * expected[c] + 1e-4) << "channel " << c;
        EXPECT_EQ(atGl(out, x, y, 3), 1.0f);
    }
}

TEST_F(DefaultWorkspaceGLTest, TheTeapotCoversTheCentre) {
    GlRun run = renderDefault();
    ASSERT_TRUE(run.exec);
    Image out = readBack(*run.exec, "output");
    ASSERT_EQ(out.width, kSize);
    CameraRays camera = workspaceCamera();
    int x = kSize / 2, y = kSize / 2;
    glm::dvec3 sky = toneMapped(skyRadiance(camera.ray(x, y)));
    double difference = 0;
    for (int c = 0; c < 3; ++c) difference = std::max(difference, std::abs(atGl(out, x, y, c) - sky[c]));
    EXPECT_GT(difference, 0.02) << "the centre pixel shows the sky, not the teapot";
}

TEST_F(DefaultWorkspaceGLTest, ZeroExposureIsBlack) {
    GlRun run = renderDefault({{"Exposure_Level", "0"}});
    ASSERT_TRUE(run.exec);
    Image out = readBack(*run.exec, "output");
    ASSERT_EQ(out.width, kSize);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            for (int c = 0; c < 3; ++c) ASSERT_EQ(out.at(x, y, c), 0.0f) << x << "," << y << " channel " << c;
            ASSERT_EQ(out.at(x, y, 3), 1.0f) << x << "," << y;
        }
}

}  // namespace
}  // namespace rmfx::test
