// samples/tour/tour.xml, the example in docs/workspace-example.md that uses every element: it
// validates, renders several frames, and its cube-map sky pass matches the analytic sky the
// cross image was made from (cross layout, face orientation and view rays together).

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "samples/SampleMedia.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

class TourWorkspaceGLTest : public GlTest {};

std::unique_ptr<Workspace> loadTour(const ScratchDir& scratch) {
    for (const char* name : {"tour.xml", "floor.frag", "downsample.frag", "adapt.frag"})
        std::filesystem::copy_file(sourceDir() / "samples" / "tour" / name, scratch / name);
    auto media = samples::writeTourMedia(scratch.path());
    EXPECT_TRUE(media) << (media ? "" : media.error());
    Result<Workspace> loaded = loadWorkspace(scratch / "tour.xml");
    EXPECT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    if (!loaded) return nullptr;
    EXPECT_TRUE(loaded.diagnostics().empty()) << formatAll(loaded.diagnostics());
    return std::make_unique<Workspace>(std::move(*loaded));
}

TEST_F(TourWorkspaceGLTest, SkyPassMatchesTheAnalyticSkyOfTheCrossImage) {
    ScratchDir scratch;
    auto ws = loadTour(scratch);
    ASSERT_TRUE(ws);
    GlRun run = runWorkspace(std::move(ws), {{64, 64}, 3, 1.0f / 30.0f});
    ASSERT_TRUE(run.exec);
    Image scene = readBack(*run.exec, "scene");
    ASSERT_EQ(scene.width, 64);

    // <camera target="0 0.2 0" distance="3" yaw="20" pitch="10" fov="45" near="0.1" far="50"/>
    const double pi = 3.14159265358979323846, yaw = 20 * pi / 180, pitch = 10 * pi / 180;
    glm::dvec3 target(0, 0.2, 0);
    glm::dvec3 eye = target + 3.0 * glm::dvec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                                               std::cos(yaw) * std::cos(pitch));
    glm::dmat4 inverse = glm::inverse(glm::perspective(45 * pi / 180, 1.0, 0.1, 50.0) *
                                      glm::lookAt(eye, target, glm::dvec3(0, 1, 0)));
    glm::vec3 sun = glm::normalize(glm::vec3(-0.35f, 0.12f, -0.93f));
    int checked = 0;
    // The top rows see only sky (the teapot and the floor lie lower); stay away from the sun's glow,
    // where a 32-pixel cube face cannot resolve the gradient.
    for (int y = 56; y < 64; ++y)
        for (int x = 0; x < 64; x += 2) {
            glm::dvec2 ndc((x + 0.5) / 32.0 - 1.0, (y + 0.5) / 32.0 - 1.0);
            glm::dvec4 far = inverse * glm::dvec4(ndc, 1.0, 1.0);
            glm::vec3 ray(glm::normalize(glm::dvec3(far) / far.w - eye));
            if (glm::dot(ray, sun) > 0.95) continue;
            glm::vec3 expected = samples::analyticSky(ray, sun, 2000.0f);
            for (int c = 0; c < 3; ++c) {
                // Bilinear filtering of a 32-texel face over a smooth gradient, then rgba16f storage.
                EXPECT_NEAR(atGl(scene, x, y, c), expected[c], 0.03 * expected[c] + 2e-3)
                    << "pixel " << x << "," << y << " channel " << c;
            }
            ++checked;
        }
    EXPECT_GT(checked, 40);

    // Every pass ran: the output holds finite, non-black values and the 1x1 history adapted away
    // from its initial 1.
    Image output = readBack(*run.exec, "output");
    double sum = 0;
    for (float v : output.pixels) {
        ASSERT_TRUE(std::isfinite(v));
        sum += v;
    }
    EXPECT_GT(sum, 0.0);
    Image history = readBack(*run.exec, "history");
    EXPECT_TRUE(std::isfinite(history.pixels[0]));
    EXPECT_NE(history.pixels[0], 1.0f);
}

}  // namespace
}  // namespace rmfx::test
