// effects/auto_exposure.xml without GL: its reduction chain reaches 1x1 from every viewport rmfx
// accepts, and the float64 references behave as the chapter's definitions say.

#include <cmath>

#include <gtest/gtest.h>

#include "reference/AutoExposureReference.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

TEST(AutoExposureWorkspaceTest, ChainHalvesWithRoundingUpToOnePixelForEverySize) {
    Result<Workspace> loaded = loadWorkspace(sourceDir() / "effects" / "auto_exposure.xml");
    ASSERT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    EXPECT_TRUE(loaded.diagnostics().empty()) << formatAll(loaded.diagnostics());
    std::vector<const RenderTarget*> chain;
    for (int level = 1;; ++level) {
        const RenderTarget* t = nullptr;
        for (const auto& target : loaded->targets)
            if (target.name == "average_" + std::to_string(level)) t = &target;
        if (!t) break;
        chain.push_back(t);
    }
    ASSERT_EQ(chain.size(), 14u);
    // 16384 is the largest --size.
    for (glm::ivec2 viewport : {glm::ivec2(1, 1), glm::ivec2(97, 61), glm::ivec2(4096, 4096), glm::ivec2(4097, 3),
                                glm::ivec2(16384, 16384), glm::ivec2(16383, 1), glm::ivec2(1, 12289)}) {
        glm::ivec2 previous = viewport;
        for (const RenderTarget* t : chain) {
            glm::ivec2 size = resolveTargetSize(t->size, viewport);
            EXPECT_EQ(size, (previous + 1) / 2) << t->name << " at " << viewport.x << "x" << viewport.y;
            previous = size;
        }
        EXPECT_EQ(previous, glm::ivec2(1)) << viewport.x << "x" << viewport.y;
    }
}

TEST(AutoExposureWorkspaceTest, ReferenceChainLevelsKeepTheMean) {
    RefImage scene(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) scene.at(x, y) = glm::dvec4(x + 1.0, 2.0 * y, -1.0, 1.0);
    scene.at(4, 2) = glm::dvec4(std::nan(""), 1e9, 3.0, 1.0);  // NaN → 0, 1e9 → 65504
    double sum = 0.0;
    for (const auto& t : scene.texels) sum += sanitisedBrightness(glm::dvec3(t));
    EXPECT_DOUBLE_EQ(meanBrightness(scene), sum / 15.0);
    EXPECT_DOUBLE_EQ(sanitisedBrightness({std::nan(""), 1e9, 3.0}), 0.7152 * 65504.0 + 0.0722 * 3.0);
    for (int level = 1; level <= 3; ++level) {
        RefImage l = brightnessLevel(scene, level);
        double weighted = 0.0, count = 0.0;
        for (const auto& t : l.texels) weighted += t.r * t.g, count += t.g;
        EXPECT_EQ(count, 15.0);
        EXPECT_NEAR(weighted / count, meanBrightness(scene), 1e-12 * meanBrightness(scene));
    }
    EXPECT_EQ(chainSizes({5, 3}), (std::vector<glm::ivec2>{{3, 2}, {2, 1}, {1, 1}}));
    // The naive chain sees only the 4x2 block at the bottom-left (5 → 2 → 1, 3 → 1).
    RefImage block(4, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) block.at(x, y) = scene.at(x, y);
    EXPECT_DOUBLE_EQ(naiveChainMean(scene), meanBrightness(block));
}

TEST(AutoExposureWorkspaceTest, ReferenceRecurrenceHasTheClosedForm) {
    // e_N = t + (e_0 − t)(1 − s)^N
    for (int n : {0, 1, 2, 10, 60})
        EXPECT_NEAR(exposureAfterFrames(3.0, 0.25, 0.05, n), 0.25 + 2.75 * std::pow(0.95, n), 1e-14) << n;
    EXPECT_EQ(targetExposure(0.0, 1e-4), 5000.0);
    EXPECT_EQ(targetExposure(2.0, 1e-4), 0.25);
}

}  // namespace
}  // namespace rmfx::test
