// The chapter-8 streaks (effects/shader_3.xml, exercise_2.xml): every streak pass and the screen
// are compared with the float64 reference (tests/reference/StreakReference.h) run on the targets
// the GPU wrote, and a single light is shown to become streaks 4, then 16 texels long, running
// the way each target's name says.

#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "reference/StreakReference.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class StreakGLTest : public GlTest {};

constexpr int kSize = 128;
constexpr glm::ivec2 kQuarter{kSize / 4, kSize / 4};
constexpr double kGlowFactor = 0.005;            // the workspaces' default
const double kHalfUlp = std::ldexp(1.0, -10);    // an rgba16f step, relative (2^-11 each side)
constexpr double kRelativeFloor = 1e-4;          // keeps relative differences finite at 0

// streak_XY_N runs XY (down-left, ...) from a light; its filter samples the opposite way.
struct Direction {
    std::string name;
    glm::dvec2 sampled;
};
const std::array<Direction, 4> kDirections{{{"dl", {1, 1}}, {"dr", {-1, 1}}, {"ul", {1, -1}}, {"ur", {-1, -1}}}};

GlRun render(std::unique_ptr<Workspace> ws) { return runWorkspace(std::move(ws), {{kSize, kSize}, 1, 1.0f / 60.0f}); }

std::array<RefImage, 4> finalStreaks(const GlRun& run) {
    std::array<RefImage, 4> streaks;
    for (int k = 0; k < 4; ++k) streaks[k] = readRef(run, "streak_" + kDirections[k].name + "_16");
    return streaks;
}

// shader_3 on rgba16f. Each pass is computed from the target the GPU gave it. GL leaves the
// rounding of render-target writes to half to the driver (llvmpipe truncates: half the texels come
// out one step low, none high); the reference rounds to nearest, so the two differ by less than
// one step, 2^-10 relative. Sampling positions are texel centres or half-texels at 128x128, where
// bilinear weights are exact. Through the two passes from the scene: the first pass's step carried
// by sums of positive terms, plus a truncation and a rounding, 2.5 steps. The scene's alpha is 1,
// so the passes' alpha is the sum of the filter's weights, 3.77 then 3.77 x 3.18, whatever the
// reference.
TEST_F(StreakGLTest, Shader3PassesMatchTheReference) {
    GlRun run = render(effectWorkspace("shader_3.xml"));
    ASSERT_TRUE(run.exec);
    RefImage scene = readRef(run, "scene");
    ASSERT_EQ(scene.width, kSize);
    EXPECT_GT(maxColorChannel(scene), 30.0) << "no sun in the scene";
    double first = 0.0, second = 0.0;
    for (int i = 0; i < 4; ++i) {
        first += std::pow(kStreakBlurFactor, i);
        second += std::pow(kStreakBlurFactor, 4 * i);
    }
    for (const Direction& d : kDirections) {
        SCOPED_TRACE("streak_" + d.name);
        RefImage short4 = readRef(run, "streak_" + d.name + "_4");
        RefImage long16 = readRef(run, "streak_" + d.name + "_16");
        ASSERT_EQ(short4.width, kQuarter.x);
        RefImage expected4 = roundedToHalf(streakPass(scene, kQuarter.x, kQuarter.y, d.sampled, 1.0));
        RefImage expected16 = roundedToHalf(streakPass(short4, kQuarter.x, kQuarter.y, d.sampled, 4.0));
        expectWithin(d.name + "_4", maxRelativeDifference(short4, expected4, kRelativeFloor), kHalfUlp);
        expectWithin(d.name + "_16", maxRelativeDifference(long16, expected16, kRelativeFloor), kHalfUlp);
        auto chain = streakChain(scene, kQuarter, d.sampled, TargetRounding::Half);
        expectWithin(d.name + "_chain", maxRelativeDifference(long16, chain[1], kRelativeFloor), 2.5 * kHalfUlp);
        EXPECT_GT(maxColorChannel(long16), 30.0) << "the streaks carry no energy";
        for (size_t t = 0; t < short4.texels.size(); ++t) {
            ASSERT_NEAR(short4.texels[t].a, first, first * kHalfUlp);
            ASSERT_NEAR(long16.texels[t].a, first * second, 2.5 * first * second * kHalfUlp);
        }
    }
}

// The screen: the scene copied, then min(1, Σ (streak · Glow_Factor, 0.15)) added at alpha 0.6,
// from the streak targets the GPU wrote. Upsampling a quarter target samples at fractions k/8,
// exact in bilinear weights; one rounding to half. Whatever the reference says, the streaks add
// between 0 and 0.6 (alpha 0.6, colour clamped to 1), and near the sun a good part of it.
TEST_F(StreakGLTest, Shader3ScreenIsTheSceneWithTheStreaksAdded) {
    GlRun run = render(effectWorkspace("shader_3.xml"));
    ASSERT_TRUE(run.exec);
    RefImage scene = readRef(run, "scene");
    RefImage output = readRef(run, "output");
    RefImage combine = streakCombine(finalStreaks(run), kGlowFactor, kSize, kSize, false);
    RefImage expected = roundedToHalf(blendedAdditive(scene, combine));
    expectWithin("screen", maxRelativeDifference(output, expected, kRelativeFloor), kHalfUlp);
    double added = 0.0;
    for (size_t t = 0; t < scene.texels.size(); ++t)
        for (int c = 0; c < 3; ++c) {
            double d = output.texels[t][c] - scene.texels[t][c], slack = output.texels[t][c] * kHalfUlp;
            ASSERT_GE(d, -slack);
            ASSERT_LE(d, 0.6 + slack);
            added = std::max(added, d + slack);
        }
    EXPECT_GE(added, 0.3) << "the streaks add nothing visible";
}

// exercise 2 on rgba8. llvmpipe filters 8-bit textures in 8-bit arithmetic: a bilinear sample
// between texels comes back quantised to 1/255, so each of the first pass's half-texel samples
// may be one step off, and the pass differs by up to Σ weights + 1 = 4.77 steps; the second pass
// samples texel centres (no filtering): one step. From the scene, the first pass's 4.77 steps
// reach the second through weights summing to 3.18, plus its step: 16.2 steps. The streaks
// saturate 8 bits: rgb and alpha at the sun are 1, since the chapter's filter is not normalised.
TEST_F(StreakGLTest, Exercise2PassesMatchTheReference) {
    GlRun run = render(effectWorkspace("exercise_2.xml"));
    ASSERT_TRUE(run.exec);
    RefImage scene = readRef(run, "scene");
    ASSERT_EQ(scene.width, kSize);
    EXPECT_GT(maxColorChannel(decodedAlpha64(scene)), 30.0) << "no sun in the scene";
    const double firstSteps = 1.0 + 0.96 + 0.96 * 0.96 + 0.96 * 0.96 * 0.96 + 1.0;
    const double secondWeights = 1.0 + std::pow(0.96, 4) + std::pow(0.96, 8) + std::pow(0.96, 12);
    for (const Direction& d : kDirections) {
        SCOPED_TRACE("streak_" + d.name);
        RefImage short4 = readRef(run, "streak_" + d.name + "_4");
        RefImage long16 = readRef(run, "streak_" + d.name + "_16");
        RefImage expected4 = roundedToUnorm8(streakPass(scene, kQuarter.x, kQuarter.y, d.sampled, 1.0));
        RefImage expected16 = roundedToUnorm8(streakPass(short4, kQuarter.x, kQuarter.y, d.sampled, 4.0));
        expectWithin("a8_" + d.name + "_4", maxAbsDifference(short4, expected4), firstSteps * kUnorm8Step);
        expectWithin("a8_" + d.name + "_16", maxAbsDifference(long16, expected16), kUnorm8Step);
        auto chain = streakChain(scene, kQuarter, d.sampled, TargetRounding::Unorm8);
        expectWithin("a8_" + d.name + "_chain", maxAbsDifference(long16, chain[1]),
                     (secondWeights * firstSteps + 1.0) * kUnorm8Step);
        EXPECT_EQ(maxColorChannel(long16), 1.0);
        double alpha = 0.0;
        for (const glm::dvec4& t : long16.texels) alpha = std::max(alpha, t.a);
        EXPECT_EQ(alpha, 1.0) << "the sun's streak should saturate alpha";
    }
}

// The screen of exercise 2: the scene decoded to rgb · (a · 64) (one rounding to half, a step at
// most), then the decoded streaks added at alpha 0.6 (that step, a truncation and a rounding: 2.5). The upsampling samples of the 8-bit streaks may be
// one step off in rgb and in a (see above), which moves a decoded streak by up to
// 64 · (rgb + a + 1/255) / 255; times Glow_Factor and 0.6, summed over the four, per pixel.
TEST_F(StreakGLTest, Exercise2ScreenIsTheDecodedSceneWithTheStreaksAdded) {
    GlRun run = render(effectWorkspace("exercise_2.xml"));
    ASSERT_TRUE(run.exec);
    RefImage scene = readRef(run, "scene");
    RefImage output = readRef(run, "output");
    std::array<RefImage, 4> streaks = finalStreaks(run);
    RefImage combine = streakCombine(streaks, kGlowFactor, kSize, kSize, true);
    RefImage expected = roundedToHalf(blendedAdditive(roundedToHalf(decodedAlpha64(scene)), combine));
    RefImage slack = shadePixels(kSize, kSize, [&](glm::dvec2 uv) {
        double s = 0.0;
        for (const RefImage& streak : streaks) {
            glm::dvec4 t = sampleBilinear(streak, uv);
            s += 0.6 * kGlowFactor * 64.0 * (std::max({t.r, t.g, t.b}) + t.a + kUnorm8Step) * kUnorm8Step;
        }
        return glm::dvec4(s);
    });
    double worst = 0.0;
    for (size_t t = 0; t < output.texels.size(); ++t)
        for (int c = 0; c < 4; ++c) {
            double tolerance = 2.5 * kHalfUlp * std::abs(expected.texels[t][c]) + slack.texels[t][c] + kRelativeFloor;
            worst = std::max(worst, std::abs(output.texels[t][c] - expected.texels[t][c]) / tolerance);
        }
    expectWithin("a8_screen_fraction_of_tolerance", worst, 1.0);
    EXPECT_GT(maxColorChannel(output), 30.0);
}

// A light filling one texel of the 1/4 targets (a 4x4 block of the scene, so the first pass's
// half-texel samples see all of it or nothing) becomes texels light + k·step with weights 0.96^k,
// k < 4, after the first pass and k < 16 after the second; nothing else lights up. `step` is the
// direction the target's name gives, so the names and the sampling direction agree.
TEST_F(StreakGLTest, Shader3LightBecomesStreaksOf4Then16Texels) {
    auto ws = effectWorkspace("shader_3.xml");
    ASSERT_TRUE(ws);
    replaceSceneWithLight(*ws, "environment", {64, 64}, {68, 68});
    GlRun run = render(std::move(ws));
    ASSERT_TRUE(run.exec);
    const glm::ivec2 light(16, 16);
    for (const Direction& d : kDirections) {
        glm::ivec2 step(d.name[1] == 'l' ? -1 : 1, d.name[0] == 'd' ? -1 : 1);
        for (int length : {4, 16}) {
            SCOPED_TRACE("streak_" + d.name + "_" + std::to_string(length));
            RefImage streak = readRef(run, "streak_" + d.name + "_" + std::to_string(length));
            ASSERT_EQ(streak.width, kQuarter.x);
            int lit = 0;
            for (int y = 0; y < streak.height; ++y)
                for (int x = 0; x < streak.width; ++x) {
                    glm::ivec2 offset = glm::ivec2(x, y) - light;
                    int k = offset.x * step.x;
                    bool onStreak = offset == k * step && k >= 0 && k < length;
                    double expected = onStreak ? std::pow(kStreakBlurFactor, k) : 0.0;
                    for (int c = 0; c < 4; ++c)
                        ASSERT_NEAR(streak.at(x, y)[c], expected, 2 * kHalfUlp * expected) << x << "," << y;
                    lit += onStreak;
                }
            EXPECT_EQ(lit, length);
        }
    }
}

}  // namespace
}  // namespace rmfx::test
