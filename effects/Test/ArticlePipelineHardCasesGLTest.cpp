// Hard cases of effects/article_pipeline.xml's 1/4 downsample (one bilinear fetch per quarter
// pixel, SuppressLDR): sizes 1x1, 3x5 and 1921x1081 with a single bright pixel (100) in the last
// column, the last row or the corner. The quarter image must hold what the float64 model of the
// article's fetch gives (tests/reference/ArticleReference.h): the pixel's share where the fetch's
// footprint covers it, nothing where it does not (the article samples, it does not average), and
// every target must be finite.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reference/ArticleReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class ArticlePipelineHardCasesGLTest : public GlTest {};

constexpr double kPixel = 100.0;

TEST_F(ArticlePipelineHardCasesGLTest, SinglePixelAtTheEdgesReachesTheQuarterImageAsTheModelSays) {
    int reached = 0;
    // The large size once; (1919, 1079) is under the last quarter column's and row's fetch.
    for (const EdgePixelCase& c : edgePixelCases({1919, 1079})) {
        SCOPED_TRACE(c.name());
        auto ws = effectWorkspace("article_pipeline.xml");
        ASSERT_TRUE(ws);
        replaceSceneWithPattern(*ws, "scene", singlePixelPattern(c.pixel, kPixel));
        GlRun run = runWorkspace(std::move(ws), {c.size, 1, 1.0f / 60.0f});
        ASSERT_TRUE(run.exec);
        for (const char* name : {"scene", "downsampled", "blurX", "blurY", "output"})
            for (float v : readBack(*run.exec, name).pixels) ASSERT_TRUE(std::isfinite(v)) << name;
        RefImage scene = readRef(run, "scene"), quarter = readRef(run, "downsampled");
        ASSERT_EQ(quarter.width, (c.size.x + 3) / 4);
        ASSERT_EQ(quarter.height, (c.size.y + 3) / 4);
        RefImage ref = article::downsampleSuppressLdr(scene, quarter.width, quarter.height, glm::dvec3(1.0));
        // GL's bilinear weights have 8 fractional bits (2^-8 of the pixel), plus one half step.
        double got = 0.0, expected = 0.0;
        for (int y = 0; y < ref.height; ++y)
            for (int x = 0; x < ref.width; ++x) {
                const double e = ref.at(x, y).r, g = quarter.at(x, y).r;
                EXPECT_NEAR(g, e, std::ldexp(kPixel, -8) + std::ldexp(e, -10)) << x << "," << y;
                got += g;
                expected += e;
            }
        reached += expected > 0.0;
        std::printf("  %dx%d pixel %d,%d: quarter total %.6g, model %.6g\n", c.size.x, c.size.y, c.pixel.x, c.pixel.y,
                    got, expected);
    }
    EXPECT_GE(reached, 3) << "1x1, the 3x5 last row and the 1921x1081 corner put the pixel under a fetch";
}

}  // namespace
}  // namespace rmfx::test
