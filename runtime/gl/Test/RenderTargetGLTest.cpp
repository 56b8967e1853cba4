// Render targets: a viewport-relative reduction chain ending in the exact mean of its input,
// the sizes targets resolve to, and what each format holds (float range and precision, 8-bit
// clamping and quantisation, single-channel reads).

#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class RenderTargetGLTest : public GlTest {};

// The input pattern of the chain, per pixel (x, y counted from the bottom as gl_FragCoord does).
// Integer arithmetic in the shader and here, so both sides see the same values.
double patternR(int x, int y) { return ((x * 37 + y * 101) % 256) / 255.0; }
double patternG(int x, int y) { return (x * y % 97) * 0.5 - 10.0; }
double patternB(int x, int y) { return x == y ? 1000.0 : 0.0; }

const char* reduceShader = R"(
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D src;
out vec4 fragColor;
void main() {
    ivec2 base = ivec2(gl_FragCoord.xy) * 4;
    vec4 sum = vec4(0.0);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) sum += texelFetch(src, base + ivec2(i, j), 0);
    fragColor = sum / 16.0;
}
]]></shader>)";

TEST_F(RenderTargetGLTest, RelativeReductionChainEndsInTheMean) {
    std::ostringstream xml;
    xml << R"(<workspace version="1" name="chain" size="256x256">
  <target name="t256" format="rgba32f" scale="1"/>
  <target name="t64" format="rgba32f" scale="1/4"/>
  <target name="t16" format="rgba32f" scale="1/16"/>
  <target name="t4" format="rgba32f" scale="1/64"/>
  <target name="t1" format="rgba32f" scale="1/256"/>
  <pass name="pattern" target="t256">
    <shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() {
    int x = int(gl_FragCoord.x), y = int(gl_FragCoord.y);
    fragColor = vec4(float((x * 37 + y * 101) % 256) / 255.0, float(x * y % 97) * 0.5 - 10.0,
                     x == y ? 1000.0 : 0.0, 1.0);
}
]]></shader>
  </pass>)";
    const char* names[] = {"t256", "t64", "t16", "t4", "t1"};
    for (int i = 1; i < 5; ++i)
        xml << "\n  <pass name=\"reduce" << i << "\" target=\"" << names[i] << "\">\n    <sampler name=\"src\" target=\""
            << names[i - 1] << "\" filter=\"nearest\"/>" << reduceShader << "\n  </pass>";
    xml << "\n</workspace>";
    GlRun run = runWorkspace(xml.str(), {{256, 256}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);

    EXPECT_EQ(run.exec->targetSize("t256"), glm::ivec2(256, 256));
    EXPECT_EQ(run.exec->targetSize("t64"), glm::ivec2(64, 64));
    EXPECT_EQ(run.exec->targetSize("t16"), glm::ivec2(16, 16));
    EXPECT_EQ(run.exec->targetSize("t4"), glm::ivec2(4, 4));
    EXPECT_EQ(run.exec->targetSize("t1"), glm::ivec2(1, 1));

    double mean[3] = {0, 0, 0};
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            mean[0] += patternR(x, y);
            mean[1] += patternG(x, y);
            mean[2] += patternB(x, y);
        }
    for (double& m : mean) m /= 256.0 * 256.0;
    Image result = readBack(*run.exec, "t1");
    ASSERT_EQ(result.width, 1);
    ASSERT_EQ(result.height, 1);
    // Four levels of 16-term float sums: a few float ulps of the largest partial value.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(result.at(0, 0, c), mean[c], 2e-6 * std::max(1.0, std::abs(mean[c]))) << c;
    EXPECT_EQ(result.at(0, 0, 3), 1.0f);

    // One intermediate level too: t4 texel (i, j) is the mean of a 64x64 block.
    Image t4 = readBack(*run.exec, "t4");
    ASSERT_EQ(t4.width, 4);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            double block = 0;
            for (int y = j * 64; y < (j + 1) * 64; ++y)
                for (int x = i * 64; x < (i + 1) * 64; ++x) block += patternG(x, y);
            block /= 64.0 * 64.0;
            EXPECT_NEAR(atGl(t4, i, j, 1), block, 2e-6 * std::max(1.0, std::abs(block))) << i << "," << j;
        }
}

TEST_F(RenderTargetGLTest, TargetSizesResolveAgainstTheViewport) {
    GlRun run = runWorkspace(R"(<workspace version="1" name="sizes" size="8x8">
  <target name="quarter" format="rgba8" scale="1/4"/>
  <target name="third" format="rgba8" scale="1/3"/>
  <target name="wide" format="rgba8" scale="2 1/2"/>
  <target name="fixed" format="rgba8" size="7x5"/>
  <pass name="p">
    <shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() { fragColor = vec4(1.0); }
]]></shader>
  </pass>
</workspace>)",
                             {{100, 60}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    // Relative sizes round up: ceil(viewport × scale), at least 1.
    EXPECT_EQ(run.exec->targetSize("quarter"), glm::ivec2(25, 15));
    EXPECT_EQ(run.exec->targetSize("third"), glm::ivec2(34, 20));
    EXPECT_EQ(run.exec->targetSize("wide"), glm::ivec2(200, 30));
    EXPECT_EQ(run.exec->targetSize("fixed"), glm::ivec2(7, 5));
    EXPECT_EQ(run.exec->targetSize("output"), glm::ivec2(100, 60));
    EXPECT_EQ(run.exec->targetSize("missing"), glm::ivec2(0, 0));
    Image out = readBack(*run.exec, "output");
    EXPECT_EQ(out.width, 100);
    EXPECT_EQ(out.height, 60);
}

// Writes `values` (4 per pixel) into a target of the given format, one pixel each, and reads it back.
Image writeValues(const char* format, const std::vector<double>& values) {
    size_t pixels = values.size() / 4;
    std::ostringstream list;
    for (size_t i = 0; i < values.size(); ++i) list << (i ? ", " : "") << glslFloat(values[i]);
    std::ostringstream xml;
    xml << R"(<workspace version="1" name="formats" size="4x4">
  <target name="t" format=")" << format << R"(" size=")" << pixels << R"(x1"/>
  <pass name="write" target="t">
    <shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
const float v[)" << values.size() << "] = float[](" << list.str() << R"();
void main() {
    int i = int(gl_FragCoord.x) * 4;
    fragColor = vec4(v[i], v[i + 1], v[i + 2], v[i + 3]);
}
]]></shader>
  </pass>
</workspace>)";
    GlRun run = runWorkspace(xml.str(), {{4, 4}, 1, 1.0f / 60.0f});
    if (!run.exec) return {};
    return readBack(*run.exec, "t");
}

TEST_F(RenderTargetGLTest, Rgba32fHoldsLargeAndSmallValues) {
    const std::vector<double> values = {1e4, 6e4, 1e6, -3.5e7, 1e-5, 1e-7, -2.5e-6, 1.17549435e-38,
                                        1e30, 0.1, 1.0 / 3.0, 0.0};
    Image img = writeValues("rgba32f", values);
    ASSERT_EQ(img.width, 3);
    ASSERT_EQ(img.channels, 4);
    for (size_t i = 0; i < values.size(); ++i) {
        double expected = static_cast<float>(values[i]);  // what the shader's float literal holds
        EXPECT_NEAR(img.at(static_cast<int>(i / 4), 0, static_cast<int>(i % 4)), expected, 1e-6 * std::abs(expected))
            << "value " << values[i];
    }
}

TEST_F(RenderTargetGLTest, Rgba16fHoldsHalfRangeAndSubnormals) {
    // Half: 11 significant bits, largest finite 65504, smallest normal 2^-14 ≈ 6.1e-5; below it
    // subnormals in steps of 2^-24 ≈ 6e-8.
    const double step = std::ldexp(1.0, -24);
    const std::vector<double> values = {1e4, 6e4, 65504, -1234.0,   // large
                                        1e-4, 6.103515625e-05, 0.1, 1.0 / 3.0,  // small normals
                                        1e-5, 3e-7, step, 37 * step};  // subnormals
    Image img = writeValues("rgba16f", values);
    ASSERT_EQ(img.width, 3);
    for (size_t i = 0; i < values.size(); ++i) {
        double v = values[i];
        // Normals: relative 1e-3 (half precision, 2^-11 rounding or 2^-10 truncating);
        // subnormals: one subnormal step.
        double tolerance = std::abs(v) >= std::ldexp(1.0, -14) ? 1e-3 * std::abs(v) : step;
        float got = img.at(static_cast<int>(i / 4), 0, static_cast<int>(i % 4));
        EXPECT_NEAR(got, v, tolerance) << "value " << v;
        if (v != 0) {
            EXPECT_NE(got, 0.0f) << "value " << v << " flushed to zero";
        }
    }
    // Exactly representable halves come back exactly.
    EXPECT_EQ(img.at(0, 0, 2), 65504.0f);
    EXPECT_EQ(img.at(0, 0, 3), -1234.0f);
    EXPECT_EQ(img.at(1, 0, 1), 6.103515625e-05f);
    EXPECT_EQ(img.at(2, 0, 2), static_cast<float>(step));
    EXPECT_EQ(img.at(2, 0, 3), static_cast<float>(37 * step));
}

TEST_F(RenderTargetGLTest, Rgba8ClampsAndQuantises) {
    const std::vector<double> values = {-0.5, 1.7, 0.2, 0.123, 0.777, 1.0, 0.0, 1e6, 0.0019, 0.9981, -1e-3, 0.6};
    Image img = writeValues("rgba8", values);
    ASSERT_EQ(img.width, 3);
    for (size_t i = 0; i < values.size(); ++i) {
        float got = img.at(static_cast<int>(i / 4), 0, static_cast<int>(i % 4));
        double clamped = std::clamp(values[i], 0.0, 1.0);
        double steps = got * 255.0;
        EXPECT_NEAR(steps, std::round(steps), 1e-4) << "value " << values[i] << " is not a multiple of 1/255";
        EXPECT_NEAR(got, clamped, 0.5 / 255.0 + 1e-6) << "value " << values[i];
        EXPECT_EQ(std::lround(steps), std::lround(clamped * 255.0)) << "value " << values[i];
    }
}

TEST_F(RenderTargetGLTest, R32fReadsBackOneChannelRowZeroAtTheTop) {
    GlRun run = runWorkspace(R"(<workspace version="1" name="single" size="4x4">
  <target name="r" format="r32f" size="3x2"/>
  <pass name="write" target="r">
    <shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() {
    float x = floor(gl_FragCoord.x), y = floor(gl_FragCoord.y);
    fragColor = vec4(1e6 * (x + 1.0) + 0.125 * y - 1e-7, 5.0, 6.0, 7.0);
}
]]></shader>
  </pass>
</workspace>)",
                             {{4, 4}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    Image img = readBack(*run.exec, "r");
    ASSERT_EQ(img.channels, 1);
    ASSERT_EQ(img.width, 3);
    ASSERT_EQ(img.height, 2);
    ASSERT_EQ(img.pixels.size(), 6u);
    for (int y = 0; y < 2; ++y)      // from the bottom
        for (int x = 0; x < 3; ++x) {
            double expected = 1e6 * (x + 1) + 0.125 * y - 1e-7;
            EXPECT_NEAR(img.at(x, 1 - y, 0), expected, 1e-6 * expected) << x << "," << y;
        }
}

}  // namespace
}  // namespace rmfx::test
