// Hard cases of effects/auto_exposure.xml's half-size reduction chain: sizes 1x1, 3x5 and
// 1921x1081 with a single lit pixel in the last column, the last row or the corner. The chain
// (levels ceil(previous / 2), mean and pixel count per texel) must end in the exact mean
// brightness, 1 / (width · height) of the pixel's, and count every pixel: a chain that dropped the
// last row or column of a level would give 0.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reference/AutoExposureReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class AutoExposureHardCasesGLTest : public GlTest {};

constexpr double kUlp = 1.0 / (1 << 24);

// As AutoExposureGLTest's bound: brightness() 3 ulps, 12 ulps per reducing level.
double chainTolerance(glm::ivec2 size) {
    int reducing = static_cast<int>(chainSizes(size).size()) - (size == glm::ivec2(1) ? 1 : 0);
    return (3.0 + 12.0 * reducing) * kUlp;
}

TEST_F(AutoExposureHardCasesGLTest, SinglePixelInTheLastRowOrColumnIsCountedAtEverySize) {
    for (const EdgePixelCase& c : edgePixelCases()) {
        SCOPED_TRACE(c.name());
        auto ws = effectWorkspace("auto_exposure.xml");
        ASSERT_TRUE(ws);
        replaceSceneWithLight(*ws, "environment", c.pixel, c.pixel + 1);
        GlRun run = runWorkspace(std::move(ws), {c.size, 1, 1.0f / 60.0f});
        ASSERT_TRUE(run.exec);
        RefImage scene = readRef(run, "scene");
        ASSERT_EQ(scene.at(c.pixel.x, c.pixel.y).r, 1.0) << "the lit pixel";
        const double exact = meanBrightness(scene);
        ASSERT_NEAR(exact * c.size.x * c.size.y, 1.0, 1e-6) << "one pixel of brightness 1";
        Image last = readBack(*run.exec, "average_14");
        EXPECT_EQ(last.at(0, 0, 1), static_cast<float>(c.size.x * c.size.y)) << "every pixel counted";
        const double tolerance = chainTolerance(c.size) * exact;
        expectWithin("mean brightness error", std::fabs(last.at(0, 0, 0) - exact), tolerance);
        const double exposure = readBack(*run.exec, "exposure").at(0, 0, 0);
        EXPECT_TRUE(std::isfinite(exposure) && exposure > 0.0) << exposure;
        for (float v : readBack(*run.exec, "output").pixels) ASSERT_TRUE(std::isfinite(v));
    }
}

}  // namespace
}  // namespace rmfx::test
