// effects/article_pipeline.xml against its float64 twin (tests/reference/ArticleReference.h), pass
// by pass: each reference runs on what the GPU wrote into that pass's inputs, so every pass is
// checked on its own and errors do not pile up. Targets are rgba16f.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "reference/ArticleReference.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class ArticlePipelineGLTest : public GlTest {};

constexpr int kSize = 128, kQuarter = 32;

struct ArticleRun {
    GlRun run;
    RefImage scene, downsampled, blurX, blurY, output;
};

ArticleRun renderArticle(const Overrides& overrides = {}) {
    ArticleRun r;
    r.run = runWorkspace(effectWorkspace("article_pipeline.xml", overrides), {{kSize, kSize}, 1, 1.0f / 60.0f});
    if (!r.run.exec) return r;
    r.scene = fromImage(readBack(*r.run.exec, "scene"));
    r.downsampled = fromImage(readBack(*r.run.exec, "downsampled"));
    r.blurX = fromImage(readBack(*r.run.exec, "blurX"));
    r.blurY = fromImage(readBack(*r.run.exec, "blurY"));
    r.output = fromImage(readBack(*r.run.exec, "output"));
    return r;
}

// One half-float step (2^-10 relative: llvmpipe truncates float -> half writes) of the result.
double halfStep(double v) { return std::ldexp(std::fabs(v), -10); }

TEST_F(ArticlePipelineGLTest, DownsampleKeepsOnlyHdrValues) {
    ArticleRun r = renderArticle();
    ASSERT_TRUE(r.run.exec);
    ASSERT_EQ(r.downsampled.width, kQuarter);
    RefImage ref = article::downsampleSuppressLdr(r.scene, kQuarter, kQuarter, glm::dvec3(1.0));
    int kept = 0, ambiguous = 0;
    for (int y = 0; y < kQuarter; ++y)
        for (int x = 0; x < kQuarter; ++x) {
            glm::dvec4 e = ref.at(x, y), g = r.downsampled.at(x, y);
            // The 1.0 threshold decides between all and nothing: where the reference's brightest
            // channel lies within GL's bilinear weight precision (2^-8 of the neighbours' spread,
            // bounded here by 1 %) of 1, either answer is right.
            glm::dvec4 unsuppressed = sampleBilinear(r.scene, {(x + 0.5) / kQuarter, (y + 0.5) / kQuarter});
            double peak = std::max({unsuppressed.r, unsuppressed.g, unsuppressed.b});
            if (std::fabs(peak - 1.0) < 0.01) {
                ++ambiguous;
                continue;
            }
            if (peak > 1.0) ++kept;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(g[c], e[c], halfStep(e[c]) + std::ldexp(std::fabs(e[c]), -8)) << x << "," << y << " c" << c;
        }
    EXPECT_GT(kept, 4) << "the sun and its halo exceed 1";
    EXPECT_LT(kept, kQuarter * kQuarter / 2) << "most of the sky is below 1 and suppressed";
    EXPECT_LT(ambiguous, kQuarter * kQuarter / 20);
}

// Each blur output is a weighted sum of 17 exact texel fetches (nearest filtering): the only error
// is float accumulation and the half-float write, one step of the sum of |terms|.
void expectBlurMatches(const RefImage& input, const RefImage& gl, int dx, int dy) {
    RefImage ref = article::blur17(input, dx, dy);  // inputs are ≥ 0, so this is also the sum of |terms|
    double worst = 0.0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x)
            for (int c = 0; c < 3; ++c) {
                double tolerance = halfStep(ref.at(x, y)[c]) + 1e-7;
                worst = std::max(worst, std::fabs(gl.at(x, y)[c] - ref.at(x, y)[c]) / tolerance);
            }
    EXPECT_LE(worst, 1.0) << "error in units of the tolerance";
}

TEST_F(ArticlePipelineGLTest, BlursAreTheBinomialKernelAlongEachAxis) {
    ArticleRun r = renderArticle();
    ASSERT_TRUE(r.run.exec);
    double energy = 0.0;
    for (const glm::dvec4& t : r.blurY.texels) energy += t.r;
    ASSERT_GT(energy, 10.0) << "the blurred highlights carry energy";
    expectBlurMatches(r.downsampled, r.blurX, 1, 0);
    expectBlurMatches(r.blurX, r.blurY, 0, 1);
}

TEST(ArticleReference, BlurWeightsAreTheBinomialRowAndSumToOne) {
    double sum = 0.0;
    for (int i = -8; i <= 8; ++i) sum += article::blurWeight(i);
    EXPECT_DOUBLE_EQ(sum, 1.0);
    EXPECT_DOUBLE_EQ(article::blurWeight(0), 12870.0 / 65536.0);
    EXPECT_DOUBLE_EQ(article::blurWeight(-8), 1.0 / 65536.0);
    EXPECT_EQ(article::blurWeight(9), 0.0);
}

// The article's four exposures, each through --set-style overrides.
TEST_F(ArticlePipelineGLTest, ToneMapMatchesAtTheArticlesFourExposures) {
    for (double exposure : {0.5, 2.5, 10.0, 20.0}) {
        SCOPED_TRACE(exposure);
        ArticleRun r = renderArticle({{"fExposureLevel", glslFloat(exposure)}});
        ASSERT_TRUE(r.run.exec);
        double worst = 0.0, brightest = 0.0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                glm::dvec2 uv((x + 0.5) / kSize, (y + 0.5) / kSize);
                glm::dvec3 original(r.scene.at(x, y));
                // The blurred target is magnified 4x bilinearly: allow 2^-8 of its local spread
                // (weight precision), and one half step of the original; both pass through ^0.55.
                glm::dvec3 blur(sampleBilinear(r.blurY, uv));
                glm::dvec3 lo(1e300), hi(0.0);
                for (int j = -1; j <= 1; ++j)
                    for (int i = -1; i <= 1; ++i) {
                        glm::dvec3 n(sampleBilinear(r.blurY, uv + glm::dvec2(i, j) / double(kQuarter)));
                        lo = glm::min(lo, n);
                        hi = glm::max(hi, n);
                    }
                glm::dvec3 ref = article::toneMap(original, blur, uv, exposure);
                for (int c = 0; c < 3; ++c) {
                    glm::dvec3 blurSlack(0.0), originalSlack(0.0);
                    blurSlack[c] = (hi[c] - lo[c]) / 256.0;
                    originalSlack[c] = halfStep(original[c]);
                    glm::dvec3 up = article::toneMap(original + originalSlack, blur + blurSlack, uv, exposure);
                    double tolerance = std::fabs(up[c] - ref[c]) + halfStep(ref[c]) + 1e-6;
                    worst = std::max(worst, std::fabs(r.output.at(x, y)[c] - ref[c]) / tolerance);
                    brightest = std::max(brightest, ref[c]);
                }
            }
        EXPECT_LE(worst, 1.0) << "error in units of the tolerance";
        EXPECT_GT(brightest, 1.0) << "the highlights exceed the display range";
    }
}

}  // namespace
}  // namespace rmfx::test
