// Every variable type, pass constants, setVariable, --set overrides and the predefined values
// reach their uniforms: shaders write them into rgba32f targets, which hold float32 exactly.

#include <cmath>
#include <cstdlib>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include "tests/support/GlTestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

class UniformBindingGLTest : public GlTest {};

// The value the parser must produce for a number written in the workspace.
float f(const char* text) { return std::strtof(text, nullptr); }

// All types into a 10x1 rgba32f target, one vec4 per pixel.
const char* allTypesWorkspace = R"(<workspace version="1" name="types" size="10x1">
  <float name="F" value="0.1234567"/>
  <int name="I" value="-123456"/>
  <bool name="B" value="true"/>
  <vec2 name="V2" value="1.5e-7 -2.75"/>
  <vec3 name="V3" value="3.14159274 -0 1e30"/>
  <vec4 name="V4" value="0.333333343 4 -5.5 65504.5"/>
  <color name="C3" value="0.9 0.75 0.5"/>
  <color name="C4" value="0.1 0.2 0.3 0.4"/>
  <mat4 name="M" value="1 2 3 4  5 6 7 8  9 10 11 12  13 14 15 16.5"/>
  <target name="out" format="rgba32f" size="10x1"/>
  <pass name="write" target="out">
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform float F;
uniform int I;
uniform bool B;
uniform vec2 V2;
uniform vec3 V3;
uniform vec4 V4;
uniform vec3 C3;
uniform vec4 C4;
uniform mat4 M;
out vec4 fragColor;
void main() {
    int x = int(gl_FragCoord.x);
    if (x == 0) fragColor = vec4(F, float(I), B ? 1.0 : 0.0, 0.0);
    else if (x == 1) fragColor = vec4(V2, 0.0, 0.0);
    else if (x == 2) fragColor = vec4(V3, 0.0);
    else if (x == 3) fragColor = V4;
    else if (x == 4) fragColor = vec4(C3, 0.0);
    else if (x == 5) fragColor = C4;
    else fragColor = M[x - 6];  // columns
}
]]></shader>
  </pass>
</workspace>)";

struct Expected {
    float F, I, B;
    float V2[2], V3[3], V4[4], C3[3], C4[4], M[16];
};

void expectAllTypes(const Image& img, const Expected& e) {
    ASSERT_EQ(img.width, 10);
    ASSERT_EQ(img.channels, 4);
    auto px = [&](int x, int c) { return atGl(img, x, 0, c); };
    EXPECT_EQ(px(0, 0), e.F) << "float";
    EXPECT_EQ(px(0, 1), e.I) << "int";
    EXPECT_EQ(px(0, 2), e.B) << "bool";
    for (int c = 0; c < 2; ++c) EXPECT_EQ(px(1, c), e.V2[c]) << "vec2[" << c << "]";
    for (int c = 0; c < 3; ++c) EXPECT_EQ(px(2, c), e.V3[c]) << "vec3[" << c << "]";
    for (int c = 0; c < 4; ++c) EXPECT_EQ(px(3, c), e.V4[c]) << "vec4[" << c << "]";
    for (int c = 0; c < 3; ++c) EXPECT_EQ(px(4, c), e.C3[c]) << "color rgb[" << c << "]";
    for (int c = 0; c < 4; ++c) EXPECT_EQ(px(5, c), e.C4[c]) << "color rgba[" << c << "]";
    // The 16 numbers of a mat4 are column-major: column i is M[i] in GLSL.
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            EXPECT_EQ(px(6 + col, row), e.M[col * 4 + row]) << "mat4 column " << col << " row " << row;
}

Expected declaredValues() {
    return {f("0.1234567"), -123456.0f, 1.0f,
            {f("1.5e-7"), -2.75f},
            {f("3.14159274"), -0.0f, f("1e30")},
            {f("0.333333343"), 4.0f, -5.5f, f("65504.5")},
            {f("0.9"), f("0.75"), f("0.5")},
            {f("0.1"), f("0.2"), f("0.3"), f("0.4")},
            {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16.5f}};
}

TEST_F(UniformBindingGLTest, EveryVariableTypeReachesItsUniformExactly) {
    GlRun run = runWorkspace(allTypesWorkspace, {{10, 1}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    expectAllTypes(readBack(*run.exec, "out"), declaredValues());
}

TEST_F(UniformBindingGLTest, OverridesFromSetArriveInTheShader) {
    auto ws = workspaceFromText(allTypesWorkspace);
    ASSERT_TRUE(ws);
    Result<void> set = applyOverrides(*ws, {{"F", "-0.75"},
                                            {"I", "16777216"},
                                            {"B", "false"},
                                            {"V2", "7,8"},
                                            {"V3", "1e-3 2e-3 3e-3"},
                                            {"V4", "-1 -2 -3 -4"},
                                            {"C3", "0.25 0.125 2"},
                                            {"C4", "1 0 0.5 0.0625"},
                                            {"M", "16 15 14 13 12 11 10 9 8 7 6 5 4 3 2 1"}});
    ASSERT_TRUE(set.diagnostics().empty()) << formatAll(set.diagnostics());
    GlRun run = runWorkspace(std::move(ws), {{10, 1}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    Expected e{-0.75f, 16777216.0f, 0.0f,
               {7, 8},
               {f("1e-3"), f("2e-3"), f("3e-3")},
               {-1, -2, -3, -4},
               {0.25f, 0.125f, 2.0f},
               {1, 0, 0.5f, 0.0625f},
               {16, 15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1}};
    expectAllTypes(readBack(*run.exec, "out"), e);
}

TEST_F(UniformBindingGLTest, SetVariableChangesTheNextFrame) {
    GlRun run = runWorkspace(allTypesWorkspace, {{10, 1}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    GlExecutor& exec = *run.exec;
    Expected e = declaredValues();
    expectAllTypes(readBack(exec, "out"), e);

    EXPECT_EQ(exec.setVariable("F", Value::ofFloat(2.5f)).error(), "");
    EXPECT_EQ(exec.setVariable("I", Value::ofInt(42)).error(), "");
    EXPECT_EQ(exec.setVariable("B", Value::ofBool(false)).error(), "");
    Value c4;
    c4.type = ValueType::Color4;
    c4.data = {0.5f, 0.25f, 0.125f, 1.0f};
    EXPECT_EQ(exec.setVariable("C4", c4).error(), "");
    Value m;
    m.type = ValueType::Mat4;
    for (int i = 0; i < 16; ++i) m.data[static_cast<size_t>(i)] = -static_cast<float>(i) * 0.5f;
    EXPECT_EQ(exec.setVariable("M", m).error(), "");
    // Wrong types are refused and change nothing.
    EXPECT_NE(exec.setVariable("F", Value::ofInt(1)).error(), "");
    Value rgb;
    rgb.type = ValueType::Color3;
    EXPECT_NE(exec.setVariable("C4", rgb).error(), "");
    EXPECT_NE(exec.setVariable("Nope", Value::ofFloat(1)).error(), "");

    // Not visible until the next frame renders.
    expectAllTypes(readBack(exec, "out"), e);
    Diagnostics frame = exec.renderFrame({1.0f / 60.0f, 1.0f / 60.0f}).takeDiagnostics();
    ASSERT_FALSE(hasErrors(frame)) << formatAll(frame);
    e.F = 2.5f;
    e.I = 42.0f;
    e.B = 0.0f;
    for (int i = 0; i < 4; ++i) e.C4[i] = c4.data[static_cast<size_t>(i)];
    for (int i = 0; i < 16; ++i) e.M[i] = m.data[static_cast<size_t>(i)];
    expectAllTypes(readBack(exec, "out"), e);
    ASSERT_NE(exec.variable("F"), nullptr);
    EXPECT_EQ(exec.variable("F")->asFloat(), 2.5f);
}

TEST_F(UniformBindingGLTest, PassConstantShadowsTheVariableInItsPassOnly) {
    GlRun run = runWorkspace(R"(<workspace version="1" name="shadow" size="4x4">
  <float name="K" value="3"/>
  <vec3 name="W" value="1 2 3"/>
  <target name="a" format="rgba32f" size="1x1"/>
  <target name="b" format="rgba32f" size="1x1"/>
  <pass name="withConstant" target="a">
    <float name="K" value="7.25"/>
    <vec3 name="W" value="-4 -5 -6"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform float K;
uniform vec3 W;
out vec4 fragColor;
void main() { fragColor = vec4(K, W); }
]]></shader>
  </pass>
  <pass name="withoutConstant" target="b">
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform float K;
uniform vec3 W;
out vec4 fragColor;
void main() { fragColor = vec4(K, W); }
]]></shader>
  </pass>
</workspace>)",
                             {{4, 4}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    Image a = readBack(*run.exec, "a"), b = readBack(*run.exec, "b");
    ASSERT_EQ(a.width, 1);
    ASSERT_EQ(b.width, 1);
    const float expectA[4] = {7.25f, -4, -5, -6}, expectB[4] = {3, 1, 2, 3};
    for (int c = 0; c < 4; ++c) {
        EXPECT_EQ(a.at(0, 0, c), expectA[c]) << c;
        EXPECT_EQ(b.at(0, 0, c), expectB[c]) << c;
    }
    // setVariable changes the variable, not the pass constant that shadows it.
    EXPECT_EQ(run.exec->setVariable("K", Value::ofFloat(11.0f)).error(), "");
    ASSERT_FALSE(hasErrors(run.exec->renderFrame({0.1f, 0.1f}).takeDiagnostics()));
    EXPECT_EQ(readBack(*run.exec, "a").at(0, 0, 0), 7.25f);
    EXPECT_EQ(readBack(*run.exec, "b").at(0, 0, 0), 11.0f);
}

// Predefined values: sizes into a viewport-relative target, clock and matrices into another.
const char* predefinedWorkspace = R"(<workspace version="1" name="predefined" size="64x64">
  <camera target="0.5 -0.25 1" distance="5" yaw="30" pitch="20" fov="45" near="0.1" far="50"/>
  <target name="sizes" format="rgba32f" scale="1/4 1/2"/>
  <target name="m" format="rgba32f" size="24x1"/>
  <pass name="sizes" target="sizes">
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform vec2 rm_ViewportSize;
uniform vec2 rm_InvViewportSize;
uniform vec2 rm_TargetSize;
uniform vec2 rm_InvTargetSize;
out vec4 fragColor;
void main() {
    fragColor = int(gl_FragCoord.x) == 0 ? vec4(rm_ViewportSize, rm_InvViewportSize)
                                         : vec4(rm_TargetSize, rm_InvTargetSize);
}
]]></shader>
  </pass>
  <pass name="matrices" target="m">
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform float rm_Time;
uniform float rm_DeltaTime;
uniform int rm_Frame;
uniform mat4 rm_View;
uniform mat4 rm_Projection;
uniform mat4 rm_ViewProjection;
uniform mat4 rm_InvViewProjection;
uniform mat4 rm_InvView;
uniform vec3 rm_CameraPosition;
out vec4 fragColor;
void main() {
    int x = int(gl_FragCoord.x);
    if (x == 0) fragColor = vec4(rm_Time, rm_DeltaTime, float(rm_Frame), 0.0);
    else if (x == 1) fragColor = vec4(rm_CameraPosition, 1.0);
    else if (x < 6) fragColor = rm_View[x - 2];
    else if (x < 10) fragColor = rm_Projection[x - 6];
    else if (x < 14) fragColor = rm_ViewProjection[x - 10];
    else if (x < 18) fragColor = rm_InvViewProjection[x - 14];
    else if (x < 22) fragColor = rm_InvView[x - 18];
    else fragColor = vec4(0.0);
}
]]></shader>
  </pass>
</workspace>)";

// A uniform declared with a value needs no variable: it keeps the value (the HLSL translator
// writes initialised globals so). A variable of its name still wins.
TEST_F(UniformBindingGLTest, UniformWithAnInitialValueKeepsItUnlessAVariableFeedsIt) {
    GlRun run = runWorkspace(R"(<workspace version="1" name="initial" size="4x4">
  <float name="Fed" value="0.75"/>
  <target name="a" format="rgba32f" size="1x1"/>
  <pass name="initial" target="a">
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform vec3 Tint = vec3(0.25, -2.5, 1e3);
uniform float Fed = 9.0;
out vec4 fragColor;
void main() { fragColor = vec4(Tint, Fed); }
]]></shader>
  </pass>
</workspace>)",
                             {{4, 4}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    Image a = readBack(*run.exec, "a");
    ASSERT_EQ(a.width, 1);
    const float expected[4] = {0.25f, -2.5f, 1000.0f, 0.75f};
    for (int c = 0; c < 4; ++c) EXPECT_EQ(a.at(0, 0, c), expected[c]) << c;
}

TEST_F(UniformBindingGLTest, ViewportAndTargetSizes) {
    GlRun run = runWorkspace(predefinedWorkspace, {{48, 32}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    EXPECT_EQ(run.exec->targetSize("sizes"), glm::ivec2(12, 16));
    Image s = readBack(*run.exec, "sizes");
    ASSERT_EQ(s.width, 12);
    ASSERT_EQ(s.height, 16);
    // Every row sees the same values; check the top and bottom rows.
    for (int y : {0, 15}) {
        EXPECT_EQ(atGl(s, 0, y, 0), 48.0f);
        EXPECT_EQ(atGl(s, 0, y, 1), 32.0f);
        EXPECT_EQ(atGl(s, 0, y, 2), 1.0f / 48.0f);
        EXPECT_EQ(atGl(s, 0, y, 3), 1.0f / 32.0f);
        EXPECT_EQ(atGl(s, 5, y, 0), 12.0f);
        EXPECT_EQ(atGl(s, 5, y, 1), 16.0f);
        EXPECT_EQ(atGl(s, 5, y, 2), 1.0f / 12.0f);
        EXPECT_EQ(atGl(s, 5, y, 3), 1.0f / 16.0f);
    }
}

TEST_F(UniformBindingGLTest, TimeDeltaTimeAndFrameIndexAcrossFrames) {
    const float dt = 0.1f;
    for (int frames = 1; frames <= 4; ++frames) {
        SCOPED_TRACE("frames=" + std::to_string(frames));
        GlRun run = runWorkspace(predefinedWorkspace, {{48, 32}, frames, dt});
        ASSERT_TRUE(run.exec);
        EXPECT_EQ(run.exec->frameIndex(), frames);
        Image m = readBack(*run.exec, "m");
        int last = frames - 1;  // the last frame rendered has index frames-1 and runs at (frames-1)·dt
        EXPECT_NEAR(m.at(0, 0, 0), last * 0.1, 1e-6 * (1 + last)) << "rm_Time";
        EXPECT_EQ(m.at(0, 0, 1), dt) << "rm_DeltaTime";
        EXPECT_EQ(m.at(0, 0, 2), static_cast<float>(last)) << "rm_Frame";
    }
}

TEST_F(UniformBindingGLTest, ViewAndProjectionMatchTheCameraComputedOnTheCpu) {
    GlRun run = runWorkspace(predefinedWorkspace, {{48, 32}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    Image m = readBack(*run.exec, "m");
    ASSERT_EQ(m.width, 24);

    // The workspace's camera in double: orbit position around the target, lookAt with +Y up,
    // perspective with the viewport's aspect (48 / 32).
    const double pi = 3.14159265358979323846;
    double yaw = 30 * pi / 180, pitch = 20 * pi / 180;
    glm::dvec3 target(0.5, -0.25, 1.0);
    glm::dvec3 eye = target + 5.0 * glm::dvec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                                               std::cos(yaw) * std::cos(pitch));
    glm::dmat4 view = glm::lookAt(eye, target, glm::dvec3(0, 1, 0));
    glm::dmat4 projection = glm::perspective(45 * pi / 180, 48.0 / 32.0, 0.1, 50.0);
    glm::dmat4 viewProjection = projection * view;
    glm::dmat4 invViewProjection = glm::inverse(viewProjection);
    glm::dmat4 invView = glm::inverse(view);

    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.at(1, 0, c), eye[c], 1e-5) << "rm_CameraPosition[" << c << "]";
    auto expectMatrix = [&](const char* name, int firstPixel, const glm::dmat4& expected) {
        double scale = 0;
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 4; ++row) scale = std::max(scale, std::abs(expected[col][row]));
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 4; ++row)
                EXPECT_NEAR(m.at(firstPixel + col, 0, row), expected[col][row], 2e-6 * scale)
                    << name << "[" << col << "][" << row << "]";
    };
    expectMatrix("rm_View", 2, view);
    expectMatrix("rm_Projection", 6, projection);
    expectMatrix("rm_ViewProjection", 10, viewProjection);
    expectMatrix("rm_InvViewProjection", 14, invViewProjection);
    expectMatrix("rm_InvView", 18, invView);
}

}  // namespace
}  // namespace rmfx::test
