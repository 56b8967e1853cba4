// rmfx render --check (gl/GlHealthCheck.h) by both methods, continued from HealthCheckGLTest.cpp:
// GLSL 3.30 passes, a target wholly of NaN, names that could clash with the counting code,
// HDRLighting as shipped, a lone NaN at every pixel, frames rendered without asking, the edges of
// each kind counted exactly, and the automatic choice of method.

#include <cmath>
#include <limits>
#include <optional>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "gl/GlExecutor.h"
#include "gl/SoftwareRasteriser.h"
#include "gl/Test/HealthCheckRuns.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class HealthCheckCasesGLTest : public GlTest, public ::testing::WithParamInterface<HealthCheckMethod> {};

INSTANTIATE_TEST_SUITE_P(Methods, HealthCheckCasesGLTest,
                         bothMethods(), methodName);

// A workspace of three passes around the pass a test is about: `ramp` writes each pixel's centre
// (gl_FragCoord.xy, 0, 1) into target 'a' of `rampFormat`; `pass`, a <pass> element, reads 'a' and
// writes 't' of `format`; `final` reads 't', so that it is drawn.
std::string aroundRamp(const std::string& rampFormat, const std::string& format, const std::string& pass) {
    return R"(<workspace version="1" name="ramp">
  <target name="a" format=")" + rampFormat + R"(" scale="1"/>
  <target name="t" format=")" + format + R"(" scale="1"/>
  <pass name="ramp" target="a"><shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() { fragColor = vec4(gl_FragCoord.xy, 0.0, 1.0); }
]]></shader></pass>
)" + pass + R"(
  <pass name="final"><sampler name="s" target="t"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D s;
out vec4 fragColor;
void main() { fragColor = texelFetch(s, ivec2(gl_FragCoord.xy), 0) * 0.0 + 0.5; }
]]></shader></pass>
</workspace>
)";
}

// GLSL 3.30, the oldest the counting code is added to, has no findLSB: the counting version of
// such a pass compiles and counts each kind of a pixel that holds four (NaN, -Inf, a negative and
// a value at half's largest), each with that pixel and the pass's input there.
TEST_P(HealthCheckCasesGLTest, AGlsl330PassCountsEachKindOfAPixelHoldingFour) {
    if (GetParam() != HealthCheckMethod::WhileDrawing) GTEST_SKIP() << "counting while drawing only";
    // The ramp and the final pass are GLSL 4.50; only "four" is 3.30.
    const std::string xml = aroundRamp("rgba32f", "rgba16f", R"(  <pass name="four" target="t"><sampler name="s" target="a" filter="nearest"/><shader stage="fragment"><![CDATA[
#version 330 core
uniform sampler2D s;
out vec4 fragColor;
void main() {
    vec4 r = texture(s, gl_FragCoord.xy / vec2(textureSize(s, 0)));
    fragColor = r.x == 1.5 && r.y == 0.5 ? vec4(uintBitsToFloat(0x7FC00000u), uintBitsToFloat(0xFF800000u), -2.0, 70000.0)
                                         : vec4(1.0);
}
]]></shader></pass>)");
    GlRun run = runChecked(workspaceFromText(xml), {3, 2}, 1, GetParam());
    ASSERT_TRUE(run.exec);
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    ASSERT_EQ(health->passes.size(), 3u);
    EXPECT_TRUE(health->passes[1].countedWhileDrawing) << health->passes[1].whyNotWhileDrawing;
    EXPECT_EQ(health->passes[1].counts, (std::array<long long, healthKindCount>{1, 0, 1, 1, 1}));
    ASSERT_EQ(health->findings.size(), 4u);
    for (const HealthFinding& f : health->findings) {
        EXPECT_EQ(f.pass, "four");
        EXPECT_EQ(f.pixel, glm::ivec2(1, 1)) << "GL's row 0 is the bottom one of two";
        ASSERT_EQ(f.inputs.size(), 1u);
        EXPECT_EQ(f.inputs[0].second, glm::vec4(1.5f, 0.5f, 0.0f, 1.0f));
    }
}

// Every pixel of a 256x256 target NaN: the first pixel's value and inputs are kept although
// thousands of fragments race to lower it (counted from the top, llvmpipe used up every record
// slot: gl/HealthBuffer.h).
TEST_P(HealthCheckCasesGLTest, TheFirstPixelOfAWholeTargetOfNanIsRecorded) {
    const std::string xml = aroundRamp("rgba16f", "rgba32f", R"(  <pass name="poison" target="t"><sampler name="s" target="a"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D s;
out vec4 fragColor;
void main() { fragColor = vec4(uintBitsToFloat(0x7fc00000u), texelFetch(s, ivec2(gl_FragCoord.xy), 0).xy, 1.0); }
]]></shader></pass>)");
    GlRun run = runChecked(workspaceFromText(xml), {256, 256}, 1, GetParam());
    ASSERT_TRUE(run.exec) ;
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    ASSERT_FALSE(health->findings.empty());
    const HealthFinding& f = health->findings.front();
    EXPECT_EQ(f.kind, HealthKind::NaN);
    EXPECT_EQ(f.count, 256 * 256);
    EXPECT_EQ(f.pixel, glm::ivec2(0, 255));  // the bottom row's first, GL's (0.5, 0.5)
    ASSERT_TRUE(f.recorded) << describeFinding(f);
    EXPECT_EQ(f.value.y, 0.5f);
    EXPECT_EQ(f.value.z, 0.5f);
    ASSERT_EQ(f.inputs.size(), 1u);
    EXPECT_EQ(f.inputs[0].second, glm::vec4(0.5f, 0.5f, 0.0f, 1.0f));
}

// The code added to a pass names nothing a shader could: a sampler called `size` and an output
// called `written` (names the added code once used for its own) still count while drawing, and
// the input is recorded.
TEST_P(HealthCheckCasesGLTest, NamesInThePassDoNotClashWithTheCountingCode) {
    const std::string xml = aroundRamp("rgba32f", "rgba32f", R"(  <pass name="poison" target="t"><sampler name="size" target="a" filter="nearest"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D size;
out vec4 written;
void main() {
    vec4 record = texelFetch(size, ivec2(gl_FragCoord.xy), 0);
    written = vec4(record.x > 2.0 ? uintBitsToFloat(0x7fc00000u) : 0.0, record.yzw);
}
]]></shader></pass>)");
    GlRun run = runChecked(workspaceFromText(xml), {5, 3}, 1, GetParam());
    ASSERT_TRUE(run.exec);
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    EXPECT_EQ(health->passes[1].countedWhileDrawing, GetParam() == HealthCheckMethod::WhileDrawing);
    ASSERT_EQ(health->findings.size(), 1u);
    const HealthFinding& f = health->findings.front();
    EXPECT_EQ(f.count, 3 * 3);  // columns 2 to 4 (centres 2.5 to 4.5 are above 2)
    EXPECT_EQ(f.pixel, glm::ivec2(2, 2));  // the bottom row's first
    ASSERT_EQ(f.inputs.size(), 1u);
    EXPECT_EQ(f.inputs[0].first, "size → target 'a'");
    EXPECT_EQ(f.inputs[0].second, glm::vec4(2.5f, 0.5f, 0.0f, 1.0f));
}

// The effects as shipped: HDRLighting over 3 frames keeps every inspected target finite.
TEST_P(HealthCheckCasesGLTest, HdrLightingAsShippedHasNoNanOrInfinity) {
    GlRun run = runChecked(effectWorkspace("hdr_lighting.xml"), {96, 64}, 3, GetParam());
    ASSERT_TRUE(run.exec);
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    EXPECT_GT(health->passes.size(), 20u);
    if (GetParam() == HealthCheckMethod::WhileDrawing) {  // every pass of it can count its own writes
        for (const PassHealth& p : health->passes) EXPECT_TRUE(p.countedWhileDrawing) << p.pass;
    }
    for (const HealthFinding& f : run.exec->firstHealthFindings())
        EXPECT_FALSE(healthKindIsError(f.kind)) << describeFinding(f);
}

// A NaN alone at each pixel of an odd-sized target in turn is found there, once (the check after a
// pass screens the target a few pixels a fragment before it counts), with its value.
// A 5x3 rgba32f target that pass "lone" fills with 0.5, but for a NaN (in green) at the pixel
// (At_X, At_Y) in GL's rows; an executor running it with the check by `method`.
std::unique_ptr<GlExecutor> loneNanExecutor(HealthCheckMethod method) {
    std::unique_ptr<Workspace> ws = workspaceFromText(R"(<workspace version="1" name="lone" size="5x3">
  <int name="At_X" value="0"/>
  <int name="At_Y" value="0"/>
  <target name="t" format="rgba32f"/>
  <pass name="lone" target="t"><shader stage="fragment"><![CDATA[
#version 450 core
uniform int At_X;
uniform int At_Y;
out vec4 c;
void main() { c = ivec2(gl_FragCoord.xy) == ivec2(At_X, At_Y) ? vec4(0.5, uintBitsToFloat(0x7fc00000u), 0.5, 1.0) : vec4(0.5); }
]]></shader></pass>
  <pass name="final"><sampler name="T" target="t" filter="nearest"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D T;
out vec4 c;
void main() { c = vec4(texelFetch(T, ivec2(gl_FragCoord.xy), 0).r); }
]]></shader></pass>
  <output format="rgba32f" transform="none"/>
</workspace>
)");
    if (!ws) return nullptr;
    ExecutorOptions options;
    options.checkHealth = true;
    options.healthCheckMethod = method;
    auto created = GlExecutor::create(std::make_shared<const Workspace>(*ws), {5, 3}, options);
    if (!created) ADD_FAILURE() << formatAll(created.diagnostics());
    return created ? std::move(*created) : nullptr;
}

TEST_P(HealthCheckCasesGLTest, ALoneNanIsFoundAtEveryPixel) {
    std::unique_ptr<GlExecutor> executor = loneNanExecutor(GetParam());
    ASSERT_TRUE(executor);
    GlExecutor& e = *executor;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x) {
            ASSERT_TRUE(e.setVariable("At_X", Value::ofInt(x)));
            ASSERT_TRUE(e.setVariable("At_Y", Value::ofInt(y)));
            ASSERT_TRUE(e.renderFrame({0.0f, 1.0f / 60.0f}));
            const FrameHealth* health = e.frameHealth();
            ASSERT_TRUE(health);
            ASSERT_EQ(health->findings.size(), 1u) << x << "," << y;
            const HealthFinding& f = health->findings.front();
            EXPECT_EQ(f.kind, HealthKind::NaN);
            EXPECT_EQ(f.pass, "lone");
            EXPECT_EQ(f.count, 1) << x << "," << y;
            EXPECT_EQ(f.pixel, glm::ivec2(x, 3 - 1 - y)) << "reading coordinates";
            // Recorded afresh each frame, though the frames take turns with the same buffers.
            ASSERT_TRUE(f.recorded) << x << "," << y;
            EXPECT_EQ(f.value.x, 0.5f);
            EXPECT_TRUE(std::isnan(f.value.y));
            EXPECT_EQ(f.value.z, 0.5f);
            EXPECT_EQ(f.value.w, 1.0f);
        }
}

// Each frame's results come back after it (a buffer of its own while it is in flight): frames
// rendered without asking are still each judged by what that frame drew. Frames 0 to 2 are
// clean, frame 3 has a NaN at (1, 2) in GL's rows, frames 4 to 8 at (4, 0).
TEST_P(HealthCheckCasesGLTest, FramesRenderedWithoutAskingAreEachJudgedByTheirOwnDraws) {
    std::unique_ptr<GlExecutor> executor = loneNanExecutor(GetParam());
    ASSERT_TRUE(executor);
    GlExecutor& e = *executor;
    for (int frame = 0; frame < 9; ++frame) {
        const glm::ivec2 at = frame < 3 ? glm::ivec2(-1, 0) : frame == 3 ? glm::ivec2(1, 2) : glm::ivec2(4, 0);
        ASSERT_TRUE(e.setVariable("At_X", Value::ofInt(at.x)));
        ASSERT_TRUE(e.setVariable("At_Y", Value::ofInt(at.y)));
        ASSERT_TRUE(e.renderFrame({static_cast<float>(frame) / 60.0f, 1.0f / 60.0f}));
        if (const FrameHealth* soFar = e.frameHealth(false)) {  // what is in: never a frame not yet drawn
            EXPECT_LE(soFar->findings.empty() ? 0 : soFar->findings.front().frame, frame);
        }
    }
    const std::vector<HealthFinding>& first = e.firstHealthFindings();
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first.front().frame, 3);
    EXPECT_EQ(first.front().pass, "lone");
    EXPECT_EQ(first.front().count, 1);
    EXPECT_EQ(first.front().pixel, glm::ivec2(1, 0)) << "reading coordinates";
    const FrameHealth* last = e.frameHealth();
    ASSERT_TRUE(last);
    ASSERT_EQ(last->findings.size(), 1u);
    EXPECT_EQ(last->findings.front().frame, 8);
    EXPECT_EQ(last->findings.front().pixel, glm::ivec2(4, 2));
    // Once the GPU has finished a frame, asking without waiting gives that frame.
    ASSERT_TRUE(e.setVariable("At_X", Value::ofInt(-1)));
    ASSERT_TRUE(e.renderFrame({9.0f / 60.0f, 1.0f / 60.0f}));
    glFinish();
    const FrameHealth* finished = e.frameHealth(false);
    ASSERT_TRUE(finished);
    EXPECT_TRUE(finished->findings.empty()) << "frame 9 is clean";
}

// What lies just inside and just outside each kind, each value alone in a target of its own (the
// check after a pass first screens the whole target, and counts only in one where the screen let
// something through: a finding elsewhere in the same target would hide a screen that missed it).
// In 32-bit floats -0, the largest finite value and 1 are no finding, -FLT_MAX is negative; in
// halves 65472 (the value below the largest) is none, 65504 and -65504 are at the largest.
TEST_P(HealthCheckCasesGLTest, TheEdgesOfEachKindAreCountedExactly) {
    struct Edge {
        const char* name;
        const char* format;
        const char* value;  // GLSL
        std::array<long long, healthKindCount> kinds;  // per pixel: NaN, +Inf, -Inf, negative, at the largest
    };
    const Edge edges[] = {
        {"minus_zero", "rgba32f", "uintBitsToFloat(0x80000000u)", {0, 0, 0, 0, 0}},
        {"float_max", "rgba32f", "uintBitsToFloat(0x7f7fffffu)", {0, 0, 0, 0, 0}},
        {"minus_float_max", "rgba32f", "uintBitsToFloat(0xff7fffffu)", {0, 0, 0, 1, 0}},
        {"infinity", "rgba32f", "uintBitsToFloat(0x7f800000u)", {0, 1, 0, 0, 0}},
        {"minus_infinity", "rgba32f", "uintBitsToFloat(0xff800000u)", {0, 0, 1, 0, 0}},
        {"nan", "rgba32f", "uintBitsToFloat(0x7fc00000u)", {1, 0, 0, 0, 0}},
        {"one", "rgba32f", "1.0", {0, 0, 0, 0, 0}},
        {"half_max", "rgba16f", "65504.0", {0, 0, 0, 0, 1}},
        {"below_half_max", "rgba16f", "65472.0", {0, 0, 0, 0, 0}},
        {"minus_half_max", "rgba16f", "-65504.0", {0, 0, 0, 1, 1}},
    };
    std::string xml = R"(<workspace version="1" name="edges" size="3x2">)";
    std::string samplers, declarations, sum;
    for (const Edge& e : edges) {
        xml += std::string("<target name=\"") + e.name + "\" format=\"" + e.format + "\"/>\n";
        xml += std::string("<pass name=\"") + e.name + "\" target=\"" + e.name +
               "\"><shader stage=\"fragment\"><![CDATA[\n#version 450 core\nout vec4 c;\nvoid main() { c = vec4(" + e.value +
               ", 0.0, 0.0, 1.0); }\n]]></shader></pass>\n";
        samplers += std::string("<sampler name=\"S_") + e.name + "\" target=\"" + e.name + "\" filter=\"nearest\"/>";
        declarations += std::string("uniform sampler2D S_") + e.name + ";\n";
        sum += std::string(" + texelFetch(S_") + e.name + ", ivec2(0), 0)";
    }
    xml += "<pass name=\"final\">" + samplers + "<shader stage=\"fragment\"><![CDATA[\n#version 450 core\n" + declarations +
           "out vec4 c;\nvoid main() { c = vec4(0.0)" + sum + "; c = vec4(c.g, 0.0, 0.0, 1.0); }\n]]></shader></pass>\n";
    xml += R"(<output format="rgba32f" transform="none"/></workspace>)";
    std::unique_ptr<Workspace> ws = workspaceFromText(xml);
    ASSERT_TRUE(ws);
    GlRun run = runChecked(std::move(ws), {3, 2}, 1, GetParam());
    ASSERT_TRUE(run.exec);
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    std::map<std::string, std::array<long long, healthKindCount>> counts;
    for (const PassHealth& p : health->passes) counts[p.pass] = p.counts;
    for (const Edge& e : edges) {
        std::array<long long, healthKindCount> expected = e.kinds;
        for (long long& k : expected) k *= 3 * 2;
        EXPECT_EQ(counts[e.name], expected) << e.name << " in " << e.format;
    }
    EXPECT_EQ(counts["final"], (std::array<long long, healthKindCount>{}));
}

// auto: on a GPU every pass that can counts what it writes (a pass that blends is inspected after
// it ran); on a software rasteriser a pass whose neighbour writes the same target ('first', before
// 'second') or that records at most two inputs ('use'), and the others ('final', three inputs) are
// inspected after they ran. Both ways in one frame: 'first' writes 1 and a NaN into 't', onto
// which 'second' adds -2.
class HealthCheckAutomaticGLTest : public GlTest {};

TEST_F(HealthCheckAutomaticGLTest, ASoftwareRasteriserCountsWhileDrawingWherePassesShareATargetOrHaveFewInputsAGpuWhereverItCan) {
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const bool software = currentContextIsSoftwareRasteriser();
    std::unique_ptr<Workspace> ws = workspaceFromText(R"(<workspace version="1" name="auto" size="9x7">
  <target name="t" format="rgba32f"/>
  <target name="u" format="rgba32f"/>
  <pass name="first" target="t"><shader stage="fragment"><![CDATA[
#version 450 core
out vec4 c;
void main() { float zero = gl_FragCoord.x - gl_FragCoord.x; c = ivec2(gl_FragCoord.xy) == ivec2(2, 3) ? vec4(zero / zero) : vec4(1.0); }
]]></shader></pass>
  <pass name="second" target="t"><blend mode="add"/><shader stage="fragment"><![CDATA[
#version 450 core
out vec4 c;
void main() { c = vec4(-2.0, 0.0, 0.0, 0.0); }
]]></shader></pass>
  <pass name="use" target="u"><sampler name="T" target="t" filter="nearest"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D T;
out vec4 c;
void main() { c = abs(texelFetch(T, ivec2(gl_FragCoord.xy), 0)); }
]]></shader></pass>
  <pass name="final"><sampler name="U" target="u" filter="nearest"/><sampler name="T" target="t" filter="nearest"/>
    <sampler name="V" target="u" filter="nearest"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D U;
uniform sampler2D T;
uniform sampler2D V;
out vec4 c;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    c = texelFetch(U, p, 0) + 0.5 * texelFetch(T, p, 0) + 0.25 * texelFetch(V, p, 0);
}
]]></shader></pass>
  <output format="rgba32f" transform="none"/>
</workspace>
)");
    ASSERT_TRUE(ws);
    GlRun run = runChecked(std::move(ws), {9, 7}, 1, HealthCheckMethod::Automatic);
    ASSERT_TRUE(run.exec);
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    std::map<std::string, bool> counted;
    for (const PassHealth& p : health->passes) counted[p.pass] = p.countedWhileDrawing;
    if (software) {
        EXPECT_EQ(counted, (std::map<std::string, bool>{{"first", true}, {"second", false}, {"use", true}, {"final", false}}))
            << renderer;
    } else {
        EXPECT_EQ(counted, (std::map<std::string, bool>{{"first", true}, {"second", false}, {"use", true}, {"final", true}}))
            << renderer;
    }
    ASSERT_EQ(health->findings.size(), 2u);
    EXPECT_EQ(health->findings[0].kind, HealthKind::NaN);
    EXPECT_EQ(health->findings[0].pass, "first");
    EXPECT_EQ(health->findings[0].count, 1);
    EXPECT_EQ(health->findings[0].pixel, glm::ivec2(2, 7 - 1 - 3));
    EXPECT_EQ(health->findings[1].kind, HealthKind::Negative);
    EXPECT_EQ(health->findings[1].pass, "second");
    EXPECT_EQ(health->findings[1].count, 9 * 7 - 1) << "every pixel but the NaN";
}
}  // namespace
}  // namespace rmfx::test
