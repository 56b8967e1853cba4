// Hard cases of the two adaptation shaders, the real GLSL files driven by a minimal workspace whose
// "measured" statistic is a constant (so 10 000 frames stay fast): effects/glsl/hdr_adapt.frag
// (hdr_lighting: adapted luminance, time-based, 1 - 0.98^(30 dt) of the way per frame) and
// effects/glsl/exposure_adapt.frag (auto_exposure: the chapter's per-frame lerp of the exposure
// towards 0.5 / average brightness). dt = 0 and 1000, 10 000 frames against a float64 iteration of
// the same recursion, measured values of 0, 1e-10, NaN and ±Inf; then one run of each real workspace.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "reference/AutoExposureReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class AdaptationHardCasesGLTest : public GlTest {};

constexpr double kUlp = 1.0 / (1 << 23);  // float32 ulp relative to the value (upper bound)

// Measured_Kind: 0 Measured_Value, 1 NaN, 2 +Inf, 3 -Inf (NaN and Inf cannot be written in XML).
const char* kMeasureShader = R"(<shader stage="fragment"><![CDATA[
#version 450 core
uniform float Measured_Value;
uniform int Measured_Kind;
out vec4 fragColor;
void main() {
    float v = Measured_Value;
    if (Measured_Kind == 1) v = uintBitsToFloat(0x7FC00000u);
    if (Measured_Kind == 2) v = uintBitsToFloat(0x7F800000u);
    if (Measured_Kind == 3) v = uintBitsToFloat(0xFF800000u);
    fragColor = vec4(v, v, 0.0, 1.0);
}
]]></shader>)";

// hdr_lighting's adaptation: measured (rg32f 1x1: r = Lavg) -> adapted (r32f 1x1, from `initial`).
std::string lightAdaptationXml(double measured, double initial) {
    return std::string(R"(<workspace version="1" name="light_adaptation" size="1x1">
  <float name="Measured_Value" value=")") + glslFloat(measured) + R"("/>
  <int name="Measured_Kind" value="0"/>
  <bool name="Light_Adaptation" value="true"/>
  <target name="measured" format="rg32f" size="1x1"/>
  <target name="adapted" format="r32f" size="1x1" initial=")" + glslFloat(initial) + R"( 0 0 0"/>
  <pass name="measure" target="measured">)" + kMeasureShader + R"(</pass>
  <pass name="adaptation" target="adapted">
    <sampler name="Adapted_Previous" target="adapted" frame="previous" filter="nearest"/>
    <sampler name="Measured" target="measured" filter="nearest"/>
    <shader stage="fragment" file="glsl/hdr_adapt.frag"/>
  </pass>
  <output target="adapted" transform="none"/>
</workspace>)";
}

// auto_exposure's adaptation: average (rgba32f 1x1: r = mean brightness) -> exposure (r32f 1x1).
std::string exposureAdaptationXml(double average, double initialExposure, double speed) {
    return std::string(R"(<workspace version="1" name="exposure_adaptation" size="1x1">
  <float name="Measured_Value" value=")") + glslFloat(average) + R"("/>
  <int name="Measured_Kind" value="0"/>
  <float name="Exposure_Adjust_Speed" value=")" + glslFloat(speed) + R"("/>
  <float name="Initial_Exposure" value=")" + glslFloat(initialExposure) + R"("/>
  <float name="Minimum_Average_Brightness" value="0.0001"/>
  <target name="average" format="rgba32f" size="1x1"/>
  <target name="exposure" format="r32f" size="1x1"/>
  <pass name="measure" target="average">)" + kMeasureShader + R"(</pass>
  <pass name="adapt" target="exposure">
    <sampler name="Previous_Exposure" target="exposure" frame="previous" filter="nearest"/>
    <sampler name="Average_Brightness" target="average" filter="nearest"/>
    <shader stage="fragment" file="glsl/exposure_adapt.frag"/>
  </pass>
  <output target="exposure" transform="none"/>
</workspace>)";
}

GlRun start(const std::string& xml) {
    return runWorkspace(workspaceFromText(xml, sourceDir() / "effects"), {{1, 1}, 0, 0.0f});
}

void frames(GlRun& run, int count, float dt) {
    for (int i = 0; i < count; ++i) {
        Diagnostics d = run.exec->renderFrame({static_cast<float>(run.exec->frameIndex()) * dt, dt}).takeDiagnostics();
        ASSERT_TRUE(d.empty()) << formatAll(d);
    }
}

float value(const GlRun& run, const std::string& target) { return readBack(*run.exec, target).at(0, 0, 0); }

uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

// The recursions in float64, with the float constants the shaders get.
double lightRate(float dt) { return 1.0 - std::pow(0.98, 30.0 * double(dt)); }
double step(double adapted, double target, double rate) { return adapted + (target - adapted) * rate; }

const float kLuminanceFloor = 0.0001f;  // LOG_DELTA: the smallest Lavg the chain can measure

// ---------------------------------------------------------------- hdr_adapt.frag

TEST_F(AdaptationHardCasesGLTest, LightAdaptationWithDtZeroLeavesTheAdaptedValueBitExact) {
    GlRun run = start(lightAdaptationXml(0.05, 0.7));
    ASSERT_TRUE(run.exec);
    frames(run, 5, 0.0f);
    EXPECT_EQ(bits(value(run, "adapted")), bits(0.7f)) << value(run, "adapted");
}

// 0.98^30000 underflows: the rate is 1 and the adapted value is the measured one, exactly
// (adapted · 0 + measured · 1).
TEST_F(AdaptationHardCasesGLTest, LightAdaptationWithDt1000JumpsToTheMeasuredValue) {
    for (double initial : {1.0, 1e-4, 3.0e4}) {
        GlRun run = start(lightAdaptationXml(0.05, initial));
        ASSERT_TRUE(run.exec);
        frames(run, 1, 1000.0f);
        const float measured = value(run, "measured");
        EXPECT_EQ(bits(value(run, "adapted")), bits(measured)) << "from " << initial;
    }
}

// 10 000 frames at 60 Hz towards a constant measured value, against the float64 recursion at
// checkpoints. Bound: the GLSL pow's error on the rate (log2 within 2^-21 absolute near 1: 2e-5 of
// the rate) moves (1 - rate)^n by at most 2e-5 · n·rate·(1 - rate)^n <= 1e-5 of |initial - measured|;
// each frame rounds once or twice (1.5 ulps of the larger value) and earlier roundings shrink by
// (1 - rate) a frame: 1.5 / rate ulps in all. After 10 000 frames (1 - rate)^10000 = e^-100, the
// float64 value is the measured one: float32 must reach it within 1e-6 relative (without the
// shader's last step it stalls about 0.5 / rate = 50 ulps, 3e-6 .. 6e-6, short).
TEST_F(AdaptationHardCasesGLTest, LightAdaptationOver10000FramesDoesNotDrift) {
    const float dt = 1.0f / 60.0f;
    const double rate = lightRate(dt);
    for (auto [measuredValue, initial] : {std::pair{0.0501, 1.0}, std::pair{7.25, 6.0}}) {
        SCOPED_TRACE("measured " + std::to_string(measuredValue) + " from " + std::to_string(initial));
        GlRun run = start(lightAdaptationXml(measuredValue, initial));
        ASSERT_TRUE(run.exec);
        frames(run, 1, dt);
        const double measured = value(run, "measured");
        double cpu = step(float(initial), measured, rate);
        int done = 1;
        for (int checkpoint : {10, 100, 1000, 10000}) {
            frames(run, checkpoint - done, dt);
            for (; done < checkpoint; ++done) cpu = step(cpu, measured, rate);
            const double gpu = value(run, "adapted");
            const double tolerance = 1e-5 * std::fabs(initial - measured) + 1.5 / rate * kUlp * std::max(initial, measured);
            expectWithin("adapted after " + std::to_string(checkpoint) + " frames", std::fabs(gpu - cpu), tolerance);
        }
        EXPECT_NEAR(cpu / measured, 1.0, 1e-12) << "the float64 recursion has converged";
        const float final = value(run, "adapted");
        expectWithin("relative error after 10000 frames", std::fabs(final - cpu) / cpu, 1e-6);
        EXPECT_LE(std::abs(int64_t(bits(final)) - int64_t(bits(float(measured)))), 1) << "settled on the target";
    }
}

TEST_F(AdaptationHardCasesGLTest, LightAdaptationStartingAtTheMeasuredValueStaysThere) {
    for (double v : {1.0 / 3.0, 1234.5678}) {
        const float exact = static_cast<float>(v);
        GlRun run = start(lightAdaptationXml(v, v));
        ASSERT_TRUE(run.exec);
        for (int checkpoint = 0; checkpoint < 10; ++checkpoint) {
            frames(run, 1000, 1.0f / 60.0f);
            const float a = value(run, "adapted");
            ASSERT_LE(std::abs(int64_t(bits(a)) - int64_t(bits(exact))), 1)
                << "after " << (checkpoint + 1) * 1000 << " frames: " << a << " vs " << exact;
        }
    }
}

// A measured 0 or 1e-10 (a hand-written or broken chain; the real chain never measures below
// delta) adapts to the floor delta = 1e-4, never to 0: the tone map divides by it.
TEST_F(AdaptationHardCasesGLTest, LightAdaptationToZeroOrTinyLuminanceStopsAtTheFloor) {
    for (double measured : {0.0, 1e-10, -3.0}) {
        SCOPED_TRACE("measured " + std::to_string(measured));
        GlRun run = start(lightAdaptationXml(measured, 1.0));
        ASSERT_TRUE(run.exec);
        frames(run, 600, 1.0f / 60.0f);  // 10 s: 0.98^300 = 2e-3 of the way is left
        float a = value(run, "adapted");
        EXPECT_TRUE(std::isfinite(a));
        EXPECT_GE(a, kLuminanceFloor);
        EXPECT_NEAR(a, kLuminanceFloor + (1.0 - kLuminanceFloor) * std::pow(0.98, 300.0), 1e-5);
        frames(run, 1, 1000.0f);
        EXPECT_EQ(value(run, "adapted"), kLuminanceFloor) << "dt = 1000: exactly the floor";
    }
}

// A NaN or infinite measurement is never stored: the adapted value holds for those frames and
// carries on from there when the measurement is finite again.
TEST_F(AdaptationHardCasesGLTest, LightAdaptationIgnoresNanAndInfiniteMeasurements) {
    const float dt = 1.0f / 60.0f;
    GlRun run = start(lightAdaptationXml(0.25, 1.0));
    ASSERT_TRUE(run.exec);
    frames(run, 30, dt);
    const float before = value(run, "adapted");
    for (int kind : {1, 2, 3}) {
        SCOPED_TRACE("Measured_Kind " + std::to_string(kind));
        ASSERT_EQ(run.exec->setVariable("Measured_Kind", Value::ofInt(kind)).error(), "");
        frames(run, 20, dt);
        EXPECT_FALSE(std::isfinite(value(run, "measured"))) << "the measurement is bad";
        EXPECT_EQ(bits(value(run, "adapted")), bits(before));
        frames(run, 1, 1000.0f);
        EXPECT_EQ(bits(value(run, "adapted")), bits(before)) << "not even a full step takes it";
    }
    ASSERT_EQ(run.exec->setVariable("Measured_Kind", Value::ofInt(0)).error(), "");
    frames(run, 1, dt);
    EXPECT_NEAR(value(run, "adapted"), step(before, 0.25, lightRate(dt)), 4 * kUlp);
}

// ---------------------------------------------------------------- exposure_adapt.frag

// The chapter's update is per frame, not per second: dt (0 or 1000) changes nothing, so these
// check that each frame is the lerp whatever dt is, and that nothing becomes NaN or Inf.
TEST_F(AdaptationHardCasesGLTest, ExposureAdaptationIsPerFrameWhateverDt) {
    const double speed = static_cast<float>(0.05), target = 0.5 / 0.25;
    for (float dt : {0.0f, 1.0f / 60.0f, 1000.0f}) {
        SCOPED_TRACE("dt " + std::to_string(dt));
        GlRun run = start(exposureAdaptationXml(0.25, 1.0, speed));
        ASSERT_TRUE(run.exec);
        frames(run, 3, dt);
        double e = 1.0;
        for (int i = 0; i < 3; ++i) e = step(e, target, speed);
        EXPECT_NEAR(value(run, "exposure"), e, 4 * kUlp * target);
    }
}

// As the light adaptation's: 10 000 frames at speed 0.01 (0.99^10000 = e^-100) against float64
// (rounding: 1.5 / speed ulps; mix is exact arithmetic otherwise), final within 1e-6 and within an
// ulp of the target (unsettled, float32 stalls up to 0.5 / speed = 50 ulps short), and a start on
// the target stays there.
TEST_F(AdaptationHardCasesGLTest, ExposureAdaptationOver10000FramesDoesNotDrift) {
    const double speed = static_cast<float>(0.01);
    for (auto [average, initial] : {std::pair{0.0501, 1.0}, std::pair{2.5, 16.0}}) {
        SCOPED_TRACE("average " + std::to_string(average) + " from " + std::to_string(initial));
        GlRun run = start(exposureAdaptationXml(average, initial, speed));
        ASSERT_TRUE(run.exec);
        const double target = 0.5 / double(float(average));
        double cpu = initial;
        int done = 0;
        for (int checkpoint : {1, 10, 100, 1000, 10000}) {
            frames(run, checkpoint - done, 1.0f / 60.0f);
            for (; done < checkpoint; ++done) cpu = step(cpu, target, speed);
            const double tolerance = (2.5 + 1.5 / speed) * kUlp * std::max(initial, target);
            expectWithin("exposure after " + std::to_string(checkpoint) + " frames",
                         std::fabs(value(run, "exposure") - cpu), tolerance);
        }
        expectWithin("relative error after 10000 frames", std::fabs(value(run, "exposure") - cpu) / cpu, 1e-6);
        EXPECT_LE(std::abs(int64_t(bits(value(run, "exposure"))) - int64_t(bits(float(target)))), 1) << "settled";
    }
    // 0.5 / 0.25 = 2 exactly: starting there, every frame's lerp gives 2 (or an ulp off).
    GlRun run = start(exposureAdaptationXml(0.25, 2.0, speed));
    ASSERT_TRUE(run.exec);
    for (int checkpoint = 0; checkpoint < 10; ++checkpoint) {
        frames(run, 1000, 1.0f / 60.0f);
        ASSERT_LE(std::abs(int64_t(bits(value(run, "exposure"))) - int64_t(bits(2.0f))), 1);
    }
}

// A black scene (0), 1e-10 or a negative average: the exposure moves towards 0.5 / floor = 5000.
TEST_F(AdaptationHardCasesGLTest, ExposureAdaptationFloorsZeroAndTinyAverages) {
    for (double average : {0.0, 1e-10, -1.0}) {
        SCOPED_TRACE("average " + std::to_string(average));
        GlRun run = start(exposureAdaptationXml(average, 1.0, 1.0));
        ASSERT_TRUE(run.exec);
        frames(run, 2, 1.0f / 60.0f);
        EXPECT_NEAR(value(run, "exposure"), 0.5 / double(kLuminanceFloor), 5000 * 4 * kUlp);
    }
}

TEST_F(AdaptationHardCasesGLTest, ExposureAdaptationIgnoresNanAndInfiniteAverages) {
    GlRun run = start(exposureAdaptationXml(0.25, 1.0, 0.05));
    ASSERT_TRUE(run.exec);
    frames(run, 10, 1.0f / 60.0f);
    const float before = value(run, "exposure");
    for (int kind : {1, 2, 3}) {
        SCOPED_TRACE("Measured_Kind " + std::to_string(kind));
        ASSERT_EQ(run.exec->setVariable("Measured_Kind", Value::ofInt(kind)).error(), "");
        frames(run, 5, 1.0f / 60.0f);
        EXPECT_EQ(bits(value(run, "exposure")), bits(before));
    }
}

// ---------------------------------------------------------------- the real workspaces

// hdr_lighting as shipped (64x64): at dt = 0 the adapted luminance keeps its initial 1 exactly,
// at dt = 1000 it is the measured log-average exactly; both finite, and >= the floor.
TEST_F(AdaptationHardCasesGLTest, HdrLightingWorkspaceAtDtZeroAndDt1000) {
    GlRun jump = runWorkspace(effectWorkspace("hdr_lighting.xml"), {{64, 64}, 3, 0.0f});
    ASSERT_TRUE(jump.exec);
    EXPECT_EQ(value(jump, "adapted"), 1.0f);
    frames(jump, 1, 1000.0f);
    const float measured = value(jump, "measured");
    ASSERT_TRUE(std::isfinite(measured));
    EXPECT_GE(measured, kLuminanceFloor);
    EXPECT_EQ(bits(value(jump, "adapted")), bits(measured));
}

// auto_exposure as shipped, three frames at dt = 0, 1000 and 0: the chapter's per-frame lerp from
// Initial_Exposure towards 0.5 / average, as if dt were 1/60 (within AutoExposureGLTest's bound:
// the chain's 3 + 12 ulps a level of the average, 2.5 ulps of the division and 3 ulps a frame).
TEST_F(AdaptationHardCasesGLTest, AutoExposureWorkspaceIgnoresDtZeroAndDt1000) {
    GlRun run = runWorkspace(effectWorkspace("auto_exposure.xml"), {{48, 48}, 1, 0.0f});
    ASSERT_TRUE(run.exec);
    frames(run, 1, 1000.0f);
    frames(run, 1, 0.0f);
    const double average = meanBrightness(readRef(run, "scene"));
    const double target = targetExposure(average, 0.0001f), initial = 1.0, speed = static_cast<float>(0.05);
    const double e = value(run, "exposure");
    EXPECT_TRUE(std::isfinite(e) && e > 0.0) << e;
    EXPECT_NEAR(e, exposureAfterFrames(initial, target, speed, 3), (3.0 + 12.0 * chainSizes({48, 48}).size() + 2.5 + 9.0) * kUlp * std::max(initial, target));
}

}  // namespace
}  // namespace rmfx::test
