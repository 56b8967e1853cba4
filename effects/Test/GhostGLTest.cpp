// The chapter-8 ghosts (effects/shader_4.xml): both ghost passes and the screen are compared with
// the float64 reference (tests/reference/GhostReference.h) run on the targets the GPU wrote, the
// passes are shown to be point-symmetric about the centre (the scales come in ± pairs), and a
// single light is shown to make ghosts where the scales put them.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "io/image/ImageIO.h"
#include "reference/GhostReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class GhostGLTest : public GlTest {};

constexpr int kSize = 128;
constexpr glm::ivec2 kQuarter{kSize / 4, kSize / 4};
constexpr double kGlowFactor = 0.2;            // the workspace's default
const double kHalfUlp = std::ldexp(1.0, -10);  // an rgba16f step, relative (2^-11 each side)
constexpr double kRelativeFloor = 1e-4;        // keeps relative differences finite at 0

GlRun render(std::unique_ptr<Workspace> ws) { return runWorkspace(std::move(ws), {{kSize, kSize}, 1, 1.0f / 60.0f}); }

// The mask the workspace reads (written by the build).
RefImage ghostMask() {
    auto image = readImage(sourceDir() / "samples" / "media" / "ghost_mask.png");
    if (!image) ADD_FAILURE() << image.error();
    return image ? fromImage(*image) : RefImage();
}

// What texture filtering may add to a ghost pass beyond the rounding of its result. GL leaves
// filtering precision to the implementation: llvmpipe blends float textures in float32 (far finer
// than a half step; the glare tests rely on it too) but 8-bit textures in 8-bit arithmetic, so a
// mask value between texels of different alpha may come back one step (1/255) off. Per pixel,
// through Glow_Factor · Σ_s source · mask. A GPU with coarse subtexel precision (8 bits on an
// H200) also puts each filtered value up to twice its weight error (bilinearWeightError) times
// the range of the texels it blends away from the float64 one, in the source and in the mask.
RefImage filterSlack(const RefImage& source, const RefImage& mask) {
    const double weightError = filteringAllowance(1);  // per unit of the range blended
    return shadePixels(kQuarter.x, kQuarter.y, [&](glm::dvec2 uv) {
        glm::dvec4 slack(0.0);
        for (double s : kGhostScales) {
            glm::dvec2 c = (uv - 0.5) * s + 0.5;
            const glm::dvec4 maskRange = bilinearFootprintRange(mask, c);
            const glm::dvec4 value = sampleBilinear(source, c);
            if (maskRange.a > 0.0) slack += value / 255.0;
            slack += weightError * (bilinearFootprintRange(source, c) + value * maskRange.a);
        }
        return slack * kGlowFactor;
    });
}

// Largest |gl − expected| as a fraction of its tolerance: `steps` half steps (2^-10 relative) plus
// the filtering slack. GL leaves the rounding to half to the driver (llvmpipe truncates) and the
// reference rounds to nearest: a pass's result differs by less than one step.
double worstFraction(const RefImage& gl, const RefImage& expected, const RefImage& slack, double steps) {
    double worst = 0.0;
    for (size_t t = 0; t < gl.texels.size(); ++t)
        for (int c = 0; c < 4; ++c) {
            double e = expected.texels[t][c];
            double tolerance = steps * kHalfUlp * std::abs(e) + slack.texels[t][c] + kRelativeFloor;
            worst = std::max(worst, std::abs(gl.texels[t][c] - e) / tolerance);
        }
    return worst;
}

TEST_F(GhostGLTest, Shader4PassesMatchTheReference) {
    GlRun run = render(effectWorkspace("shader_4.xml"));
    ASSERT_TRUE(run.exec);
    RefImage mask = ghostMask();
    ASSERT_EQ(mask.width, 128);
    RefImage scene = readRef(run, "scene");
    RefImage ghost1 = readRef(run, "ghost_1");
    RefImage ghost2 = readRef(run, "ghost_2");
    ASSERT_EQ(ghost1.width, kQuarter.x);
    EXPECT_GT(maxColorChannel(scene), 30.0) << "no sun in the scene";
    RefImage expected1 = roundedToHalf(ghostPass(scene, mask, kQuarter.x, kQuarter.y, kGlowFactor));
    RefImage expected2 = roundedToHalf(ghostPass(ghost1, mask, kQuarter.x, kQuarter.y, kGlowFactor));
    RefImage slack1 = filterSlack(scene, mask), slack2 = filterSlack(ghost1, mask);
    expectWithin("ghost_1", worstFraction(ghost1, expected1, slack1, 1), 1.0);
    expectWithin("ghost_2", worstFraction(ghost2, expected2, slack2, 1), 1.0);
    // From the scene: the first pass's tolerance reaches the second through the same positive,
    // linear pass (a ghost pass of the tolerance image), then its own filtering, a truncation on
    // the GPU and a rounding in the reference (1.5 steps).
    auto chain = ghostChain(scene, mask, kQuarter, kGlowFactor, TargetRounding::Half);
    RefImage tolerance1 = slack1;
    for (size_t t = 0; t < tolerance1.texels.size(); ++t) tolerance1.texels[t] += kHalfUlp * chain[0].texels[t];
    RefImage chainSlack = ghostPass(tolerance1, mask, kQuarter.x, kQuarter.y, kGlowFactor);
    for (size_t t = 0; t < chainSlack.texels.size(); ++t) chainSlack.texels[t] += slack2.texels[t];
    expectWithin("ghost_chain", worstFraction(ghost2, chain[1], chainSlack, 1.5), 1.0);
    EXPECT_GT(maxColorChannel(ghost1), 1.0) << "the ghosts carry no energy";
    EXPECT_GT(maxColorChannel(ghost2), 0.1) << "the ghosts of ghosts carry no energy";
}

// The scales come in pairs ±s, and c_−s(uv) = c_s(1 − uv): whatever the source, a ghost pass is
// point-symmetric about the centre. The GPU evaluates the two pixels of a pair with different
// interpolated coordinates, so they may differ by the filtering slack of both and a rounding step.
TEST_F(GhostGLTest, Shader4PassesArePointSymmetric) {
    GlRun run = render(effectWorkspace("shader_4.xml"));
    ASSERT_TRUE(run.exec);
    RefImage mask = ghostMask();
    RefImage scene = readRef(run, "scene");
    RefImage ghost1 = readRef(run, "ghost_1");
    const std::pair<std::string, const RefImage&> passes[] = {{"ghost_1", scene}, {"ghost_2", ghost1}};
    for (const auto& [name, source] : passes) {
        RefImage ghost = readRef(run, name);
        RefImage slack = filterSlack(source, mask);
        RefImage rotated = ghost;
        for (int y = 0; y < ghost.height; ++y)
            for (int x = 0; x < ghost.width; ++x) {
                rotated.at(x, y) = ghost.at(ghost.width - 1 - x, ghost.height - 1 - y);
                slack.at(x, y) += slack.at(ghost.width - 1 - x, ghost.height - 1 - y);
            }
        expectWithin(name + "_symmetry", worstFraction(ghost, rotated, slack, 1), 1.0);
    }
}

// The screen: the scene copied, then the ghosts at alpha 0.8. Upsampling the quarter target
// samples at fractions k/8, exact in bilinear weights; one rounding to half.
TEST_F(GhostGLTest, Shader4ScreenIsTheSceneWithTheGhostsAdded) {
    GlRun run = render(effectWorkspace("shader_4.xml"));
    ASSERT_TRUE(run.exec);
    RefImage scene = readRef(run, "scene");
    RefImage output = readRef(run, "output");
    RefImage composite = ghostComposite(readRef(run, "ghost_2"), kSize, kSize);
    RefImage expected = roundedToHalf(blendedAdditive(scene, composite));
    expectWithin("ghost_screen", maxRelativeDifference(output, expected, kRelativeFloor), kHalfUlp);
    double added = 0.0;
    for (size_t t = 0; t < scene.texels.size(); ++t) added = std::max(added, output.texels[t].r - scene.texels[t].r);
    EXPECT_GT(added, 0.05) << "the ghosts add nothing visible";
}

// A light of 8x8 scene pixels (2x2 texels of the 1/4 targets), inside the mask's opaque disc:
// the first pass draws it where each scale puts it, 0.5 + (light − 0.5) / s, and the second where
// each product of two scales does; ghosts that land outside the target (the products ±0.36) and
// the clamped borders add nothing. Checked on the GPU's targets alone, without the reference.
TEST_F(GhostGLTest, Shader4LightMakesGhostsWhereTheScalesPutThem) {
    auto ws = effectWorkspace("shader_4.xml");
    ASSERT_TRUE(ws);
    replaceSceneWithLight(*ws, "environment", {88, 72}, {96, 80});
    GlRun run = render(std::move(ws));
    ASSERT_TRUE(run.exec);
    const glm::dvec2 light(92.0 / kSize, 76.0 / kSize);
    for (int passes : {1, 2}) {
        SCOPED_TRACE("ghost_" + std::to_string(passes));
        RefImage ghost = readRef(run, "ghost_" + std::to_string(passes));
        ASSERT_EQ(ghost.width, kQuarter.x);
        // Predicted centres in texel indices (texel i's centre is at (i + 0.5) / 32).
        std::vector<glm::dvec2> centres, inside;
        for (glm::dvec2 q : ghostPositions(light, passes)) {
            glm::dvec2 c = q * glm::dvec2(kQuarter) - 0.5;
            centres.push_back(c);
            if (q.x > 0 && q.x < 1 && q.y > 0 && q.y < 1) inside.push_back(c);
        }
        EXPECT_EQ(inside.size(), passes == 1 ? 4u : 12u);
        double peak = maxColorChannel(ghost);
        ASSERT_GT(peak, passes == 1 ? 0.1 : 0.01) << "no ghosts";
        const double lit = 1e-3 * peak;
        for (int y = 0; y < ghost.height; ++y)
            for (int x = 0; x < ghost.width; ++x) {
                if (ghost.at(x, y).r <= lit) continue;
                double nearest = 1e9;
                for (glm::dvec2 c : centres) nearest = std::min(nearest, glm::distance(glm::dvec2(x, y), c));
                ASSERT_LE(nearest, 3.0) << "texel " << x << "," << y << " lit far from every ghost";
            }
        for (glm::dvec2 c : inside) {
            // Each ghost is there: its light's energy-weighted centre, within 3 texels, lies on the
            // prediction where ghosts do not overlap (the first pass), and it is lit near it.
            glm::dvec2 sum(0.0);
            double energy = 0.0, near = 0.0;
            for (int y = 0; y < ghost.height; ++y)
                for (int x = 0; x < ghost.width; ++x) {
                    double d = glm::distance(glm::dvec2(x, y), c), r = ghost.at(x, y).r;
                    if (d <= 1.5) near = std::max(near, r);
                    if (d > 3.0) continue;
                    sum += r * glm::dvec2(x, y);
                    energy += r;
                }
            EXPECT_GT(near, 0.05 * peak) << "no ghost near " << c.x << "," << c.y;
            if (passes == 1) {
                ASSERT_GT(energy, 0.0);
                EXPECT_LE(glm::distance(sum / energy, c), 0.5) << "ghost at " << c.x << "," << c.y;
            }
        }
    }
}

}  // namespace
}  // namespace rmfx::test
