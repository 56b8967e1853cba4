// effects/auto_exposure.xml: the 1x1 end of the reduction chain is the exact mean brightness of
// the scene at any viewport size, and the exposure follows the chapter's per-frame lerp towards
// 0.5 / average, compared with float64 references (tests/reference/AutoExposureReference.h)
// computed from the scene target the GPU rendered.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "reference/AutoExposureReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

class AutoExposureGLTest : public GlTest {};

constexpr int kLevels = 14;  // average_1 .. average_14 in the workspace
const std::string kLast = "average_" + std::to_string(kLevels);
constexpr double kUlp = 1.0 / (1 << 24);  // float32 relative rounding (half an ulp is 2^-24)

std::unique_ptr<Workspace> loadAutoExposure(const std::vector<std::pair<std::string, std::string>>& overrides = {}) {
    Result<Workspace> loaded = loadWorkspace(sourceDir() / "effects" / "auto_exposure.xml");
    EXPECT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    if (!loaded) return nullptr;
    Result<void> set = applyOverrides(*loaded, overrides);
    EXPECT_TRUE(set.diagnostics().empty()) << formatAll(set.diagnostics());
    return std::make_unique<Workspace>(std::move(*loaded));
}

float floatVariable(const Workspace& ws, const std::string& name) {
    for (const auto& v : ws.variables)
        if (v.name == name) return v.value.asFloat();
    ADD_FAILURE() << "no variable " << name;
    return 0.0f;
}

// Relative error bound of the rgba32f chain's mean: brightness() is 3 products and 2 sums of
// positive terms (3 ulps); each level that reduces (ceil(log2(max extent)) of them) forms
// count/total (GLSL division: 2.5 ulps), the products and up to 3 sums of positive terms, with
// weights that sum to 1 within 4 ulps: 12 ulps a level. Levels past 1x1 copy their texel exactly
// (weight count/count = 1).
double chainTolerance(glm::ivec2 size) {
    int reducing = static_cast<int>(chainSizes(size).size()) - (size == glm::ivec2(1) ? 1 : 0);
    return (3.0 + 12.0 * reducing) * kUlp;
}

double readExposure(const GlExecutor& exec) {
    Image e = readBack(exec, "exposure");
    return e.pixels.empty() ? std::numeric_limits<double>::quiet_NaN() : e.at(0, 0, 0);
}

void renderFrames(GlExecutor& exec, int frames, float dt = 1.0f / 60.0f) {
    for (int i = 0; i < frames; ++i) {
        int index = exec.frameIndex();
        Diagnostics d = exec.renderFrame({static_cast<float>(index) * dt, dt}).takeDiagnostics();
        ASSERT_TRUE(d.empty()) << formatAll(d);
    }
}

TEST_F(AutoExposureGLTest, LastLevelIsTheExactMeanBrightnessAtAnySize) {
    // On sizes that are not powers of two a naive floor(size / 2) chain drops the last row or
    // column of some level (65x129: the top row and right column of the scene at the first level).
    for (glm::ivec2 size : {glm::ivec2(128, 128), glm::ivec2(97, 61), glm::ivec2(1, 1), glm::ivec2(3, 5),
                            glm::ivec2(255, 1), glm::ivec2(65, 129)}) {
        SCOPED_TRACE("size " + std::to_string(size.x) + "x" + std::to_string(size.y));
        GlRun run = runWorkspace(loadAutoExposure(), {size, 1});
        ASSERT_TRUE(run.exec);
        RefImage scene = fromImage(readBack(*run.exec, "scene"));
        ASSERT_EQ(scene.width, size.x);
        ASSERT_EQ(scene.height, size.y);

        // Every level is ceil(previous / 2); the last one is 1x1 with all the scene's pixels counted.
        std::vector<glm::ivec2> sizes = chainSizes(size);
        for (int level = 1; level <= kLevels; ++level) {
            glm::ivec2 expected = level <= static_cast<int>(sizes.size()) ? sizes[level - 1] : glm::ivec2(1);
            EXPECT_EQ(run.exec->targetSize("average_" + std::to_string(level)), expected) << "level " << level;
        }
        Image last = readBack(*run.exec, kLast);
        ASSERT_EQ(last.width, 1);
        ASSERT_EQ(last.height, 1);
        EXPECT_EQ(last.at(0, 0, 1), static_cast<float>(size.x * size.y)) << "pixel count";

        double exact = meanBrightness(scene);
        ASSERT_GT(exact, 0.01) << "the scene carries light";
        double tolerance = chainTolerance(size);
        EXPECT_NEAR(last.at(0, 0, 0), exact, tolerance * exact);
        std::printf("  %dx%d: mean %.9g, GL %.9g, relative error %.3g, tolerance %.3g\n", size.x, size.y, exact,
                    last.at(0, 0, 0), std::abs(last.at(0, 0, 0) - exact) / exact, tolerance);

        // The first two levels, texel by texel: footprint means and exact counts.
        for (int level = 1; level <= 2; ++level) {
            RefImage expected = brightnessLevel(scene, level);
            RefImage got = fromImage(readBack(*run.exec, "average_" + std::to_string(level)));
            ASSERT_EQ(got.width, expected.width);
            ASSERT_EQ(got.height, expected.height);
            for (size_t i = 0; i < got.texels.size(); ++i) {
                EXPECT_NEAR(got.texels[i].r, expected.texels[i].r, (3.0 + 12.0 * level) * kUlp * expected.texels[i].r)
                    << "level " << level << " texel " << i;
                EXPECT_EQ(got.texels[i].g, expected.texels[i].g) << "level " << level << " texel " << i;
            }
        }

        // A naive chain gives a visibly different answer there (measured: 3.5 % at 65x129, 76 % at
        // 97x61), so the test can fail.
        if (size.x * size.y > 1 && (size.x & (size.x - 1) || size.y & (size.y - 1))) {
            double naive = naiveChainMean(scene);
            EXPECT_GT(std::abs(naive - exact), 100.0 * tolerance * exact) << "naive " << naive << ", exact " << exact;
        }
    }
}

TEST_F(AutoExposureGLTest, TheSunIsInViewAndBright) {
    GlRun run = runWorkspace(loadAutoExposure(), {{128, 128}, 1});
    ASSERT_TRUE(run.exec);
    RefImage scene = fromImage(readBack(*run.exec, "scene"));
    double brightest = 0.0;
    for (const auto& t : scene.texels) brightest = std::max(brightest, sanitisedBrightness(glm::dvec3(t)));
    // The sun (about 2000 in the half-float sky, up to 65 × 255/255 in the 8-bit one) is in view.
    EXPECT_GT(brightest, 30.0);
}

TEST_F(AutoExposureGLTest, ExposureFollowsTheChaptersLerpFromTheInitialValue) {
    auto ws = loadAutoExposure({{"Initial_Exposure", "2"}, {"Exposure_Adjust_Speed", "0.08"}});
    ASSERT_TRUE(ws);
    const double initial = floatVariable(*ws, "Initial_Exposure");
    const double speed = floatVariable(*ws, "Exposure_Adjust_Speed");  // the float the shader gets
    const double floor = floatVariable(*ws, "Minimum_Average_Brightness");
    GlRun run = runWorkspace(std::move(ws), {{64, 64}, 1});
    ASSERT_TRUE(run.exec);
    const double average = meanBrightness(fromImage(readBack(*run.exec, "scene")));
    const double target = targetExposure(average, floor);
    const glm::ivec2 size(64, 64);
    int rendered = 1;
    for (int frames : {1, 2, 10, 60}) {
        renderFrames(*run.exec, frames - rendered);
        rendered = frames;
        double expected = exposureAfterFrames(initial, target, speed, frames);
        double got = readExposure(*run.exec);
        // r32f: the target carries the chain's error and 2.5 ulps of division; each mix() adds
        // about 3 ulps of max(e, target), and earlier errors shrink by (1 − speed) a frame.
        double tolerance = (chainTolerance(size) + (2.5 + 3.0 * frames) * kUlp) * std::max(initial, target);
        EXPECT_NEAR(got, expected, tolerance) << frames << " frames";
        // It moved, and is not yet at the target: the comparison can tell the frames apart.
        EXPECT_GT(std::abs(got - initial), 100 * tolerance);
        EXPECT_GT(std::abs(got - target), 100 * tolerance);
        std::printf("  %d frames: exposure %.9g, expected %.9g (target %.9g), error %.3g, tolerance %.3g\n", frames,
                    got, expected, target, std::abs(got - expected), tolerance);
    }
}

TEST_F(AutoExposureGLTest, SceneChangeMovesTheExposureMonotonicallyTowardsTheNewTarget) {
    auto ws = loadAutoExposure({{"Exposure_Adjust_Speed", "0.2"}});
    ASSERT_TRUE(ws);
    const double speed = floatVariable(*ws, "Exposure_Adjust_Speed");
    GlRun run = runWorkspace(std::move(ws), {{48, 48}, 1});
    ASSERT_TRUE(run.exec);
    const double average = meanBrightness(fromImage(readBack(*run.exec, "scene")));
    renderFrames(*run.exec, 80);  // 0.8^80 ≈ 2e-8 of the initial distance is left
    double e = readExposure(*run.exec);
    EXPECT_NEAR(e, 0.5 / average, 1e-4 * e) << "settled before the change";

    // Exposure_Level scales the scene by a power of two, exactly in half floats, so the average and
    // the target scale by exactly that: the exposure must fall (×4) or rise (×1/4) frame by frame,
    // never passing the new target.
    for (float level : {4.0f, 0.25f}) {
        SCOPED_TRACE("Exposure_Level " + std::to_string(level));
        ASSERT_EQ(run.exec->setVariable("Exposure_Level", Value::ofFloat(level)).error(), "");
        const double target = 0.5 / (average * level);
        const double direction = target < e ? -1.0 : 1.0;
        for (int frame = 0; frame < 30; ++frame) {
            renderFrames(*run.exec, 1);
            double next = readExposure(*run.exec);
            EXPECT_GT(direction * (next - e), 0.0) << "frame " << frame << ": " << e << " -> " << next;
            EXPECT_GT(direction * (target - next), -1e-5 * target) << "frame " << frame << " passed the target";
            // The step is the lerp's: (target − e)·speed.
            EXPECT_NEAR(next - e, (target - e) * speed, 1e-4 * std::abs(target - e) + 1e-5 * target);
            e = next;
        }
        EXPECT_NEAR(e, target, 0.01 * target) << "most of the way after 30 frames (1 − 0.8^30)";
    }
}

TEST_F(AutoExposureGLTest, BlackOrInvalidSceneGivesAFiniteExposure) {
    auto ws = loadAutoExposure({{"Exposure_Level", "0"}, {"Exposure_Adjust_Speed", "0.5"}});
    ASSERT_TRUE(ws);
    const double floor = floatVariable(*ws, "Minimum_Average_Brightness");
    const double speed = floatVariable(*ws, "Exposure_Adjust_Speed");
    const double initial = floatVariable(*ws, "Initial_Exposure");
    GlRun run = runWorkspace(std::move(ws), {{32, 32}, 1});
    ASSERT_TRUE(run.exec);
    RefImage scene = fromImage(readBack(*run.exec, "scene"));
    EXPECT_EQ(meanBrightness(scene), 0.0) << "the scene is black";
    EXPECT_EQ(readBack(*run.exec, kLast).at(0, 0, 0), 0.0f);
    renderFrames(*run.exec, 9);
    double e = readExposure(*run.exec);
    ASSERT_TRUE(std::isfinite(e));
    double expected = exposureAfterFrames(initial, targetExposure(0.0, floor), speed, 10);
    EXPECT_NEAR(e, expected, 40 * kUlp * expected) << "moves towards 0.5 / Minimum_Average_Brightness";

    // NaN and +Inf in the scene (an exposure of NaN or Inf) are sanitised before averaging: NaN
    // and negative channels count as 0, Inf as 65504, as the CPU reference does.
    for (float level : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        SCOPED_TRACE("Exposure_Level " + std::to_string(level));
        ASSERT_EQ(run.exec->setVariable("Exposure_Level", Value::ofFloat(level)).error(), "");
        renderFrames(*run.exec, 3);
        RefImage bad = fromImage(readBack(*run.exec, "scene"));
        double average = meanBrightness(bad);
        float got = readBack(*run.exec, kLast).at(0, 0, 0);
        EXPECT_NEAR(got, average, chainTolerance({32, 32}) * average + 1e-30);
        double exposure = readExposure(*run.exec);
        EXPECT_TRUE(std::isfinite(exposure)) << exposure;
        EXPECT_GT(exposure, 0.0);
    }
}

}  // namespace
}  // namespace rmfx::test
