// Hard cases of effects/hdr_lighting.xml: sizes 1x1, 3x5 and 1921x1081 through its reduction
// chains (the exact 4x4 box to the quarter image, the 64² -> 16² -> 4² -> 1² log-average, the 2x2
// box to the 1/8 bloom source) with a single bright pixel in the last column, the last row or the
// corner, against the float64 references of tests/reference/HdrLightingReference.h; and a scene
// whose luminance is 1e-10 everywhere.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "reference/CpuImage.h"
#include "reference/HdrLightingReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class HdrLightingHardCasesGLTest : public GlTest {};

const double kHalfTolerance = std::ldexp(1.0, -10) + 1e-5;  // one rounding to half + float32 sums
constexpr double kPixel = 30000.0;                           // the bright pixel, grey, inside half range

int nonFiniteValues(const Image& image) {
    int n = 0;
    for (float v : image.pixels) n += !std::isfinite(v);
    return n;
}

double total(const RefImage& image) {
    double sum = 0.0;
    for (const glm::dvec4& t : image.texels) sum += t.r + t.g + t.b;
    return sum;
}

// The log-average of an image that is black but for the quarter texels holding the pixel: with
// log(1 + Y / delta) carried through the chain every black texel adds exactly 0, so the GPU's only
// errors are those of one log (3 ulps), the weighted means (1e-6 relative of the mean) and the
// final exp (3 ulps): 2e-6 of Lavg. The pixel moves Lavg above delta by what the reference says;
// the test requires that move to be over 20 times the tolerance, so a lost pixel fails.
TEST_F(HdrLightingHardCasesGLTest, SinglePixelInTheLastRowOrColumnReachesEveryReduction) {
    int bloomed = 0;
    for (const EdgePixelCase& c : edgePixelCases()) {
        SCOPED_TRACE(c.name());
        auto ws = effectWorkspace("hdr_lighting.xml", {{"Light_Adaptation", "false"}});
        ASSERT_TRUE(ws);
        replaceSceneWithPattern(*ws, "scene", singlePixelPattern(c.pixel, kPixel));
        ExecutorOptions bloomOnly;  // the star is no reduction chain; leaving it out saves compiling 25 passes
        bloomOnly.effects = std::vector<std::string>{"bloom"};
        GlRun run = runWorkspace(std::move(ws), {c.size, 1, 1.0f / 60.0f}, bloomOnly);
        ASSERT_TRUE(run.exec);
        for (const char* name : {"scene", "quarter", "lum64", "lum16", "lum4", "measured", "adapted", "bright",
                                 "star_source", "bloom_source", "bloom_blur", "bloom_h", "bloom", "output"})
            EXPECT_EQ(nonFiniteValues(readBack(*run.exec, name)), 0) << name;

        RefImage scene = readRef(run, "scene"), quarter = readRef(run, "quarter");
        ASSERT_EQ(scene.at(c.pixel.x, c.pixel.y).r, kPixel) << "the pattern drew the pixel";
        EXPECT_EQ(quarter.width, (c.size.x + 3) / 4);
        EXPECT_EQ(quarter.height, (c.size.y + 3) / 4);
        EXPECT_LE(worstExcess(quarter, hdr::boxDownscale(scene, 4), kHalfTolerance, 1e-12), 0.0) << "quarter";

        Image measured = readBack(*run.exec, "measured");
        hdr::LogAverage ref = hdr::logAverage(quarter, scene);
        const double tolerance = 2e-6 * ref.average;
        expectWithin("Lavg error", std::fabs(measured.at(0, 0, 0) - ref.average), tolerance);
        EXPECT_GT(ref.average - hdr::kLogDelta, 20 * tolerance) << "the pixel moves Lavg: " << ref.average;
        EXPECT_NEAR(measured.at(0, 0, 1), ref.peak, 2e-5 * ref.peak) << "the peak is the pixel";
        EXPECT_NEAR(ref.peak, kPixel * (0.2125 + 0.7154 + 0.0721), 1e-6 * kPixel);

        // 1/8 bloom source: the 2x2 box of the star source, whatever texels the edges have.
        RefImage starSource = readRef(run, "star_source"), bloomSource = readRef(run, "bloom_source");
        EXPECT_EQ(bloomSource.width, (c.size.x + 7) / 8);
        EXPECT_EQ(bloomSource.height, (c.size.y + 7) / 8);
        EXPECT_LE(worstExcess(bloomSource, hdr::boxDownscale(starSource, 2), kHalfTolerance, 1e-12), 0.0) << "bloom source";
        // The bright pass, from the quarter image and the adapted luminance (= measured, with
        // adaptation off): at 1x1 the pixel is its own average and nothing is bright.
        const double adapted = readBack(*run.exec, "adapted").at(0, 0, 0);
        RefImage bright = hdr::brightPass(quarter, adapted, 0.18);
        EXPECT_LE(worstExcess(readRef(run, "bright"), bright, kHalfTolerance, 1e-6), 0.0) << "bright pass";
        if (total(bright) > 0.1) {
            ++bloomed;
            EXPECT_GT(total(bloomSource), 0.1) << "the pixel passes the bright pass into the bloom";
        }
    }
    EXPECT_GE(bloomed, 4) << "the pixel reaches the bloom source at 3x5 and 1921x1081";
}

// Every radiance 1e-10. In the half-float scene that is below the smallest subnormal (6e-8): the
// scene is black, Lavg is delta exactly and the output 0. With the scene and quarter images in
// rgba32f the 1e-10 survive: Lavg = delta + Y (uniform Y), above delta by 1e-6 of it, and
// everything stays finite; the adapted luminance is >= the floor delta in both.
TEST_F(HdrLightingHardCasesGLTest, LuminanceOf1e10EverywhereStaysFiniteAndAboveTheFloor) {
    const float floor = static_cast<float>(hdr::kLogDelta);
    for (bool floatScene : {false, true}) {
        SCOPED_TRACE(floatScene ? "rgba32f scene" : "rgba16f scene");
        auto ws = effectWorkspace("hdr_lighting.xml", {{"Light0_Radiance", "1e-10"},
                                                        {"Light1_Radiance", "1e-10"},
                                                        {"Panel_Radiance", "1e-10"},
                                                        {"Ambient_Radiance", "1e-10"}});
        ASSERT_TRUE(ws);
        if (floatScene)
            for (RenderTarget& t : ws->targets)
                if (t.name == "scene" || t.name == "quarter") {
                    t.format = TargetFormat::RGBA32F;
                    std::fill(t.formats.begin(), t.formats.end(), TargetFormat::RGBA32F);
                }
        GlRun run = runWorkspace(std::move(ws), {{96, 64}, 20, 0.1f});
        ASSERT_TRUE(run.exec);
        for (const RenderTarget& t : run.ws->targets) EXPECT_EQ(nonFiniteValues(readBack(*run.exec, t.name)), 0) << t.name;
        Image output = readBack(*run.exec, "output");
        EXPECT_EQ(nonFiniteValues(output), 0);
        for (float v : output.pixels) ASSERT_GE(v, 0.0f);
        const float measured = readBack(*run.exec, "measured").at(0, 0, 0);
        const float adapted = readBack(*run.exec, "adapted").at(0, 0, 0);
        EXPECT_GE(measured, floor);
        EXPECT_GE(adapted, floor);
        RefImage scene = readRef(run, "scene");
        double brightest = 0.0;
        for (const glm::dvec4& t : scene.texels) brightest = std::max({brightest, t.r, t.g, t.b});
        if (floatScene) {
            EXPECT_GT(brightest, 0.0) << "the 1e-10 radiances reach the scene";
            EXPECT_LT(brightest, 1e-8);
            hdr::LogAverage ref = hdr::logAverage(readRef(run, "quarter"), scene);
            EXPECT_NEAR(measured, ref.average, 2e-6 * ref.average);
        } else {
            EXPECT_EQ(brightest, 0.0) << "half floats flush 1e-10 to 0";
            EXPECT_EQ(measured, floor) << "Lavg of black is delta";
        }
    }
}

}  // namespace
}  // namespace rmfx::test
