// The chapter-8 glare family (effects/shader_2.xml, shader_6.xml, exercise_1.xml): every blur
// level and the screen are compared with the float64 reference (tests/reference/GlareReference.h)
// run on the scene target the GPU rendered, and the 49-sample chain of exercise 1 is shown to
// blur exactly as the 9-sample chain of shader_2 by feeding both an impulse.

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "reference/GlareReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

class GlareGLTest : public GlTest {};

// A small square size, where sampling positions fall on texel centres and half-texels, and an odd
// one, where the 1/4 targets round up (25x16) and bilinear weights are fractions of every kind.
const std::vector<glm::ivec2> kSizes{{128, 128}, {97, 61}};
constexpr int kSize = 128;  // the impulse and scene-encoding tests
const glm::dvec3 kGlowFactors(0.1, 0.1, 0.1);  // the workspaces' defaults
const double kHalfUlp = std::ldexp(1.0, -10);  // an rgba16f rounding step, relative (2^-11 each side)

GlRun renderEffect(std::unique_ptr<Workspace> ws, glm::ivec2 size = {kSize, kSize}) {
    return runWorkspace(std::move(ws), {size, 1, 1.0f / 60.0f});
}

std::string sizeName(glm::ivec2 size) { return std::to_string(size.x) + "x" + std::to_string(size.y); }

// A 1/4 target's size: ceil(viewport / 4), the format's rounding rule.
glm::ivec2 quarterOf(glm::ivec2 size) { return (size + 3) / 4; }

// Every value is a sum of positive terms, so relative errors do not grow through the chain; the
// floor only keeps the ratio finite where a channel is 0.
constexpr double kRelativeFloor = 1e-4;

// The scene must hold the sun (65 · Exposure_Level = 16 from the 8-bit environment at the default
// 0.25) and the compared level must carry its energy, or a comparison of two black images would pass.
void expectSunEnergy(const RefImage& scene, const RefImage& level, bool alpha64) {
    RefImage sceneHdr = alpha64 ? decodedAlpha64(scene) : scene;
    RefImage levelHdr = alpha64 ? decodedAlpha64(level) : level;
    EXPECT_GT(maxColorChannel(sceneHdr), 10.0) << "no sun in the scene";
    EXPECT_GT(maxColorChannel(levelHdr), 1.0) << "the blur level carries no energy";
}

// A half-float glare workspace: `passes` passes of `kernel` into targets prefix_1 .. prefix_n, the
// composite reading levels `combined` (1-based). Level k went through k roundings to half on the
// GPU and k in the reference; where they round to different sides the two differ by one half ulp
// (2^-10 relative), and averages with positive weights keep relative differences: level k within
// k · 2^-10, the screen one rounding more than its most rounded level. On top of that, what the
// context's bilinear filtering may add (blurChainFilteringBounds, from bilinearWeightError): about
// 1e-7 of a footprint's range on llvmpipe, which interpolates in float32, and up to 2^-9 of it on a
// GPU with 8 bits of subtexel precision at 97x61, where taps fall between texels at any fraction
// (at 128x128 they fall on texel centres and half-texels, which such a GPU weighs exactly).
void expectHalfFloatGlareMatchesTheReference(const std::string& effect, const std::vector<KernelTap>& kernel,
                                             int passes, const std::string& prefix, glm::ivec3 combined) {
    for (glm::ivec2 size : kSizes) {
        SCOPED_TRACE(effect + " at " + sizeName(size));
        GlRun run = renderEffect(effectWorkspace(effect + ".xml"), size);
        ASSERT_TRUE(run.exec);
        RefImage scene = readRef(run, "scene");
        ASSERT_EQ(scene.width, size.x);
        const glm::ivec2 quarter = quarterOf(size);
        std::vector<RefImage> expected = blurChain(scene, quarter, kernel, passes, TargetRounding::Half);
        std::vector<RefImage> filtering = blurChainFilteringBounds(scene, expected, quarter, kernel, bilinearWeightError());
        for (int k = 1; k <= passes; ++k) {
            RefImage level = readRef(run, prefix + std::to_string(k));
            expectWithin(prefix + std::to_string(k) + " error over its bound",
                         maxDifferenceOverBound(level, expected[k - 1], k * kHalfUlp, kRelativeFloor, filtering[k - 1]), 1.0);
        }
        expectSunEnergy(scene, expected[passes - 1], false);

        const int a = combined[0] - 1, b = combined[1] - 1, c = combined[2] - 1;
        RefImage screen = roundedToHalf(blendedAdditive(
            scene, glareCombine(expected[a], expected[b], expected[c], kGlowFactors, size.x, size.y, false)));
        RefImage screenFiltering = glareCombineFilteringBound(expected[a], expected[b], expected[c], filtering[a], filtering[b],
                                                              filtering[c], kGlowFactors, size.x, size.y, bilinearWeightError());
        RefImage output = readRef(run, "output");
        int screenRoundings = std::max({combined[0], combined[1], combined[2]}) + 1;
        expectWithin("screen error over its bound",
                     maxDifferenceOverBound(output, screen, screenRoundings * kHalfUlp, kRelativeFloor, screenFiltering, 3), 1.0);
        // The glare really is on the screen: near the sun it adds far more than the scene's half ulp.
        EXPECT_GT(maxAbsDifference(output, roundedToHalf(scene), 3), 0.1);
    }
}

// shader_2: six 9-sample passes, the composite reading passes 4, 5 and 6.
TEST_F(GlareGLTest, Shader2LevelsAndScreenMatchTheReference) {
    expectHalfFloatGlareMatchesTheReference("shader_2", gauss9Kernel(), 6, "glare_", {4, 5, 6});
}

// exercise 1: two 49-sample passes, the composite reading passes 1, 2 and 2.
TEST_F(GlareGLTest, Exercise1LevelsAndScreenMatchTheReference) {
    expectHalfFloatGlareMatchesTheReference("exercise_1", gauss49Kernel(), 2, "glare49_", {1, 2, 2});
}

// shader_6's screen, decode(scene) + Σ Glow_Factor_j · decode(level_j) rounded to half, from the
// given levels, where level j's channels may each be `steps[j]` 1/255 steps off: the largest
// |output − expected| over its bound. Decoding multiplies by 64 a, so a channel's bound is
// Σ_j Glow_Factor_j · 64 (δ_j a + rgb δ_j + δ_j²) + the half rounding of the screen.
double worstAlpha64ScreenError(const RefImage& output, const RefImage& scene, const std::vector<RefImage>& levels,
                               const std::vector<int>& steps) {
    int width = scene.width, height = scene.height;
    RefImage screen = roundedToHalf(blendedAdditive(
        decodedAlpha64(scene), glareCombine(levels[0], levels[1], levels[2], kGlowFactors, width, height, true)));
    double worst = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::dvec2 uv((x + 0.5) / width, (y + 0.5) / height);
            for (int c = 0; c < 3; ++c) {
                double bound = kHalfUlp * screen.at(x, y)[c] + 1e-6;
                for (int j = 0; j < 3; ++j) {
                    double delta = steps[j] * kUnorm8Step;
                    glm::dvec4 v = sampleBilinear(levels[j], uv);
                    bound += kGlowFactors[j] * 64.0 * (delta * v.a + v[c] * delta + delta * delta);
                }
                worst = std::max(worst, std::abs(output.at(x, y)[c] - screen.at(x, y)[c]) / bound);
            }
        }
    return worst;
}

// shader_6: the same passes on rgba8. A level rounded to 1/255 on both sides differs by at most
// one more step than its source did: level k within k/255 (the scene is the GPU's own).
TEST_F(GlareGLTest, Shader6LevelsAndScreenMatchTheReference) {
    for (glm::ivec2 size : kSizes) {
        SCOPED_TRACE(sizeName(size));
        GlRun run = renderEffect(effectWorkspace("shader_6.xml"), size);
        ASSERT_TRUE(run.exec);
        RefImage scene = readRef(run, "scene");
        ASSERT_EQ(scene.width, size.x);
        std::vector<RefImage> expected = blurChain(scene, quarterOf(size), gauss9Kernel(), 6, TargetRounding::Unorm8);
        std::vector<RefImage> levels;
        for (int k = 1; k <= 6; ++k) {
            levels.push_back(readRef(run, "glare_" + std::to_string(k)));
            EXPECT_LE(maxAbsDifference(levels.back(), expected[k - 1]), k * kUnorm8Step + 1e-6) << "glare_" << k;
        }
        expectSunEnergy(scene, expected[5], true);

        // llvmpipe's bilinear filtering of rgba8 textures is not exact to float precision (an
        // exact bound fails by 16 % relative after decoding): allow one 1/255 step per sample. Screen from the GPU's own levels:
        // that step on every level. From the reference levels: level k's k steps, plus that one.
        RefImage output = readRef(run, "output");
        EXPECT_LE(worstAlpha64ScreenError(output, scene, {levels[3], levels[4], levels[5]}, {1, 1, 1}), 1.0);
        EXPECT_LE(worstAlpha64ScreenError(output, scene, {expected[3], expected[4], expected[5]}, {5, 6, 7}), 1.0);
    }
}

// The 8-bit scene of shader_6 decodes to the half-float scene of shader_2 (same camera, same 8-bit
// environment) within the quantisation of the encoding: rgb to 1/255, the multiplier to 64/255
// (each within kUnorm8Conversion of a step: half of it where the conversion rounds to nearest, as
// llvmpipe's does, 0.6 on GPUs), plus the half rounding of shader_2's scene.
TEST_F(GlareGLTest, Shader6SceneDecodesToTheFloatSceneWithinItsQuantisation) {
    GlRun floatRun = renderEffect(effectWorkspace("shader_2.xml"));
    GlRun byteRun = renderEffect(effectWorkspace("shader_6.xml"));
    ASSERT_TRUE(floatRun.exec && byteRun.exec);
    RefImage hdr = readRef(floatRun, "scene");
    RefImage encoded = readRef(byteRun, "scene");
    ASSERT_EQ(encoded.width, hdr.width);
    RefImage decoded = decodedAlpha64(encoded);
    double worstRatio = 0.0;
    for (size_t i = 0; i < hdr.texels.size(); ++i) {
        const glm::dvec4& e = encoded.texels[i];
        double rgbStep = kUnorm8Conversion, multiplierStep = 64.0 * kUnorm8Conversion;
        for (int c = 0; c < 3; ++c) {
            double bound = rgbStep * e.a * 64.0 + e[c] * multiplierStep + rgbStep * multiplierStep +
                           kHalfUlp * hdr.texels[i][c] + 1e-6;
            worstRatio = std::max(worstRatio, std::abs(decoded.texels[i][c] - hdr.texels[i][c]) / bound);
        }
    }
    expectWithin("decoded scene error over its bound", worstRatio, 1.0);
    // The encoding keeps the sun: its multiplier (1 + 64 a) · 0.25 fits below 64.
    EXPECT_GT(maxColorChannel(decoded), 10.0);
}

// Both glare chains fed a single bright scene pixel instead of the scene. The first pass reads the
// scene at half-texels 4 pixels apart, so the impulse sits on scene pixel 4m + 1 where both
// kernels see it, at the centre of quarter pixel m. Three 3x3 binomial passes are one 7x7 binomial
// pass, so the six 9-sample passes (variance 6 × 0.5) and the two 49-sample ones (2 × 1.5) give
// the same 13x13 binomial: the same variance, 3 texel² per axis, and the same image.
std::unique_ptr<Workspace> withImpulseScene(std::unique_ptr<Workspace> ws) {
    if (!ws) return nullptr;
    std::erase_if(ws->passes, [](const Pass& p) { return p.name == "environment" || p.name == "teapot"; });
    Pass impulse;
    impulse.name = "impulse";
    impulse.target = "scene";
    impulse.draw.mesh = BuiltinMesh::FullscreenTriangle;
    ShaderSource fragment;
    fragment.stage = ShaderStage::Fragment;
    fragment.code = R"(
out vec4 fragColor;
void main() { fragColor = all(equal(ivec2(gl_FragCoord.xy), ivec2(65))) ? vec4(4096.0) : vec4(0.0); }
)";
    impulse.shaders.push_back(fragment);
    ws->passes.insert(ws->passes.begin(), impulse);
    return ws;
}

TEST_F(GlareGLTest, Exercise1BlursAsMuchAsShader2) {
    GlRun nine = renderEffect(withImpulseScene(effectWorkspace("shader_2.xml")));
    GlRun fortyNine = renderEffect(withImpulseScene(effectWorkspace("exercise_1.xml")));
    ASSERT_TRUE(nine.exec && fortyNine.exec);

    // Kernels that sum to 1 keep the energy: the impulse (4096) reaches the first level through
    // two half-weight bilinear taps per axis, 1024 in all, and every later pass keeps it.
    for (int k = 1; k <= 6; ++k) {
        ImageMoments m = imageMoments(readRef(nine, "glare_" + std::to_string(k)), 0);
        EXPECT_NEAR(m.total, 1024.0, 1024.0 * k * kHalfUlp) << "glare_" << k;
        EXPECT_NEAR(m.mean.x, 16.0, 1e-3) << "glare_" << k;
        EXPECT_NEAR(m.mean.y, 16.0, 1e-3) << "glare_" << k;
        EXPECT_NEAR(m.variance.x, 0.5 * k, 0.01) << "glare_" << k;
        EXPECT_NEAR(m.variance.y, 0.5 * k, 0.01) << "glare_" << k;
    }
    RefImage nine6 = readRef(nine, "glare_6"), nine3 = readRef(nine, "glare_3");
    RefImage forty1 = readRef(fortyNine, "glare49_1"), forty2 = readRef(fortyNine, "glare49_2");
    ImageMoments a = imageMoments(nine6, 0), b = imageMoments(forty2, 0);
    // Half rounding changes each value by 2^-11 relative: the variances agree far better than 0.01.
    EXPECT_NEAR(b.variance.x, 3.0, 0.01);
    EXPECT_NEAR(b.variance.y, 3.0, 0.01);
    EXPECT_NEAR(a.variance.x, b.variance.x, 0.01);
    EXPECT_NEAR(a.variance.y, b.variance.y, 0.01);
    EXPECT_NEAR(imageMoments(forty1, 0).variance.x, 1.5, 0.01);
    // Texel by texel: 6 (nine) and 2 (forty-nine) half roundings of positive sums.
    EXPECT_LE(maxRelativeDifference(forty2, nine6, 1e-3, 3), 8 * kHalfUlp);
    EXPECT_LE(maxRelativeDifference(forty1, nine3, 1e-3, 3), 4 * kHalfUlp);
    // Symmetric about the impulse.
    for (int y = 10; y <= 22; ++y)
        for (int x = 10; x <= 22; ++x)
            EXPECT_EQ(forty2.at(x, y).r, forty2.at(32 - x, 32 - y).r) << x << "," << y;
}

}  // namespace
}  // namespace rmfx::test
