// effects/variants/luminance.xml: each variant against a float64 CPU model of its own maths (the
// ideal log-average for `exact`), on synthetic images of odd sizes (tests/reference/
// LuminanceVariantsReference.h).

#include <cmath>

#include <gtest/gtest.h>

#include "effects/Test/StageTestSupport.h"
#include "reference/LuminanceVariantsReference.h"
#include "reference/StageInput.h"

namespace rmfx::test {
namespace {

class LuminanceVariantsGLTest : public GlTest {};

constexpr double kDelta = 1e-4;

LogAverage luminanceOf(const GlRun& run) {
    glm::dvec2 lum = readLuminance(run);
    return {lum.x, lum.y};
}

// `exact` is the mean of log(delta + Y) over every pixel: the float logs (an ulp of up to ~10) and
// the float exp at the end stay within 1e-6 of Lavg; the chain's sums are in double.
TEST_F(LuminanceVariantsGLTest, ExactIsTheFloat64LogAverage) {
    ScratchDir dir;
    RefImage input = syntheticHdrImage(157, 91, 7, -20.0, 16.0, 0.05);
    GlRun run = runStage("luminance.xml", "exact", input, dir);
    ASSERT_TRUE(run.exec);
    LogAverage gpu = luminanceOf(run), ideal = logAverage(input, kDelta);
    expectWithin("exact Lavg relative error", relativeError(gpu.lavg, ideal.lavg), 1e-6);
    expectWithin("exact peak relative error", relativeError(gpu.peak, ideal.peak), 1e-6);
    // Each texel of the first level counts the pixels of its 16x16 block, clipped at the edges.
    Image first = readBack(*run.exec, "exact_16");
    ASSERT_EQ(first.width, 10);
    ASSERT_EQ(first.height, 6);
    EXPECT_EQ(atGl(first, 9, 5, 2), float(13 * 11));
    EXPECT_EQ(atGl(first, 0, 0, 2), 256.0f);
}

// `sampled64` against the model of its own sampling: box averages to the Downsample size, stored
// in Target_Format (checked against the exact averages within the format's rounding), then the
// mean of log(delta + Y) over the stored texels. The downsample factor is read from the target
// sizes: each of 2, 4, 8 by Downsample; every Target_Format at 1/4.
TEST_F(LuminanceVariantsGLTest, Sampled64IsTheLogAverageOfTheDownsampledImage) {
    ScratchDir dir;
    RefImage input = syntheticHdrImage(301, 203, 11, -14.0, 17.0, 0.02);
    for (int factor : {2, 4, 8}) {
        for (int format = 0; format < 6; ++format) {
            if (factor != 4 && format > 1) continue;  // every format at 1/4, the float ones at each factor
            SCOPED_TRACE("factor " + std::to_string(factor) + ", Target_Format " + std::to_string(format));
            std::filesystem::path file = dir / "input.exr";
            writeFloatExr(file, input);
            const std::string downsample = factor == 2 ? "0" : factor == 4 ? "1" : "2";  // 1/2, 1/4, 1/8
            auto ws = stageWorkspace("luminance.xml", file, {{"Target_Format", std::to_string(format)}, {"Downsample", downsample}});
            ASSERT_TRUE(ws);
            ExecutorOptions options;
            options.effects = std::vector<std::string>{"sampled64"};
            GlRun run = runWorkspace(std::move(ws), {{input.width, input.height}, 1}, options);
            ASSERT_TRUE(run.exec);
            LogAverage gpu = luminanceOf(run);
            const RefImage downsampled = checkedDownsampled(run, input, factor, format);
            LogAverage model = logAverage(downsampled, kDelta);
            expectWithin("sampled64 Lavg relative error", relativeError(gpu.lavg, model.lavg),
                         logAverageTolerance(downsampled, kDelta));
            expectWithin("sampled64 peak relative error", relativeError(gpu.peak, model.peak), 2e-6);
        }
    }
}

// `histogram` against the model: every pixel in its bin (the image keeps log2(Y) away from bin
// edges, so float and double bin alike), counts exact, then the mean at bin centres over all
// pixels (Low 0, High 1) and over the 5 %..95 % ranks.
TEST_F(LuminanceVariantsGLTest, HistogramIsTheBinnedMeanBetweenThePercentiles) {
    ScratchDir dir;
    HistogramSettings settings;
    RefImage input = syntheticHdrImage(133, 77, 5, -18.0, 18.0, 0.03, 0.5);
    GlRun run = runStage("luminance.xml", "histogram", input, dir);
    ASSERT_TRUE(run.exec);

    std::vector<double> counts = logHistogram(input, settings);
    Image histogram = readBack(*run.exec, "histogram");
    ASSERT_EQ(histogram.width, 65);
    for (int bin = 0; bin < settings.bins; ++bin) EXPECT_EQ(atGl(histogram, bin / 4, 0, bin % 4), counts[bin]) << "bin " << bin;
    EXPECT_EQ(atGl(histogram, 64, 0, 1), float(133 * 77));

    LogAverage gpu = luminanceOf(run), model = histogramLogAverage(input, kDelta, settings);
    expectWithin("histogram Lavg relative error (0..1)", relativeError(gpu.lavg, model.lavg), 1e-6);
    expectWithin("histogram peak relative error", relativeError(gpu.peak, model.peak), 1e-6);

    setVariable(run, "Histogram_Low", Value::ofFloat(0.05f));
    setVariable(run, "Histogram_High", Value::ofFloat(0.95f));
    renderAgain(run);
    settings.low = double(0.05f);
    settings.high = double(0.95f);
    LogAverage trimmed = luminanceOf(run), trimmedModel = histogramLogAverage(input, kDelta, settings);
    expectWithin("histogram Lavg relative error (0.05..0.95)", relativeError(trimmed.lavg, trimmedModel.lavg), 2e-6);
    // The trimmed mean differs from the full one by far more than the tolerance, so the test tells them apart.
    EXPECT_GT(relativeError(trimmedModel.lavg, model.lavg), 1e-3);
}

}  // namespace
}  // namespace rmfx::test
