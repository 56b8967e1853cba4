// The chapter-8 composite of all the effects (effects/shader_5.xml): each effect's targets are
// bit for bit those of its own workspace (shader_2, shader_3, shader_4) at the same settings, the
// screen is compared with the float64 composite of the chapter's shader_5 formula
// (tests/reference/CombinedReference.h) run on the targets the GPU wrote, and with the streak and
// ghost factors at 0 the screen is shader_2's.

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reference/CombinedReference.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class CombinedGLTest : public GlTest {};

constexpr int kSize = 128;
const double kHalfUlp = std::ldexp(1.0, -10);  // an rgba16f step, relative (2^-11 each side)
constexpr double kRelativeFloor = 1e-4;        // keeps relative differences finite at 0

// shader_5's defaults, which the single-effect workspaces get too.
constexpr double kExposure = 0.25;
const glm::dvec3 kGlowFactors(0.05, 0.05, 0.05);
constexpr double kStreakFactor = 0.01;
constexpr double kGhostFactor = 0.3;

const std::array<std::string, 4> kStreaks{"streak_dl_16", "streak_dr_16", "streak_ul_16", "streak_ur_16"};

GlRun render(const std::string& file, const Overrides& overrides = {}) {
    return runWorkspace(effectWorkspace(file, overrides), {{kSize, kSize}, 1, 1.0f / 60.0f});
}

std::string exposure() { return glslFloat(kExposure); }

// The same shaders on the same inputs give the same bits: every target of one effect, and the scene.
void expectSameTargets(const GlRun& combined, const GlRun& single, const std::vector<std::string>& targets) {
    for (const std::string& target : targets) {
        RefImage a = readRef(combined, target), b = readRef(single, target);
        ASSERT_EQ(a.width, b.width) << target;
        expectWithin(target + "_identical", maxAbsDifference(a, b), 0.0);
    }
}

TEST_F(CombinedGLTest, EachEffectsTargetsAreThoseOfItsOwnWorkspace) {
    GlRun all = render("shader_5.xml");
    ASSERT_TRUE(all.exec);
    EXPECT_GT(maxColorChannel(readRef(all, "scene")), 10.0) << "no sun in the scene";

    GlRun glare = render("shader_2.xml", {{"Exposure_Level", exposure()}});
    ASSERT_TRUE(glare.exec);
    expectSameTargets(all, glare, {"scene", "glare_1", "glare_2", "glare_3", "glare_4", "glare_5", "glare_6"});

    GlRun streak = render("shader_3.xml", {{"Exposure_Level", exposure()}});
    ASSERT_TRUE(streak.exec);
    std::vector<std::string> streaks;
    for (const char* d : {"dl", "dr", "ul", "ur"})
        for (const char* n : {"_4", "_16"}) streaks.push_back(std::string("streak_") + d + n);
    expectSameTargets(all, streak, streaks);

    // shader_4's Glow_Factor is shader_5's Ghost_Factor.
    GlRun ghost = render("shader_4.xml", {{"Exposure_Level", exposure()}, {"Glow_Factor", glslFloat(kGhostFactor)}});
    ASSERT_TRUE(ghost.exec);
    expectSameTargets(all, ghost, {"ghost_1", "ghost_2"});
}

// The screen: the scene copied, then the chapter's composite (alpha 1) added. Upsampling the
// quarter targets samples at fractions k/8, exact in bilinear weights, and float32 sums of eight
// terms are far finer than half; the one rounding to half (llvmpipe truncates, the reference
// rounds to nearest) leaves one step, 2^-10 relative. Each term must be visible on the screen.
TEST_F(CombinedGLTest, ScreenIsTheSceneWithTheChaptersCompositeAdded) {
    GlRun run = render("shader_5.xml");
    ASSERT_TRUE(run.exec);
    RefImage scene = readRef(run, "scene");
    RefImage output = readRef(run, "output");
    std::array<RefImage, 4> streaks;
    for (int k = 0; k < 4; ++k) streaks[k] = readRef(run, kStreaks[k]);
    CombinedTerms terms = allCombineTerms(readRef(run, "ghost_2"),
                                          {readRef(run, "glare_4"), readRef(run, "glare_5"), readRef(run, "glare_6")},
                                          kGlowFactors, streaks, kStreakFactor, kSize, kSize);
    RefImage expected = roundedToHalf(blendedAdditive(scene, allCombine(terms)));
    expectWithin("screen", maxRelativeDifference(output, expected, kRelativeFloor), kHalfUlp);
    EXPECT_GT(maxColorChannel(terms.glare), 0.5) << "the glare adds nothing visible";
    EXPECT_GT(maxColorChannel(terms.streaks), 0.5) << "the streaks add nothing visible";
    EXPECT_GT(maxColorChannel(terms.ghosts), 0.5) << "the ghosts add nothing visible";
}

// With the streaks and the ghosts weighted 0, only the glare is added: shader_2's screen at the
// same settings (the ghost passes write 0, and adding 0 changes no float; within one half step).
TEST_F(CombinedGLTest, WithoutStreaksAndGhostsTheScreenIsShader2s) {
    Overrides glare{{"Exposure_Level", exposure()},
                    {"Glow_Factor", glslFloat(kGlowFactors[0])},
                    {"Glow_Factor2", glslFloat(kGlowFactors[1])},
                    {"Glow_Factor3", glslFloat(kGlowFactors[2])}};
    Overrides glareOnly = glare;
    glareOnly.push_back({"Streak_Factor", "0"});
    glareOnly.push_back({"Ghost_Factor", "0"});
    GlRun all = render("shader_5.xml", glareOnly);
    GlRun shader2 = render("shader_2.xml", glare);
    ASSERT_TRUE(all.exec && shader2.exec);
    EXPECT_EQ(maxColorChannel(readRef(all, "ghost_2")), 0.0);
    RefImage output = readRef(all, "output"), expected = readRef(shader2, "output");
    expectWithin("glare_only_screen", maxRelativeDifference(output, expected, kRelativeFloor), kHalfUlp);
    EXPECT_GT(maxAbsDifference(output, readRef(all, "scene"), 3), 0.1) << "the glare adds nothing visible";
}

}  // namespace
}  // namespace rmfx::test
