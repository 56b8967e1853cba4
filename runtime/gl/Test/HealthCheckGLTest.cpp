// rmfx render --check (gl/GlHealthCheck.h), by both methods: each target inspected after its
// pass, and the passes counting what they write (gl/HealthInstrumentation.h). A workspace written
// to produce each kind (NaN, ±Inf, negatives, half's largest value) is checked on the GPU, and
// every pass's count of each kind, the first pass of each kind, its first pixel, value and inputs
// equal a float64 evaluation of the same shader maths. A NaN alone in the last pixel of odd-sized
// targets is found there; normalised targets are reported as not inspected; passes that blend or
// discard behind a depth test are inspected after they ran. HealthCheckCasesGLTest.cpp goes on.

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

class HealthCheckGLTest : public GlTest, public ::testing::WithParamInterface<HealthCheckMethod> {};

INSTANTIATE_TEST_SUITE_P(Methods, HealthCheckGLTest,
                         bothMethods(), methodName);

constexpr int kWidth = 17, kHeight = 9;

// gradient: (x, y > 7 ? 65504 : 1, 0.5, 1) in half floats, x and y pixel centres from the bottom;
// divide: (log(x - 3.5) (NaN below 0, -Inf at 0), 1 / (x - 5.5), -0.5, 1) in 32-bit floats, reading
// gradient; show copies
// divide into an 8-bit target, which cannot hold any of it; final copies show.
const char* const kProblemWorkspace = R"(<workspace version="1" name="problems" size="17x9">
  <target name="base" format="rgba16f" scale="1"/>
  <target name="dark" format="rgba32f" scale="1"/>
  <target name="ldr" format="rgba8" scale="1"/>
  <pass name="gradient" target="base">
    <shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() { fragColor = vec4(gl_FragCoord.x, gl_FragCoord.y > 7.0 ? 65504.0 : 1.0, 0.5, 1.0); }
]]></shader>
  </pass>
  <pass name="divide" target="dark">
    <sampler name="src" target="base" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D src;
out vec4 fragColor;
void main() {
    vec4 s = texelFetch(src, ivec2(gl_FragCoord.xy), 0);
    float zero = s.w - 1.0, z = s.x - 3.5;  // GLSL leaves log of 0 and below undefined: spelled out
    fragColor = vec4(z < 0.0 ? zero / zero : z == 0.0 ? -1.0 / zero : log(z), 1.0 / (s.x - 5.5), -s.z, s.w);
}
]]></shader>
  </pass>
  <pass name="show" target="ldr">
    <sampler name="a" target="dark" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D a;
out vec4 fragColor;
void main() { fragColor = texelFetch(a, ivec2(gl_FragCoord.xy), 0); }
]]></shader>
  </pass>
  <pass name="final">
    <sampler name="b" target="ldr" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D b;
out vec4 fragColor;
void main() { fragColor = texelFetch(b, ivec2(gl_FragCoord.xy), 0); }
]]></shader>
  </pass>
</workspace>
)";

// The kinds a texel holds, as the check defines them for a format.
std::array<bool, healthKindCount> kindsOf(const glm::dvec4& v, const FormatHealthLimits& limits) {
    std::array<bool, healthKindCount> kinds{};
    for (int c = 0; c < limits.channels; ++c) {
        const double x = v[c];
        if (std::isnan(x)) kinds[0] = true;
        else if (std::isinf(x)) kinds[x > 0 ? 1 : 2] = true;
        else {
            if (limits.holdsNegatives && x < 0) kinds[3] = true;
            if (limits.largest[c] > 0 && std::abs(x) >= limits.largest[c]) kinds[4] = true;
        }
    }
    return kinds;
}

// What a pass wrote, evaluated in float64; row 0 at the top (reading order), as the check reports.
struct Written {
    std::vector<glm::dvec4> texels;  // kWidth * kHeight, reading order
    glm::dvec4 at(int x, int y) const { return texels[static_cast<size_t>(y * kWidth + x)]; }
};

Written gradient() {
    Written w;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double fragY = (kHeight - 1 - y) + 0.5;
            w.texels.push_back({x + 0.5, fragY > 7.0 ? 65504.0 : 1.0, 0.5, 1.0});
        }
    return w;
}

Written divide(const Written& base) {
    Written w;
    for (const glm::dvec4& s : base.texels) {
        const double z = s.x - 3.5;
        const double logZ = z < 0 ? std::numeric_limits<double>::quiet_NaN() : std::log(z);  // log(0) = -inf
        w.texels.push_back({logZ, 1.0 / (s.x - 5.5), -s.z, s.w});
    }
    return w;
}

TEST_P(HealthCheckGLTest, EveryPassesCountsAndTheFirstOfEachKindMatchAFloat64Evaluation) {
    GlRun run = runChecked(workspaceFromText(kProblemWorkspace), {kWidth, kHeight}, 1, GetParam());
    ASSERT_TRUE(run.exec);
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    ASSERT_EQ(health->passes.size(), 4u);

    const Written base = gradient(), dark = divide(base);
    const std::vector<std::pair<const Written*, TargetFormat>> expected{{&base, TargetFormat::RGBA16F},
                                                                        {&dark, TargetFormat::RGBA32F}};
    std::array<std::optional<std::pair<int, glm::ivec2>>, healthKindCount> firsts;  // pass position, pixel
    for (size_t p = 0; p < expected.size(); ++p) {
        const auto& [written, format] = expected[p];
        std::array<long long, healthKindCount> counts{};
        for (int y = kHeight - 1; y >= 0; --y)  // the check's order: the bottom row first
            for (int x = 0; x < kWidth; ++x) {
                auto kinds = kindsOf(written->at(x, y), formatHealthLimits(format));
                for (int k = 0; k < healthKindCount; ++k) {
                    if (!kinds[static_cast<size_t>(k)]) continue;
                    ++counts[static_cast<size_t>(k)];
                    if (!firsts[static_cast<size_t>(k)]) firsts[static_cast<size_t>(k)] = {{static_cast<int>(p), {x, y}}};
                }
            }
        EXPECT_TRUE(health->passes[p].inspected);
        EXPECT_EQ(health->passes[p].countedWhileDrawing, GetParam() == HealthCheckMethod::WhileDrawing);
        EXPECT_EQ(health->passes[p].counts, counts) << health->passes[p].pass;
    }
    // The maths gives every kind somewhere (3 columns of NaN, one of each infinity, …).
    for (const auto& f : firsts) ASSERT_TRUE(f.has_value());
    EXPECT_EQ(health->passes[0].pass, "gradient");
    EXPECT_EQ(health->passes[1].target, "dark");
    EXPECT_FALSE(health->passes[2].inspected) << "rgba8 clamps what is written";
    EXPECT_TRUE(health->passes[3].inspected);
    EXPECT_EQ(health->passes[3].counts, (std::array<long long, healthKindCount>{}));

    ASSERT_EQ(health->findings.size(), static_cast<size_t>(healthKindCount));
    for (const HealthFinding& f : health->findings) {
        SCOPED_TRACE(healthKindName(f.kind));
        const auto& [position, pixel] = *firsts[static_cast<size_t>(f.kind)];
        const Written& written = *expected[static_cast<size_t>(position)].first;
        EXPECT_EQ(f.pass, health->passes[static_cast<size_t>(position)].pass);
        EXPECT_EQ(f.frame, 0);
        EXPECT_EQ(f.pixel, pixel);
        EXPECT_EQ(f.count, health->passes[static_cast<size_t>(position)].counts[static_cast<size_t>(f.kind)]);
        for (int c = 0; c < 4; ++c) {
            const double want = written.at(pixel.x, pixel.y)[c];
            if (std::isnan(want)) EXPECT_TRUE(std::isnan(f.value[c])) << c;
            else if (std::isinf(want)) EXPECT_EQ(f.value[c], want) << c;
            else EXPECT_NEAR(f.value[c], want, 1e-6 * std::max(1.0, std::abs(want))) << c;
        }
        if (position == 0) {
            EXPECT_TRUE(f.inputs.empty());
            continue;
        }
        ASSERT_EQ(f.inputs.size(), 1u);
        EXPECT_EQ(f.inputs[0].first, "src → target 'base'");
        for (int c = 0; c < 4; ++c) EXPECT_EQ(f.inputs[0].second[c], base.at(pixel.x, pixel.y)[c]) << c;
    }
    EXPECT_EQ(describeFinding(health->findings[0]),
              "pass 'divide' wrote NaN into target 'dark' (27 pixels; first at x=0 y=8: (nan, -0.2, -0.5, 1); there the "
              "inputs held: src → target 'base' (0.5, 1, 0.5, 1))");
    EXPECT_EQ(run.exec->firstHealthFindings().size(), static_cast<size_t>(healthKindCount));
}

// A single NaN in the last pixel of the last row (reading order) of targets whose sizes leave
// partial 8x8 groups, and in 1x1.
TEST_P(HealthCheckGLTest, ANanInTheLastPixelOfOddSizesIsFoundThere) {
    for (glm::ivec2 size : {glm::ivec2(17, 9), glm::ivec2(1, 1), glm::ivec2(33, 2), glm::ivec2(3, 41)}) {
        SCOPED_TRACE(std::to_string(size.x) + "x" + std::to_string(size.y));
        const std::string xml = R"(<workspace version="1" name="corner">
  <target name="t" format="r16f" scale="1"/>
  <pass name="corner" target="t">
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform vec2 rm_InvTargetSize;
out vec4 fragColor;
void main() {
    bool last = gl_FragCoord.x * rm_InvTargetSize.x > 1.0 - rm_InvTargetSize.x && gl_FragCoord.y < 1.0;
    // A quiet NaN by its bits: NVIDIA's compiler does not keep 0.0 / 0.0 a NaN.
    fragColor = vec4(last ? uintBitsToFloat(0x7fc00000u) : 0.25, 0.0, 0.0, 1.0);
}
]]></shader>
  </pass>
  <pass name="final"><sampler name="s" target="t"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D s;
out vec4 fragColor;
void main() { fragColor = vec4(texelFetch(s, ivec2(gl_FragCoord.xy), 0).rrr * 0.0, 1.0); }
]]></shader></pass>
</workspace>
)";
        GlRun run = runChecked(workspaceFromText(xml), size, 1, GetParam());
        ASSERT_TRUE(run.exec);
        const FrameHealth* health = run.exec->frameHealth();
        ASSERT_TRUE(health);
        ASSERT_EQ(health->findings.size(), 1u);
        const HealthFinding& f = health->findings.front();
        EXPECT_EQ(f.kind, HealthKind::NaN);
        EXPECT_EQ(f.pass, "corner");
        EXPECT_EQ(f.count, 1);
        EXPECT_EQ(f.pixel, glm::ivec2(size.x - 1, size.y - 1));
        EXPECT_TRUE(std::isnan(f.value.x));
    }
}

// The last pass of a test workspace and its end: shows `target` as the output.
std::string finalShowing(const std::string& target) {
    return R"(  <pass name="final"><sampler name="s" target=")" + target + R"("/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D s;
out vec4 fragColor;
void main() { fragColor = texelFetch(s, ivec2(gl_FragCoord.xy), 0); }
]]></shader></pass>
</workspace>
)";
}

// The inspections wait for memory to be written again: a target that holds NaN after its first
// pass and is overwritten clean later in the frame is reported for that first pass, with the
// value it held then, and the pass that read it sees its NaN input.
TEST_P(HealthCheckGLTest, ATargetOverwrittenLaterInTheFrameIsReportedAsItsFirstPassLeftIt) {
    const std::string xml = R"(<workspace version="1" name="overwrite">
  <target name="t" format="rgba32f" scale="1"/>
  <target name="u" format="rgba32f" scale="1"/>
  <pass name="poison" target="t"><shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() {
    fragColor = vec4(uintBitsToFloat(0x7fc00000u), 2.0, 3.0, 4.0);
}
]]></shader></pass>
  <pass name="copy" target="u"><sampler name="s" target="t"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D s;
out vec4 fragColor;
void main() { fragColor = vec4(0.5, texelFetch(s, ivec2(gl_FragCoord.xy), 0).gba); }
]]></shader></pass>
  <pass name="clean" target="t"><sampler name="s" target="u"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D s;
out vec4 fragColor;
void main() { fragColor = texelFetch(s, ivec2(gl_FragCoord.xy), 0) * 2.0; }
]]></shader></pass>
)" + finalShowing("t");
    const glm::ivec2 size{7, 5};
    GlRun run = runChecked(workspaceFromText(xml), size, 1, GetParam());
    ASSERT_TRUE(run.exec);
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    ASSERT_EQ(health->passes.size(), 4u);
    EXPECT_EQ(health->passes[0].counts[0], size.x * size.y) << "poison";
    EXPECT_EQ(health->passes[2].counts[0], 0) << "clean: t overwritten";
    ASSERT_EQ(health->findings.size(), 1u);
    const HealthFinding& f = health->findings.front();
    EXPECT_EQ(f.kind, HealthKind::NaN);
    EXPECT_EQ(f.pass, "poison");
    EXPECT_EQ(f.pixel, glm::ivec2(0, size.y - 1));  // the bottom row's first
    EXPECT_TRUE(std::isnan(f.value.x));
    EXPECT_EQ(f.value.y, 2.0f);
    EXPECT_EQ(f.value.w, 4.0f);
    EXPECT_TRUE(f.inputs.empty());
}

// A mesh drawn over what its target held (no colour clear) covers only some of it: counting while
// drawing, its counts are of the pixels it drew (PassHealth::ownPixelsOnly), and the NaN the pass
// before it left elsewhere is not its; inspected after it ran, the whole target is. Either way the
// frame's first NaN is poison's.
TEST_P(HealthCheckGLTest, AMeshDrawnOverATargetCountsWhatItDrewWhileDrawing) {
    const std::string xml = R"(<workspace version="1" name="patch">
  <target name="t" format="rgba32f" scale="1"/>
  <pass name="poison" target="t"><shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() { fragColor = vec4(uintBitsToFloat(0x7fc00000u), 0.0, 0.0, 1.0); }
]]></shader></pass>
  <pass name="patch" target="t"><draw mesh="quad"/><shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() { fragColor = vec4(0.5, 0.5, 0.5, 1.0); }
]]></shader></pass>
)" + finalShowing("t");
    const glm::ivec2 size{16, 16};
    GlRun run = runChecked(workspaceFromText(xml), size, 1, GetParam());
    ASSERT_TRUE(run.exec);
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    ASSERT_EQ(health->passes.size(), 3u);
    Result<Image> t = run.exec->readTarget("t");
    ASSERT_TRUE(t);
    long long nan = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) nan += std::isnan(t->at(x, y, 0)) ? 1 : 0;
    ASSERT_GT(nan, 0) << "the quad covers the whole target: the test needs it not to";
    ASSERT_LT(nan, size.x * size.y) << "the quad covers nothing";
    const bool whileDrawing = GetParam() == HealthCheckMethod::WhileDrawing;
    EXPECT_FALSE(health->passes[0].ownPixelsOnly) << "a full-screen pass replaces its target";
    EXPECT_EQ(health->passes[1].countedWhileDrawing, whileDrawing);
    EXPECT_EQ(health->passes[1].ownPixelsOnly, whileDrawing);
    EXPECT_EQ(health->passes[0].counts[0], size.x * size.y);
    EXPECT_EQ(health->passes[1].counts[0], whileDrawing ? 0 : nan);
    ASSERT_EQ(health->findings.size(), 1u);
    EXPECT_EQ(health->findings[0].pass, "poison");
}

// What a pass that blends leaves is not what its shader wrote, and a shader that discards behind a
// depth test cannot let the test run first: both are inspected after they ran, by either method.
// base holds -3; blend adds 1 (the target then holds -2: negative); cut writes 0.25 where it does
// not discard, behind a depth test that always passes.
TEST_P(HealthCheckGLTest, PassesThatBlendOrDiscardBehindADepthTestAreInspectedAfterTheyRan) {
    const std::string xml = R"(<workspace version="1" name="blend">
  <target name="t" format="rgba32f" scale="1"/>
  <target name="u" format="rgba32f" scale="1"/>
  <pass name="base" target="t"><shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() { fragColor = vec4(-3.0, 0.0, 0.0, 1.0); }
]]></shader></pass>
  <pass name="blend" target="t"><blend mode="add"/><shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() { fragColor = vec4(1.0, 0.0, 0.0, 0.0); }
]]></shader></pass>
  <pass name="cut" target="u"><clear color="0 0 0 1" depth="1"/><depth test="always"/><sampler name="s" target="t"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D s;
out vec4 fragColor;
void main() {
    if (gl_FragCoord.x < 2.0) discard;
    fragColor = vec4(texelFetch(s, ivec2(gl_FragCoord.xy), 0).x, 0.25, 0.0, 1.0);
}
]]></shader></pass>
)" + finalShowing("u");
    const glm::ivec2 size{5, 3};
    GlRun run = runChecked(workspaceFromText(xml), size, 1, GetParam());
    ASSERT_TRUE(run.exec) ;
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    ASSERT_EQ(health->passes.size(), 4u);
    const bool whileDrawing = GetParam() == HealthCheckMethod::WhileDrawing;
    EXPECT_EQ(health->passes[0].countedWhileDrawing, whileDrawing);
    EXPECT_FALSE(health->passes[1].countedWhileDrawing);
    EXPECT_FALSE(health->passes[2].countedWhileDrawing);
    EXPECT_EQ(health->passes[1].whyNotWhileDrawing, whileDrawing ? "it blends onto its target" : "");
    EXPECT_EQ(health->passes[2].whyNotWhileDrawing,
              whileDrawing ? "it tests depth and its fragment shader discards or writes gl_FragDepth" : "");
    EXPECT_EQ(health->passes[3].countedWhileDrawing, whileDrawing);
    const int negative = static_cast<int>(HealthKind::Negative);
    EXPECT_EQ(health->passes[0].counts[negative], size.x * size.y);
    EXPECT_EQ(health->passes[1].counts[negative], size.x * size.y) << "-3 + 1: still negative";
    // cut left its two discarded columns cleared (0) and wrote -2 in the other three.
    EXPECT_EQ(health->passes[2].counts[negative], 3 * size.y);
    ASSERT_EQ(health->findings.size(), 1u);
    EXPECT_EQ(health->findings[0].pass, "base");
    EXPECT_EQ(health->findings[0].value, glm::vec4(-3.0f, 0.0f, 0.0f, 1.0f));
}

// Counting while drawing sees the value the shader wrote, before the format rounds it: a half
// target given 70000 (stored as 65504 or as +Inf, by the GPU) and 65490 (rounds to 65504) is at
// its largest there; 65480 rounds to 65472 and is not; -1e-8 rounds to -0 and is not negative.
// At the edge, 65488 (halfway, rounds to the even 65472) is not and the float after it is: the
// screen before the kinds (HealthInstrumentation's screenBelow) lets that float through.
TEST_P(HealthCheckGLTest, AHalfTargetIsJudgedByWhatItsFormatMakesOfTheWrittenValue) {
    if (GetParam() != HealthCheckMethod::WhileDrawing) GTEST_SKIP() << "the stored value is what after-pass sees";
    const std::string xml = R"(<workspace version="1" name="half">
  <target name="h" format="rgba16f" scale="1"/>
  <pass name="big" target="h"><shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() {
    float x = gl_FragCoord.x < 1.0 ? 70000.0 : gl_FragCoord.x < 2.0 ? 65490.0 : gl_FragCoord.x < 3.0 ? 65480.0
            : gl_FragCoord.x < 4.0 ? uintBitsToFloat(0x477FD000u) : uintBitsToFloat(0x477FD001u);
    fragColor = vec4(x, gl_FragCoord.x < 3.0 ? -1e-8 : 0.0, 0.0, 1.0);  // the edge alone in its pixels
}
]]></shader></pass>
  <pass name="final"><sampler name="s" target="h"/><shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D s;
out vec4 fragColor;
void main() { fragColor = texelFetch(s, ivec2(gl_FragCoord.xy), 0) * 0.0; }
]]></shader></pass>
</workspace>
)";
    GlRun run = runChecked(workspaceFromText(xml), {5, 2}, 1, GetParam());
    ASSERT_TRUE(run.exec) ;
    const FrameHealth* health = run.exec->frameHealth();
    ASSERT_TRUE(health);
    EXPECT_TRUE(health->passes[0].countedWhileDrawing);
    EXPECT_EQ(health->passes[0].counts, (std::array<long long, healthKindCount>{0, 0, 0, 0, 3 * 2}));
    ASSERT_EQ(health->findings.size(), 1u);
    EXPECT_EQ(health->findings[0].pixel, glm::ivec2(0, 1));
    EXPECT_EQ(health->findings[0].value.x, 70000.0f);
}

}  // namespace
}  // namespace rmfx::test
