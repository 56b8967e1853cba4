// Hard cases of the luminance stage (effects/variants/luminance.xml), for every variant: each
// asserts a finite result within a stated bound of the float64 model of that variant (the ideal
// for `exact`; tests/reference/LuminanceVariantsReference.h). Variables at their defaults:
// delta 1e-4, sampled64 at 1/4 in rgba16f, histogram 64 bins over log2 Y in [-16, 16], 0..100 %.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "effects/Test/StageTestSupport.h"
#include "reference/LuminanceVariantsReference.h"
#include "reference/StageInput.h"

namespace rmfx::test {
namespace {

class LuminanceHardCasesGLTest : public GlTest {};

constexpr double kDelta = 1e-4;
const char* const kVariants[] = {"exact", "sampled64", "histogram"};

// sampled64: the mean over its downsampled image as stored, itself checked against the exact box
// averages within rgba16f's rounding.
LogAverage model(const GlRun& run, const std::string& variant, const RefImage& input) {
    if (variant == "exact") return logAverage(input, kDelta);
    if (variant == "sampled64") return logAverage(checkedDownsampled(run, input, 4, 1), kDelta);
    return histogramLogAverage(input, kDelta, HistogramSettings{});
}

constexpr double kPeakTolerance = 1e-6;  // Y in float

void expectModel(const GlRun& run, const std::string& variant, const RefImage& input, const std::string& what) {
    glm::dvec2 gpu = readLuminance(run);
    LogAverage expected = model(run, variant, input);
    ASSERT_TRUE(std::isfinite(gpu.x) && std::isfinite(gpu.y)) << what << ": " << gpu.x << ", " << gpu.y;
    expectWithin(variant + ", " + what + ": Lavg relative error", relativeError(gpu.x, expected.lavg), logAverageTolerance(input, kDelta));
    if (expected.peak == 0.0) EXPECT_EQ(gpu.y, 0.0) << what;
    else expectWithin(variant + ", " + what + ": peak relative error", relativeError(gpu.y, expected.peak), kPeakTolerance);
}

// Renders the next image on the same executor: the Input file rewritten and reloaded.
void renderImage(GlRun& run, const ScratchDir& dir, const RefImage& input) {
    writeFloatExr(dir / "input.exr", input);
    Diagnostics d = run.exec->reloadTexture("Input").takeDiagnostics();
    ASSERT_TRUE(d.empty()) << formatAll(d);
    renderAgain(run);
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST_F(LuminanceHardCasesGLTest, BlackOneBrightPixelBadTexelsAndTinyLuminanceStayFiniteAndOnTheModel) {
    const int w = 31, h = 17;
    RefImage black(w, h, glm::dvec4(0.0, 0.0, 0.0, 1.0));
    RefImage bright = black;
    bright.at(12, 9) = glm::dvec4(1e6, 1e6, 1e6, 1.0);
    // NaN, ±Inf and negative channels (as lossy EXR compression leaves) in one texel in seven.
    RefImage bad = syntheticHdrImage(w, h, 21, -10.0, 10.0);
    const glm::dvec4 poison[] = {{kNaN, 1.0, 1.0, 1.0}, {kInf, 0.5, 0.5, 1.0}, {-kInf, 2.0, kNaN, 1.0},
                                 {-0.25, 3.0, -1e-3, 1.0}, {kNaN, kNaN, kNaN, kNaN}, {1.0, -kInf, kInf, 1.0}};
    for (size_t i = 0; i < bad.texels.size(); i += 7) bad.texels[i] = poison[(i / 7) % 6];
    RefImage tiny(w, h, glm::dvec4(1e-10, 1e-10, 1e-10, 1.0));

    for (const std::string variant : kVariants) {
        SCOPED_TRACE(variant);
        ScratchDir dir;
        GlRun run = runStage("luminance.xml", variant, black, dir);
        ASSERT_TRUE(run.exec);
        // All black: Lavg = delta (histogram: delta + the first bin's centre, 2^-15.75), peak 0.
        expectModel(run, variant, black, "all black");
        double lavg = readLuminance(run).x, slack = logAverageTolerance(black, kDelta);
        EXPECT_GE(lavg, kDelta * (1.0 - slack));
        EXPECT_LE(lavg, (kDelta + std::exp2(-15.5)) * (1.0 + slack));

        renderImage(run, dir, bright);
        expectModel(run, variant, bright, "one pixel at 1e6");

        renderImage(run, dir, bad);
        expectModel(run, variant, bad, "NaN, Inf and negative texels");

        // Y = 1e-10 everywhere (below rgba16f's smallest subnormal, and below the histogram's range).
        renderImage(run, dir, tiny);
        expectModel(run, variant, tiny, "luminance 1e-10");
        lavg = readLuminance(run).x;
        slack = logAverageTolerance(tiny, kDelta);
        EXPECT_GE(lavg, kDelta * (1.0 - slack));
        EXPECT_LE(lavg, (kDelta + std::exp2(-15.5)) * (1.0 + slack));
    }
}

// Every reduction chain at 1x1, 3x5 and 1921x1081 (one render each): a pixel of 1e30 in the last
// row and column (the top-right corner) moves the exact Lavg by far more than the tolerance, and
// the GPU follows the CPU; the histogram counts every pixel.
TEST_F(LuminanceHardCasesGLTest, EveryChainCountsTheEdgePixelsAtOddSizes) {
    for (glm::ivec2 size : {glm::ivec2(1, 1), glm::ivec2(3, 5), glm::ivec2(1921, 1081)}) {
        SCOPED_TRACE(std::to_string(size.x) + "x" + std::to_string(size.y));
        RefImage input = syntheticHdrImage(size.x, size.y, 33, -8.0, 4.0);
        RefImage without = input;
        input.at(size.x - 1, size.y - 1) = glm::dvec4(1e30, 1e30, 1e30, 1.0);
        if (size.x > 1) {
            double moved = relativeError(logAverage(input, kDelta).lavg, logAverage(without, kDelta).lavg);
            EXPECT_GT(moved, 10.0 * logAverageTolerance(input, kDelta)) << "the corner pixel must move Lavg measurably";
        }
        ScratchDir dir;
        writeFloatExr(dir / "input.exr", input);
        for (const std::string variant : kVariants) {
            SCOPED_TRACE(variant);
            ExecutorOptions options;
            options.effects = std::vector<std::string>{variant};
            GlRun run = runWorkspace(stageWorkspace("luminance.xml", dir / "input.exr"), {size, 1}, options);
            ASSERT_TRUE(run.exec);
            expectModel(run, variant, input, std::to_string(size.x) + "x" + std::to_string(size.y));
            if (variant == "histogram") {
                Image histogram = readBack(*run.exec, "histogram");
                double total = 0.0;
                for (int bin = 0; bin < 64; ++bin) total += atGl(histogram, bin / 4, 0, bin % 4);
                EXPECT_EQ(total, double(size.x) * size.y);
                EXPECT_EQ(atGl(histogram, 64, 0, 1), float(size.x * size.y));
                EXPECT_EQ(atGl(histogram, 63 / 4, 0, 63 % 4), 1.0f) << "the 1e30 pixel in the last bin";
            }
        }
    }
}

}  // namespace
}  // namespace rmfx::test
