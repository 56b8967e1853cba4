// The streak stage workspace (effects/variants/streak.xml): every pass count against the float64
// reference of the same discrete algorithm (tests/reference/GlareVariantsReference.h) with rgba32f
// targets, and every target format against the rgba32f render within its quantisation.

#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "effects/Test/GlareStageRun.h"

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

// The bright pass and P passes write each value of a streak. Each format compiles every shader anew
// on llvmpipe, so the formats are checked on the default, streak_3pass; the filter tolerance is
// the one BloomVariantsGLTest measures (llvmpipe filters float textures in float32).
TEST_F(StreakVariantsGLTest, EveryFormatStaysWithinItsQuantisationOfTheRgba32fResult) {
    expectFormatsWithinQuantisation("streak.xml", syntheticInput(64, 64), effectName(3), {}, 3 + 1, 0.5, 1e-5);
}

}  // namespace
}  // namespace rmfx::test
