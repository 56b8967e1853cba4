// <effect source>: an effect whose source holds nothing is skipped on the GPU, and the image is
// bit for bit what running it gives. Each test runs the same workspace twice, content skip on and
// off, frame by frame, and compares every byte of the output; it also checks which effects the
// frame skipped, so that a skip that never happens (or always happens) cannot pass. Here
// hdr_lighting and the article's pipeline; ContentSkipGlowGLTest.cpp goes on with a small glow
// workspace.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "gl/GlExecutor.h"
#include "io/image/ImageIO.h"
#include "model/HdrEncoding.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/ImageInputs.h"
#include "gl/Test/ContentSkipRuns.h"

namespace rmfx::test {
namespace {


// Runs `ws` on dim and bright frames, alternating, so that adaptation carries between frames of
// both kinds, with skipping on and off, and compares every frame; dim frames must skip `effects`.
// With CpuWaits, dim frames must leave out `notIssued` passes on the CPU.
void expectAlternatingFramesBitIdentical(Workspace& ws, const std::set<std::string>& effects, const std::string& label,
                                         Decision decision = Decision::CpuWhenKnown, int notIssued = 0) {
    const int w = 64, h = 48;
    const DimAndBright images = dimAndBright(w, h);
    ScratchDir dir;
    ASSERT_TRUE(writeImage(dir / "dim.exr", images.dim));
    Result<SuppliedInputs> supplied = supplyInputs(ws, {parseInputArgument((dir / "dim.exr").string())}, std::nullopt);
    ASSERT_TRUE(supplied) << formatAll(supplied.diagnostics());
    auto on = executorFor(ws, {w, h}, supplied->given, true, decision);
    auto off = executorFor(ws, {w, h}, supplied->given, false);
    ASSERT_TRUE(on && off);
    const bool frames[] = {false, true, false, false, true, true, false};  // bright?
    for (size_t k = 0; k < std::size(frames); ++k) {
        auto image = std::make_shared<const Image>(frames[k] ? images.bright : images.dim);
        ASSERT_TRUE(on->replaceInputImage("scene", image));
        ASSERT_TRUE(off->replaceInputImage("scene", image));
        const std::string what = label + " frame " + std::to_string(k) + (frames[k] ? " (bright)" : " (dim)");
        ASSERT_NO_FATAL_FAILURE(expectSameFrame(*on, *off, static_cast<float>(k) / 24.0f, what));
        std::set<std::string> skipped;
        for (const auto& [effect, why] : on->contentSkippedEffects()) skipped.insert(effect);
        // The first frame is decided by its own source: no frame of lag.
        if (k == 0) {
            EXPECT_EQ(skipped, effects) << what;
        }
        // Which side left the passes out: the GPU alone, or the CPU, which waited for the answer.
        if (decision == Decision::GpuOnly || frames[k]) {
            EXPECT_EQ(on->passesNotIssuedByContentSkip(), 0) << what;
        }
        if (decision == Decision::CpuWaits && !frames[k]) {
            EXPECT_EQ(on->passesNotIssuedByContentSkip(), notIssued) << what;
        }
        if (frames[k]) {
            EXPECT_TRUE(skipped.empty()) << what << ": a light far above 1 runs every effect";
        }
    }
}

// Each encoding, with the passes left out by the GPU alone (conditional rendering) and by the CPU
// (which waits for the source's answer here, to be sure to take that side; by default it takes
// it only where the answer has arrived).
class HdrLightingContentSkipGLTest : public GlTest, public ::testing::WithParamInterface<std::tuple<HdrEncoding, Decision>> {};

TEST_P(HdrLightingContentSkipGLTest, DimBrightAndAlternatingFramesAreBitIdenticalToRunningEverything) {
    const auto [encoding, decision] = GetParam();
    std::unique_ptr<Workspace> ws = effectWorkspace("hdr_lighting.xml", {{"HDR_Encoding", std::to_string(static_cast<int>(encoding))}});
    ASSERT_TRUE(ws);
    // bright_pass and star_source (which only the effects read), bloom's 4 passes and star's 25:
    // the effects count their gate, which is written before the bright pass.
    expectAlternatingFramesBitIdentical(*ws, {"bloom", "star"}, std::string(hdrEncodingName(encoding)) + ", " + decisionName(decision),
                                        decision, 31);
}

INSTANTIATE_TEST_SUITE_P(Encodings, HdrLightingContentSkipGLTest,
                         ::testing::Combine(::testing::Values(HdrEncoding::Float, HdrEncoding::Rgb16, HdrEncoding::Rgb32,
                                                              HdrEncoding::Rgb9e5, HdrEncoding::Rgbe8, HdrEncoding::Rgba8x64),
                                            ::testing::Values(Decision::GpuOnly, Decision::CpuWaits)),
                         [](const auto& info) {
                             return std::string(hdrEncodingName(std::get<0>(info.param))) + "_" + decisionName(std::get<1>(info.param));
                         });

class ArticleContentSkipGLTest : public GlTest {};

TEST_F(ArticleContentSkipGLTest, NothingAboveOneSkipsTheBlurAndTheImageIsTheSame) {
    std::unique_ptr<Workspace> ws = effectWorkspace("article_pipeline.xml");
    ASSERT_TRUE(ws);
    expectAlternatingFramesBitIdentical(*ws, {"bloom"}, "article_pipeline");
}

// hdr_lighting's gate (glsl/hdr_glare_gate.frag) bounds the bright pass from the brightest channel
// of the quarter image that the luminance chain carries. One scene pixel in a corner of an odd-sized
// image: bisecting its value finds the last value for which the bright pass (read back from a run
// with content skip off) writes zero everywhere and the first for which it does not, a float
// apart; just above, bloom and star must run; a little below, the gate must close; and every frame
// must equal running everything. Adaptation is off, so that each frame is decided by its own image.
class HdrLightingGateGLTest : public GlTest, public ::testing::WithParamInterface<HdrEncoding> {};

TEST_P(HdrLightingGateGLTest, ACornerPixelJustAboveTheBrightPassKeepsBloomAndStar) {
    std::unique_ptr<Workspace> ws = effectWorkspace(
        "hdr_lighting.xml", {{"HDR_Encoding", std::to_string(static_cast<int>(GetParam()))}, {"Light_Adaptation", "false"}});
    ASSERT_TRUE(ws);
    const int w = 37, h = 23;
    const Image dim = dimAndBright(w, h).dim;
    ScratchDir dir;
    ASSERT_TRUE(writeImage(dir / "dim.exr", dim));
    Result<SuppliedInputs> supplied = supplyInputs(*ws, {parseInputArgument((dir / "dim.exr").string())}, std::nullopt);
    ASSERT_TRUE(supplied) << formatAll(supplied.diagnostics());
    auto on = executorFor(*ws, {w, h}, supplied->given, true, Decision::CpuWaits);
    ExecutorOptions options;
    options.outputs = {"output", "bright"};
    options.givenInputs = supplied->given;
    options.contentSkip = false;
    auto created = GlExecutor::create(std::make_shared<const Workspace>(*ws), {w, h}, options);
    ASSERT_TRUE(on && created) << formatAll(created.diagnostics());
    GlExecutor& off = **created;
    for (glm::ivec2 corner : {glm::ivec2(0, 0), glm::ivec2(w - 1, h - 1)}) {
        SCOPED_TRACE("corner " + std::to_string(corner.x) + "," + std::to_string(corner.y));
        auto setPixel = [&](float value) {
            auto image = std::make_shared<Image>(dim);
            for (int c = 0; c < 3; ++c) image->at(corner.x, corner.y, c) = value;
            EXPECT_TRUE(on->replaceInputImage("scene", image));
            EXPECT_TRUE(off.replaceInputImage("scene", image));
        };
        // Whether the bright pass writes a non-zero red, green or blue anywhere, content skip off.
        auto brightPasses = [&](float value) {
            setPixel(value);
            EXPECT_TRUE(off.renderFrame({0.0f, 1.0f / 24.0f}));
            const Image bright = readBack(off, "bright");
            for (size_t i = 0; i < bright.pixels.size(); ++i)
                if (i % 4 != 3 && bright.pixels[i] != 0.0f) return true;
            return false;
        };
        float below = 0.03f, above = 1.0e5f;
        ASSERT_FALSE(brightPasses(below));
        ASSERT_TRUE(brightPasses(above));
        while (std::nextafter(below, above) < above) {
            const float middle = below + (above - below) / 2.0f;
            if (middle <= below || middle >= above) break;
            (brightPasses(middle) ? above : below) = middle;
        }
        // Each frame with both executors, the outputs compared; returns what was skipped.
        auto frame = [&](float value, const std::string& what) {
            setPixel(value);
            expectSameFrame(*on, off, 0.0f, what);
            return on->contentSkippedEffects();
        };
        EXPECT_TRUE(frame(above, "just above: " + std::to_string(above)).empty()) << "the first value the bright pass passes";
        frame(below, "just below: " + std::to_string(below));
        const Skipped wellBelow = frame(below * 0.98f, "2 % below");
        EXPECT_EQ(wellBelow.count("bloom"), 1u) << "2 % under the threshold the gate is closed";
        EXPECT_EQ(wellBelow.count("star"), 1u);
        EXPECT_EQ(on->passesNotIssuedByContentSkip(), 31) << "bright_pass, star_source, bloom's 4 and star's 25";
        // NaN and infinity: the input pass makes them finite before the quarter image (today the
        // bright pass then writes zero, and the gate closes); whatever it makes of them, the
        // effects run exactly where the bright pass writes anything but zero (NaN included).
        for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
            const bool passes = brightPasses(bad);
            const Skipped skipped = frame(bad, std::isnan(bad) ? "NaN" : "+Inf");
            EXPECT_EQ(skipped.empty(), passes) << (std::isnan(bad) ? "NaN" : "+Inf");
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Encodings, HdrLightingGateGLTest,
                         ::testing::Values(HdrEncoding::Float, HdrEncoding::Rgb9e5, HdrEncoding::Rgbe8),
                         [](const auto& info) { return std::string(hdrEncodingName(info.param)); });

}  // namespace
}  // namespace rmfx::test
