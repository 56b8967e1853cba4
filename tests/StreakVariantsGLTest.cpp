// The streak stage workspace (effects/variants/streak.xml): every pass count against the float64
// reference of the same discrete algorithm (tests/reference/GlareVariantsReference.h) with rgba32f
// targets, and every target format against the rgba32f render within its quantisation.

#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "tests/GlareStageRun.h"

namespace rmfx::test {
namespace {

class StreakVariantsGLTest : public GlTest {};

constexpr int kFactor = 4;  // scale="1/4"
const int kPassCounts[] = {2, 3, 4};

std::string effectName(int passes) { return "streak_" + std::to_string(passes) + "pass"; }

// Streak_Length 0.5 at 128 texels: per reduced step the weight is exp(-1/16), so the 4^4 = 256
// texels of streak_4pass span far more than the 32-texel image and the 16 of streak_2pass cut it.
TEST_F(StreakVariantsGLTest, EveryPassCountMatchesTheFloat64ReferenceWithRgba32fTargets) {
    constexpr int size = 128;
    RefImage input = syntheticInput(size, size);
    StreakSettings settings;
    settings.length = 0.5;
    for (int passes : kPassCounts) {
        std::string name = effectName(passes);
        SCOPED_TRACE(name);
        StageImages expected = streakStage(input, passes, settings, kFactor);
        GlRun run = renderStage("streak.xml", input, name, {{"Streak_Length", "0.5"}, {"Target_Format", "0"}});
        ASSERT_TRUE(run.exec);
        double worst = 0.0;
        for (int d = 0; d < 4; ++d) {
            double peak = maxColorChannel(expected.blurred[d]);
            ASSERT_GT(peak, 0.1);
            worst = std::max(worst, maxRgbDifference(readRef(run, "streak_" + std::to_string(d + 1)), expected.blurred[d]) / peak);
        }
        double resultError = maxRgbDifference(readRef(run, "result"), expected.result) / maxColorChannel(expected.result);
        std::printf("%-13s streaks %.3g  result %.3g (relative to the peak)\n", name.c_str(), worst, resultError);
        // Measured at most 2.1e-6 (the float32 exp of the decay weights) and 2.8e-8.
        expectWithin(name + " streaks", worst, 1e-5);
        expectWithin(name + " result", resultError, 1e-6);
    }
    // The pass counts differ where the streaks reach beyond 16 reduced texels: the comparison
    // tells them apart.
    EXPECT_GT(maxRgbDifference(streakStage(input, 2, settings, kFactor).result, streakStage(input, 4, settings, kFactor).result), 0.01);
}

// As for bloom: every pass averages with non-negative weights summing to at most 1, so the result
// of format F is within Streak_Strength * (passes + 1) * quantisation(F, max down) of the rgba32f
// one, plus the composite's shader bilinear (encoded formats) against the hardware's (rgba32f).
// Each format compiles every shader anew on llvmpipe, so the formats are checked on the default.
TEST_F(StreakVariantsGLTest, EveryFormatStaysWithinItsQuantisationOfTheRgba32fResult) {
    constexpr int size = 64;
    constexpr double kFilterTolerance = 1e-5;  // measured: llvmpipe filters float32 finely (BloomVariantsGLTest)
    RefImage input = syntheticInput(size, size);
    for (int passes : {3}) {
        std::string name = effectName(passes);
        GlRun reference = renderStage("streak.xml", input, name, {{"Target_Format", "0"}});
        ASSERT_TRUE(reference.exec);
        RefImage expected = readRef(reference, "result");
        double peak = maxColorChannel(readRef(reference, "down"));
        std::printf("%-13s", name.c_str());
        for (int format = 1; format <= 5; ++format) {
            SCOPED_TRACE(name + " Target_Format " + std::to_string(format));
            GlRun run = renderStage("streak.xml", input, name, {{"Target_Format", std::to_string(format)}});
            ASSERT_TRUE(run.exec);
            RefImage result = readRef(run, "result");
            ASSERT_TRUE(allFinite(result));
            double bound = 0.5 * ((passes + 1) * quantisation(format, peak) + kFilterTolerance * peak);
            double error = maxRgbDifference(result, expected);
            std::printf("  %d: %.3g of %.3g", format, error, bound);
            expectWithin(name + " format " + std::to_string(format), error, bound);
        }
        std::printf("\n");
    }
}

}  // namespace
}  // namespace rmfx::test
