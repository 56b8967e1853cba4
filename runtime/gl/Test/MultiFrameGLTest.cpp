// Targets that carry state across frames (frame="previous"): accumulation and exponential
// adaptation compared with the CPU recurrence in double, and the initial contents.

#include <cmath>

#include <gtest/gtest.h>

#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class MultiFrameGLTest : public GlTest {};

// "acc" accumulates (dt, 1, time, 0) per frame from its initial value. "after" copies acc as the
// accumulate pass left it this frame; "before" reads acc as the last frame left it (a pass may not
// read a target before the frame writes it without saying frame="previous").
const char* accumulateWorkspace = R"(<workspace version="1" name="accumulate" size="4x4">
  <target name="acc" format="rgba32f" size="1x1" initial="0.5 -3 0 1"/>
  <target name="before" format="rgba32f" size="1x1" initial="7 7 7 7"/>
  <target name="after" format="rgba32f" size="1x1"/>
  <pass name="before" target="before">
    <sampler name="acc" target="acc" frame="previous" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D acc;
out vec4 fragColor;
void main() { fragColor = texelFetch(acc, ivec2(0), 0); }
]]></shader>
  </pass>
  <pass name="accumulate" target="acc">
    <sampler name="previous" target="acc" frame="previous" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D previous;
uniform float rm_DeltaTime;
uniform float rm_Time;
out vec4 fragColor;
void main() { fragColor = texelFetch(previous, ivec2(0), 0) + vec4(rm_DeltaTime, 1.0, rm_Time, 0.0); }
]]></shader>
  </pass>
  <pass name="after" target="after">
    <sampler name="acc" target="acc" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D acc;
out vec4 fragColor;
void main() { fragColor = texelFetch(acc, ivec2(0), 0); }
]]></shader>
  </pass>
</workspace>)";

struct Accumulated {
    double sumDt, count, sumTime;
};

// The CPU sum after `frames` frames: frame i runs at time i·dt (with dt the float the runtime uses).
Accumulated cpuAccumulate(int frames, float dt) {
    Accumulated a{0.5, -3.0, 0.0};
    for (int i = 0; i < frames; ++i) {
        a.sumDt += dt;
        a.count += 1;
        a.sumTime += static_cast<double>(static_cast<float>(i) * dt);
    }
    return a;
}

void expectAccumulated(const Image& img, const Accumulated& a, int frames) {
    ASSERT_EQ(img.width, 1);
    // float additions: each adds at most half an ulp of the running sum.
    auto tolerance = [&](double value) { return (frames + 1) * std::abs(value) * 6e-8 + 1e-7; };
    EXPECT_NEAR(img.at(0, 0, 0), a.sumDt, tolerance(a.sumDt)) << "sum of dt";
    EXPECT_EQ(img.at(0, 0, 1), static_cast<float>(a.count)) << "frame count";
    EXPECT_NEAR(img.at(0, 0, 2), a.sumTime, tolerance(a.sumTime)) << "sum of time";
    EXPECT_EQ(img.at(0, 0, 3), 1.0f);
}

TEST_F(MultiFrameGLTest, PreviousFrameAccumulatesFromTheInitialValue) {
    const float dt = 1.0f / 60.0f;
    for (int frames : {1, 2, 7, 40}) {
        SCOPED_TRACE("frames=" + std::to_string(frames));
        GlRun run = runWorkspace(accumulateWorkspace, {{4, 4}, frames, dt});
        ASSERT_TRUE(run.exec);
        expectAccumulated(readBack(*run.exec, "acc"), cpuAccumulate(frames, dt), frames);
        // A later pass in the same frame reading frame="current" sees this frame's value.
        expectAccumulated(readBack(*run.exec, "after"), cpuAccumulate(frames, dt), frames);
        // An earlier pass sees what the last frame left: the value after frames-1 frames.
        expectAccumulated(readBack(*run.exec, "before"), cpuAccumulate(frames - 1, dt), frames);
    }
}

TEST_F(MultiFrameGLTest, ZeroFramesLeaveTheInitialValues) {
    GlRun run = runWorkspace(accumulateWorkspace, {{4, 4}, 0, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    EXPECT_EQ(run.exec->frameIndex(), 0);
    Image acc = readBack(*run.exec, "acc"), before = readBack(*run.exec, "before"), after = readBack(*run.exec, "after");
    const float accInitial[4] = {0.5f, -3.0f, 0.0f, 1.0f};
    for (int c = 0; c < 4; ++c) {
        EXPECT_EQ(acc.at(0, 0, c), accInitial[c]) << c;
        EXPECT_EQ(before.at(0, 0, c), 7.0f) << c;
        EXPECT_EQ(after.at(0, 0, c), 0.0f) << c;  // no initial attribute: zero
    }
}

TEST_F(MultiFrameGLTest, ExponentialAdaptationMatchesTheCpuRecurrence) {
    // a += (target - a) * (1 - 0.98^(30 dt)), per channel with different targets, in rgba32f and
    // in rgba16f (which rounds the state to half every frame).
    auto workspace = [](const char* format) {
        return std::string(R"(<workspace version="1" name="adapt" size="4x4">
  <vec4 name="Goal" value="10 -2 0.25 1000"/>
  <target name="a" format=")") + format + R"(" size="2x2" initial="1 1 1 1"/>
  <pass name="adapt" target="a">
    <sampler name="previous" target="a" frame="previous" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D previous;
uniform vec4 Goal;
uniform float rm_DeltaTime;
out vec4 fragColor;
void main() {
    vec4 a = texelFetch(previous, ivec2(gl_FragCoord.xy), 0);
    fragColor = a + (Goal - a) * (1.0 - pow(0.98, 30.0 * rm_DeltaTime));
}
]]></shader>
  </pass>
</workspace>)";
    };
    const double goal[4] = {10, -2, 0.25, 1000};
    const float dt = 1.0f / 30.0f;
    const int frames = 45;
    double cpu[4] = {1, 1, 1, 1};
    double k = 1 - std::pow(0.98, 30.0 * static_cast<double>(dt));
    for (int i = 0; i < frames; ++i)
        for (int c = 0; c < 4; ++c) cpu[c] += (goal[c] - cpu[c]) * k;
    // GLSL's pow(x, y) is exp2(y·log2(x)): log2 within 2^-21 absolute on [0.5, 2], exp2 within
    // (3 + 2|y|) ulps, so k = 1 - pow(...) may be off by dk; the result after N frames moves by
    // |goal - a0| · N · (1-k)^(N-1) · dk. Each frame's float rounding adds a few ulps of the range;
    // rgba16f rounds the state to half (2^-11 relative) every frame, which the contraction (1-k)
    // keeps below 2^-11 / k of the range.
    const double dk = std::ldexp(1.0, -21) * std::log(2.0) + 5 * std::ldexp(1.0, -24);
    for (const char* format : {"rgba32f", "rgba16f"}) {
        SCOPED_TRACE(format);
        GlRun run = runWorkspace(workspace(format), {{4, 4}, frames, dt});
        ASSERT_TRUE(run.exec);
        Image img = readBack(*run.exec, "a");
        ASSERT_EQ(img.width, 2);
        bool half = std::string(format) == "rgba16f";
        for (int c = 0; c < 4; ++c) {
            double range = std::max(std::abs(goal[c]), 1.0);
            double powError = std::abs(goal[c] - 1.0) * frames * std::pow(1 - k, frames - 1) * dk;
            double rounding = half ? range * std::ldexp(1.0, -11) / k : range * 1e-6;
            double tolerance = powError + rounding;
            for (int y = 0; y < 2; ++y)
                for (int x = 0; x < 2; ++x) EXPECT_NEAR(img.at(x, y, c), cpu[c], tolerance) << "channel " << c;
        }
    }
}

}  // namespace
}  // namespace rmfx::test
