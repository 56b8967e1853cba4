// <effect source> on a small glow workspace, continued from ContentSkipGLTest.cpp: a pixel just
// above the threshold anywhere keeps the effect, NaN and infinity count as the shaders treat them,
// the pass reading a skipped effect is drawn compiled without it, feeders are skipped with it,
// what it hands on is cleared only where something reads it, a gate decides in the source's
// place, and the health check reports a pass left out as clean. Each frame is compared byte for
// byte with content skip off.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "gl/GlExecutor.h"
#include "gl/Test/ContentSkipRuns.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

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
