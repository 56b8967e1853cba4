// <effect source>: an effect whose source holds nothing is skipped on the GPU, and the image is
// bit for bit what running it gives. Each test runs the same workspace twice, content skip on and
// off, frame by frame, and compares every byte of the output; it also checks which effects the
// frame skipped, so that a skip that never happens (or always happens) cannot pass. A pass that
// reads a skipped effect's output is drawn compiled without the effect; one test tells the two
// versions apart.

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

namespace rmfx::test {
namespace {

using Skipped = std::map<std::string, std::string>;
using Decision = ExecutorOptions::ContentSkipDecision;

const char* decisionName(Decision d) {
    switch (d) {
        case Decision::CpuWhenKnown: return "CpuWhenKnown";
        case Decision::GpuOnly: return "GpuOnly";
        case Decision::CpuWaits: return "CpuWaits";
    }
    return "?";
}

std::unique_ptr<GlExecutor> executorFor(const Workspace& ws, glm::ivec2 size, const std::set<std::string>& given, bool skip,
                                        Decision decision = Decision::CpuWhenKnown) {
    ExecutorOptions options;
    options.outputs = {"output"};
    options.givenInputs = given;
    options.contentSkip = skip;
    options.contentSkipDecision = decision;
    auto created = GlExecutor::create(std::make_shared<const Workspace>(ws), size, options);
    EXPECT_TRUE(created) << formatAll(created.diagnostics());
    return created ? std::move(*created) : nullptr;
}

// Renders one frame with each executor and checks that the outputs hold the same bytes.
void expectSameFrame(GlExecutor& on, GlExecutor& off, float time, const std::string& what) {
    for (GlExecutor* e : {&on, &off}) {
        Diagnostics frame = e->renderFrame({time, 1.0f / 24.0f}).takeDiagnostics();
        ASSERT_FALSE(hasErrors(frame)) << formatAll(frame);
    }
    Image a = readBack(on, "output"), b = readBack(off, "output");
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    ASSERT_FALSE(a.pixels.empty());
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0)
        << what << ": the output with content skip differs from the output without it";
    EXPECT_TRUE(off.contentSkippedEffects().empty()) << what << ": --content-skip off skips nothing";
}

// A dim image (nothing passes the bright pass) and one with a light far above 1.
struct DimAndBright {
    Image dim, bright;
};
DimAndBright dimAndBright(int w, int h) {
    DimAndBright out{blankHdrImage(w, h), blankHdrImage(w, h)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c) {
                const float base = c == 3 ? 1.0f : 0.02f + 0.01f * c;
                out.dim.at(x, y, c) = base;
                out.bright.at(x, y, c) = (c < 3 && x >= 40 && x < 48 && y >= 10 && y < 18) ? 200.0f : base;
            }
    return out;
}

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

// A bright pass keeps what exceeds 1; the glow effect spreads it over 3x3 pixels and the final
// pass adds it to the scene. The scene is black but for one pixel.
const char* const kGlow = R"(<workspace version="1" name="glow" size="37x23">
  <int name="Pixel_X" value="0"/>
  <int name="Pixel_Y" value="0"/>
  <float name="Value" value="0"/>
  <int name="Kind" value="0"/>
  <target name="scene" format="rgba32f"/>
  <target name="bright" format="rgba32f"/>
  <target name="glow" format="rgba32f"/>
  <pass name="draw" target="scene"><shader stage="fragment"><![CDATA[
uniform int Pixel_X;
uniform int Pixel_Y;
uniform float Value;
uniform int Kind;
out vec4 c;
void main() {
    float v = Kind == 1 ? uintBitsToFloat(0x7fc00000u) : Kind == 2 ? uintBitsToFloat(0x7f800000u) : Value;
    c = ivec2(gl_FragCoord.xy) == ivec2(Pixel_X, Pixel_Y) ? vec4(vec3(v), 1.0) : vec4(0.0, 0.0, 0.0, 1.0);
}
]]></shader></pass>
  <pass name="bright_pass" target="bright"><sampler name="Scene" target="scene" filter="nearest"/><shader stage="fragment"><![CDATA[
uniform sampler2D Scene;
out vec4 c;
void main() { c = vec4(max(texelFetch(Scene, ivec2(gl_FragCoord.xy), 0).rgb - 1.0, 0.0), 1.0); }
]]></shader></pass>
  <pass name="glow_pass" target="glow"><sampler name="Bright" target="bright" filter="nearest"/><shader stage="fragment"><![CDATA[
uniform sampler2D Bright;
out vec4 c;
void main() {
    ivec2 size = textureSize(Bright, 0);
    vec3 sum = vec3(0.0);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            sum += texelFetch(Bright, clamp(ivec2(gl_FragCoord.xy) + ivec2(dx, dy), ivec2(0), size - 1), 0).rgb;
    c = vec4(sum * 0.5, 0.0);
}
]]></shader></pass>
  <effect name="glow" passes="glow_pass" source="bright"/>
  <pass name="final"><sampler name="Scene" target="scene" filter="nearest"/><sampler name="Glow" target="glow" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
uniform sampler2D Scene;
uniform sampler2D Glow;
out vec4 c;
void main() { ivec2 p = ivec2(gl_FragCoord.xy); c = texelFetch(Scene, p, 0) + texelFetch(Glow, p, 0); }
]]></shader></pass>
  <output format="rgba32f" transform="none"/>
</workspace>
)";

class ArticleContentSkipGLTest : public GlTest {};

TEST_F(ArticleContentSkipGLTest, NothingAboveOneSkipsTheBlurAndTheImageIsTheSame) {
    std::unique_ptr<Workspace> ws = effectWorkspace("article_pipeline.xml");
    ASSERT_TRUE(ws);
    expectAlternatingFramesBitIdentical(*ws, {"bloom"}, "article_pipeline");
}

class GlowContentSkipGLTest : public GlTest {
protected:
    // One frame with the pixel at (x, y) holding `value` (kind 0), NaN (1) or +Inf (2); returns
    // what the frame skipped, after checking the outputs are the same (unless `sameImage` is false).
    Skipped frameWith(glm::ivec2 pixel, float value, int kind = 0) { return frameOf(kGlow, pixel, value, kind); }
    Skipped frameOf(const std::string& xml, glm::ivec2 pixel, float value, int kind,
                    Decision decision = Decision::CpuWhenKnown, bool sameImage = true) {
        std::unique_ptr<Workspace> ws = workspaceFromText(xml);
        if (!ws) return {{"-", "no workspace"}};
        on_ = executorFor(*ws, {37, 23}, {}, true, decision);
        off_ = executorFor(*ws, {37, 23}, {}, false);
        if (!on_ || !off_) return {{"-", "no executor"}};
        for (GlExecutor* e : {on_.get(), off_.get()}) {
            EXPECT_TRUE(e->setVariable("Pixel_X", Value::ofInt(pixel.x)));
            EXPECT_TRUE(e->setVariable("Pixel_Y", Value::ofInt(pixel.y)));
            EXPECT_TRUE(e->setVariable("Value", Value::ofFloat(value)));
            EXPECT_TRUE(e->setVariable("Kind", Value::ofInt(kind)));
        }
        const std::string what = "pixel " + std::to_string(pixel.x) + "," + std::to_string(pixel.y) + " kind " +
                                 std::to_string(kind) + " value " + std::to_string(value);
        if (sameImage) {
            expectSameFrame(*on_, *off_, 0.0f, what);
        } else {
            for (GlExecutor* e : {on_.get(), off_.get()}) EXPECT_TRUE(e->renderFrame({0.0f, 1.0f / 24.0f})) << what;
        }
        return on_->contentSkippedEffects();
    }
    std::unique_ptr<GlExecutor> on_, off_;  // of the last frame
};

TEST_F(GlowContentSkipGLTest, OnePixelJustAboveTheThresholdInAnyCornerKeepsTheEffect) {
    const float justAbove = std::nextafter(1.0f, 2.0f);
    for (glm::ivec2 corner : {glm::ivec2(0, 0), glm::ivec2(36, 0), glm::ivec2(0, 22), glm::ivec2(36, 22)}) {
        EXPECT_TRUE(frameWith(corner, justAbove).empty()) << "corner " << corner.x << "," << corner.y;
        Skipped at = frameWith(corner, 1.0f);
        ASSERT_EQ(at.count("glow"), 1u) << "exactly at the threshold nothing passes: corner " << corner.x << "," << corner.y;
        EXPECT_EQ(at.at("glow"), "'bright' holds no pixel with a non-zero red, green or blue value");
    }
}

// The probe gives each fragment 2x2 pixels: a pixel at each place of a block (odd coordinates
// too, and the last, unpaired column and row of this odd-sized source) must keep the effect.
TEST_F(GlowContentSkipGLTest, OnePixelAtEachPlaceOfATwoByTwoBlockKeepsTheEffect) {
    const float justAbove = std::nextafter(1.0f, 2.0f);
    for (glm::ivec2 pixel : {glm::ivec2(1, 0), glm::ivec2(0, 1), glm::ivec2(1, 1), glm::ivec2(35, 21), glm::ivec2(35, 22),
                             glm::ivec2(36, 21), glm::ivec2(17, 9)})
        EXPECT_TRUE(frameWith(pixel, justAbove).empty()) << "pixel " << pixel.x << "," << pixel.y;
}

TEST_F(GlowContentSkipGLTest, NanAndInfinityCountAsTheShadersTreatThem) {
    // +Inf - 1 is +Inf: the effect runs. NaN goes through max() as the GL implementation makes
    // it; whatever the bright pass writes, the output is what running everything gives.
    EXPECT_TRUE(frameWith({18, 11}, 0.0f, 2).empty());
    frameWith({18, 11}, 0.0f, 1);
}

// A pass after the effect that reads what it hands on is drawn, where the effect is skipped,
// compiled without it (RMFX_EFFECT_glow false), so it reads nothing of the cleared target. This
// final pass is written to tell the two apart (it adds 0.25 to alpha when the effect is compiled
// in, which the workspaces in effects/ never do): dim frames give the version without the
// effect, bright ones and --content-skip off the version as compiled.
TEST_F(GlowContentSkipGLTest, APassReadingASkippedEffectIsDrawnCompiledWithoutIt) {
    std::string xml = kGlow;
    const std::string final = "c = texelFetch(Scene, p, 0) + texelFetch(Glow, p, 0); }";
    const size_t at = xml.find(final);
    ASSERT_NE(at, std::string::npos);
    xml.replace(at, final.size(),
                "c = texelFetch(Scene, p, 0); if (RMFX_EFFECT_glow) c += texelFetch(Glow, p, 0) + vec4(0.0, 0.0, 0.0, 0.25); }");
    std::unique_ptr<Workspace> ws = workspaceFromText(xml);
    ASSERT_TRUE(ws);
    for (Decision decision : {Decision::GpuOnly, Decision::CpuWaits}) {
        SCOPED_TRACE(decisionName(decision));
        auto on = executorFor(*ws, {37, 23}, {}, true, decision);
        auto off = executorFor(*ws, {37, 23}, {}, false);
        ASSERT_TRUE(on && off);
        auto alphaOf = [&](GlExecutor& e, float value) {
            EXPECT_TRUE(e.setVariable("Pixel_X", Value::ofInt(5)));
            EXPECT_TRUE(e.setVariable("Pixel_Y", Value::ofInt(7)));
            EXPECT_TRUE(e.setVariable("Value", Value::ofFloat(value)));
            Diagnostics frame = e.renderFrame({0.0f, 1.0f / 24.0f}).takeDiagnostics();
            EXPECT_FALSE(hasErrors(frame)) << formatAll(frame);
            Image out = readBack(e, "output");
            std::set<float> alphas;
            for (int y = 0; y < out.height; ++y)
                for (int x = 0; x < out.width; ++x) alphas.insert(out.at(x, y, 3));
            return alphas;
        };
        EXPECT_EQ(alphaOf(*on, 0.5f), (std::set<float>{1.0f})) << "dim: drawn without the effect";
        EXPECT_EQ(on->contentSkippedEffects().count("glow"), 1u);
        EXPECT_EQ(alphaOf(*on, 3.0f), (std::set<float>{1.25f})) << "bright: drawn as compiled";
        EXPECT_TRUE(on->contentSkippedEffects().empty());
        EXPECT_EQ(alphaOf(*on, 0.5f), (std::set<float>{1.0f})) << "dim again";
        EXPECT_EQ(alphaOf(*off, 0.5f), (std::set<float>{1.25f})) << "--content-skip off: as compiled";
    }
}

// kGlow with spread_pass between the bright pass and the glow, which reads it instead of
// 'bright': it copies 'bright' and writes alpha 0.5, which nothing reads.
std::string glowWithAFeeder() {
    std::string xml = kGlow;
    auto replace = [&](const std::string& from, const std::string& to) {
        const size_t at = xml.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) xml.replace(at, from.size(), to);
    };
    replace(R"(<target name="glow" format="rgba32f"/>)",
            R"(<target name="glow" format="rgba32f"/><target name="spread" format="rgba16f"/>)");
    replace(R"(  <pass name="glow_pass" target="glow"><sampler name="Bright" target="bright" filter="nearest"/>)",
            R"(  <pass name="spread_pass" target="spread"><sampler name="Bright" target="bright" filter="nearest"/><shader stage="fragment"><![CDATA[
uniform sampler2D Bright;
out vec4 c;
void main() { c = vec4(texelFetch(Bright, ivec2(gl_FragCoord.xy), 0).rgb, 0.5); }
]]></shader></pass>
  <pass name="glow_pass" target="glow"><sampler name="Bright" target="spread" filter="nearest"/>)");
    return xml;
}

// A pass between the source and the effect that only the effect reads (hdr_lighting's
// star_source) is drawn under the effect's condition: on a dim frame it is not drawn at all (its
// target keeps what it held; it writes alpha 0.5 when drawn, and nothing reads alpha), on a
// bright one it is, and asking for its target as an output makes it run whatever the source.
TEST_F(GlowContentSkipGLTest, APassOnlyTheEffectReadsIsSkippedWithIt) {
    std::unique_ptr<Workspace> ws = workspaceFromText(glowWithAFeeder());
    ASSERT_TRUE(ws);
    auto on = executorFor(*ws, {37, 23}, {}, true);
    auto off = executorFor(*ws, {37, 23}, {}, false);
    ASSERT_TRUE(on && off);
    EXPECT_EQ(on->passesDrawnOnlyForEffects(), (std::map<std::string, std::set<std::string>>{{"spread_pass", {"glow"}}}));
    EXPECT_TRUE(off->passesDrawnOnlyForEffects().empty());
    auto spreadAlphas = [](const GlExecutor& e) {
        std::vector<float> rgba(37 * 23 * 4);
        glGetTextureImage(e.targetTexture("spread"), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)),
                          rgba.data());
        std::set<float> alphas;
        for (size_t i = 3; i < rgba.size(); i += 4) alphas.insert(rgba[i]);
        return alphas;
    };
    auto frame = [&](float value, const std::string& what) {
        for (GlExecutor* e : {on.get(), off.get()}) {
            EXPECT_TRUE(e->setVariable("Pixel_X", Value::ofInt(36)));
            EXPECT_TRUE(e->setVariable("Pixel_Y", Value::ofInt(22)));
            EXPECT_TRUE(e->setVariable("Value", Value::ofFloat(value)));
        }
        expectSameFrame(*on, *off, 0.0f, what);
    };
    frame(0.5f, "dim");
    EXPECT_EQ(on->contentSkippedEffects().count("glow"), 1u);
    EXPECT_EQ(spreadAlphas(*on), (std::set<float>{0.0f})) << "dim: spread_pass is not drawn";
    EXPECT_EQ(spreadAlphas(*off), (std::set<float>{0.5f})) << "--content-skip off draws it";
    frame(3.0f, "bright");
    EXPECT_TRUE(on->contentSkippedEffects().empty());
    EXPECT_EQ(spreadAlphas(*on), (std::set<float>{0.5f})) << "bright: spread_pass is drawn";

    ExecutorOptions options;
    options.outputs = {"output", "spread"};
    auto created = GlExecutor::create(std::make_shared<const Workspace>(*ws), {37, 23}, options);
    ASSERT_TRUE(created) << formatAll(created.diagnostics());
    EXPECT_TRUE((*created)->passesDrawnOnlyForEffects().empty()) << "a target read back after the frame is always drawn";
    ASSERT_TRUE((*created)->setVariable("Value", Value::ofFloat(0.5f)));
    ASSERT_TRUE((*created)->renderFrame({0.0f, 1.0f / 24.0f}));
    EXPECT_EQ((*created)->contentSkippedEffects().count("glow"), 1u);
    EXPECT_EQ(spreadAlphas(**created), (std::set<float>{0.5f}));
}

// Where the effect is skipped, what it hands on is cleared to zero only where something reads the
// zeros: not when the pass after it, drawn compiled without the effect, samples nothing of it
// (the target keeps what the last bright frame left), but when that version still samples it.
// Read back after the frame, the target holds what the effect's pass writes: the effect runs.
// Bright frame, then dim; every output is compared with --content-skip off byte for byte.
TEST_F(GlowContentSkipGLTest, WhatASkippedEffectHandsOnIsClearedOnlyWhereSomethingReadsIt) {
    const std::string plain = "c = texelFetch(Scene, p, 0) + texelFetch(Glow, p, 0); }";
    struct Case {
        const char* label;
        std::string final;
        std::set<std::string> outputs;
        bool cleared;  // or, where the effect runs, as running it left it
        bool skipped = true;
    };
    const Case cases[] = {
        {"guarded", "c = texelFetch(Scene, p, 0); if (RMFX_EFFECT_glow) c += texelFetch(Glow, p, 0); }", {"output"}, false},
        {"also read unguarded", "c = texelFetch(Scene, p, 0) + texelFetch(Glow, p, 0); if (RMFX_EFFECT_glow) c += texelFetch(Glow, p, 0); }",
         {"output"}, true},
        {"not guarded", plain, {"output"}, true},
        {"guarded, read back", "c = texelFetch(Scene, p, 0); if (RMFX_EFFECT_glow) c += texelFetch(Glow, p, 0); }", {"output", "glow"}, true, false},
    };
    for (const Case& c : cases)
        for (Decision decision : {Decision::GpuOnly, Decision::CpuWaits}) {
            SCOPED_TRACE(std::string(c.label) + ", " + decisionName(decision));
            std::string xml = kGlow;
            xml.replace(xml.find(plain), plain.size(), c.final);
            std::unique_ptr<Workspace> ws = workspaceFromText(xml);
            ASSERT_TRUE(ws);
            ExecutorOptions options;
            options.outputs = std::vector<std::string>(c.outputs.begin(), c.outputs.end());
            options.contentSkipDecision = decision;
            auto on = GlExecutor::create(std::make_shared<const Workspace>(*ws), {37, 23}, options);
            options.contentSkip = false;
            auto off = GlExecutor::create(std::make_shared<const Workspace>(*ws), {37, 23}, options);
            ASSERT_TRUE(on && off) << formatAll(on.diagnostics()) << formatAll(off.diagnostics());
            for (GlExecutor* e : {on->get(), off->get()}) {
                ASSERT_TRUE(e->setVariable("Pixel_X", Value::ofInt(9)));
                ASSERT_TRUE(e->setVariable("Pixel_Y", Value::ofInt(3)));
                ASSERT_TRUE(e->setVariable("Value", Value::ofFloat(3.0f)));
            }
            expectSameFrame(**on, **off, 0.0f, "bright");
            for (GlExecutor* e : {on->get(), off->get()}) ASSERT_TRUE(e->setVariable("Value", Value::ofFloat(0.5f)));
            expectSameFrame(**on, **off, 1.0f / 24.0f, "dim");
            EXPECT_EQ((*on)->contentSkippedEffects().count("glow"), c.skipped ? 1u : 0u);
            EXPECT_EQ((*on)->effectsRunningWhateverTheContent().count("glow"), c.skipped ? 0u : 1u);
            std::vector<float> glow(37 * 23 * 4);
            glGetTextureImage((*on)->targetTexture("glow"), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(glow.size() * sizeof(float)),
                              glow.data());
            const float most = *std::max_element(glow.begin(), glow.end());
            if (c.cleared) {
                EXPECT_EQ(most, 0.0f) << "cleared to zero";
            } else {
                EXPECT_EQ(most, 1.0f) << "left as the bright frame made it ((3 - 1) / 2)";
            }
        }
}

// <effect gate>: the glow workspace with a 1x1 gate, the scene's largest channel minus the
// threshold, written before the bright pass. The gate is counted in place of the bright pass,
// so that the bright pass (which only the effect reads) is left out with the effect.
std::string glowWithAGate(const std::string& gateExpression = "max(largest - 1.0, 0.0)") {
    std::string xml = kGlow;
    auto replace = [&](const std::string& from, const std::string& to) {
        const size_t at = xml.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) xml.replace(at, from.size(), to);
    };
    replace(R"(  <target name="bright" format="rgba32f"/>)", R"(  <target name="bright" format="rgba32f"/>
  <target name="gate" format="r32f" size="1x1"/>)");
    replace(R"(  <pass name="bright_pass" target="bright">)", R"(  <pass name="gate_pass" target="gate"><sampler name="Scene" target="scene" filter="nearest"/><shader stage="fragment"><![CDATA[
uniform sampler2D Scene;
out vec4 c;
void main() {
    ivec2 size = textureSize(Scene, 0);
    float largest = 0.0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            vec3 v = texelFetch(Scene, ivec2(x, y), 0).rgb;
            largest = any(isnan(v)) || any(isinf(v)) ? 3.0e38 : max(largest, max(v.r, max(v.g, v.b)));
        }
    c = vec4()" + gateExpression + R"(, 0.0, 0.0, 1.0);
}
]]></shader></pass>
  <pass name="bright_pass" target="bright">)");
    replace(R"(<effect name="glow" passes="glow_pass" source="bright"/>)",
            R"(<effect name="glow" passes="glow_pass" source="bright" gate="gate" gate-channels="r"/>)");
    return xml;
}

// The CPU waits for the gate's answer here, so that it leaves out the passes itself.
class GatedGlowContentSkipGLTest : public GlowContentSkipGLTest {
protected:
    Skipped frameWith(const std::string& xml, glm::ivec2 pixel, float value, int kind = 0, bool sameImage = true) {
        return frameOf(xml, pixel, value, kind, Decision::CpuWaits, sameImage);
    }
};

TEST_F(GatedGlowContentSkipGLTest, TheGateDecidesAndTheBrightPassIsLeftOutWithTheEffect) {
    const std::string xml = glowWithAGate();
    const float justAbove = std::nextafter(1.0f, 2.0f);
    for (glm::ivec2 corner : {glm::ivec2(0, 0), glm::ivec2(36, 0), glm::ivec2(0, 22), glm::ivec2(36, 22)}) {
        SCOPED_TRACE("corner " + std::to_string(corner.x) + "," + std::to_string(corner.y));
        EXPECT_TRUE(frameWith(xml, corner, justAbove).empty());
        Skipped at = frameWith(xml, corner, 1.0f);
        ASSERT_EQ(at.count("glow"), 1u) << "exactly at the threshold the gate is 0";
        EXPECT_EQ(at.at("glow"), "its gate 'gate' holds no pixel with a non-zero red value, so its source 'bright' holds none either");
        // The bright pass and the glow pass, both left out by the CPU, which waited for the gate.
        EXPECT_EQ(on_->passesNotIssuedByContentSkip(), 2);
        EXPECT_EQ(on_->passesDrawnOnlyForEffects(), (std::map<std::string, std::set<std::string>>{{"bright_pass", {"glow"}}}));
    }
    EXPECT_TRUE(frameWith(xml, {18, 11}, 0.0f, 2).empty()) << "+Inf opens the gate";
    EXPECT_TRUE(frameWith(xml, {18, 11}, 0.0f, 1).empty()) << "NaN opens the gate";
}

// What the gate holds is what decides: a gate written as 0 whatever the scene holds skips the
// glow of a bright pixel, and the image then lacks it. (The mathematics of a gate is the
// workspace's, as a source's is; this test shows the gate is what content skip counts.)
TEST_F(GatedGlowContentSkipGLTest, AGateThatIsAlwaysZeroSkipsTheEffectEvenWhereTheSourceHoldsSomething) {
    Skipped skipped = frameWith(glowWithAGate("0.0 * largest"), {18, 11}, 3.0f, 0, false);
    EXPECT_EQ(skipped.count("glow"), 1u);
    Image a = readBack(*on_, "output"), b = readBack(*off_, "output");
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_NE(a.pixels, b.pixels) << "the glow of the bright pixel is missing where the gate says 0";
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

// The health check reports what the passes of a frame wrote: a pass content skip leaves out
// wrote nothing, though its target still holds what it wrote before (+Inf here, from a bright
// frame: spread_pass's target is read by no pass after the effect, so nothing clears it).
class ContentSkipHealthGLTest : public GlTest, public ::testing::WithParamInterface<HealthCheckMethod> {};

TEST_P(ContentSkipHealthGLTest, APassLeftOutIsReportedClean) {
    std::unique_ptr<Workspace> ws = workspaceFromText(glowWithAFeeder());
    ASSERT_TRUE(ws);
    for (Decision decision : {Decision::GpuOnly, Decision::CpuWaits}) {
        SCOPED_TRACE(decisionName(decision));
        ExecutorOptions options;
        options.outputs = {"output"};
        options.checkHealth = true;
        options.healthCheckMethod = GetParam();
        options.contentSkipDecision = decision;
        auto created = GlExecutor::create(std::make_shared<const Workspace>(*ws), {37, 23}, options);
        ASSERT_TRUE(created) << formatAll(created.diagnostics());
        GlExecutor& e = **created;
        auto infinitiesOf = [&](const std::string& pass) -> long long {
            const FrameHealth* health = e.frameHealth();
            if (!health) return -1;
            for (const PassHealth& p : health->passes)
                if (p.pass == pass) return p.counts[static_cast<size_t>(HealthKind::PositiveInfinity)];
            return -1;
        };
        ASSERT_TRUE(e.setVariable("Pixel_X", Value::ofInt(4)));
        ASSERT_TRUE(e.setVariable("Kind", Value::ofInt(2)));
        ASSERT_TRUE(e.renderFrame({0.0f, 1.0f / 24.0f}));
        EXPECT_TRUE(e.contentSkippedEffects().empty());
        EXPECT_EQ(infinitiesOf("spread_pass"), 1) << "bright: spread_pass copies the +Inf";
        EXPECT_EQ(infinitiesOf("glow_pass"), 6) << "the 3x2 pixels around it at the bottom edge";
        ASSERT_TRUE(e.setVariable("Kind", Value::ofInt(0)));
        ASSERT_TRUE(e.setVariable("Value", Value::ofFloat(0.5f)));
        ASSERT_TRUE(e.renderFrame({1.0f / 24.0f, 1.0f / 24.0f}));
        EXPECT_EQ(e.contentSkippedEffects().count("glow"), 1u);
        EXPECT_EQ(infinitiesOf("spread_pass"), 0) << "dim: spread_pass did not run";
        EXPECT_EQ(infinitiesOf("glow_pass"), 0);
        EXPECT_TRUE(e.frameHealth()->findings.empty());
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, ContentSkipHealthGLTest,
                         ::testing::Values(HealthCheckMethod::AfterPass, HealthCheckMethod::WhileDrawing),
                         [](const auto& info) { return info.param == HealthCheckMethod::AfterPass ? "AfterPass" : "WhileDrawing"; });

}  // namespace
}  // namespace rmfx::test
