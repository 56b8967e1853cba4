// Every semantic variable (RenderMonkey's VARIABLE_SEMANTIC) reaches its uniform with the value
// computed here on the CPU in double: the matrices from the camera and draw written in the
// workspace, cycling time, the viewport, the pass index. A fragment shader writes each uniform
// into an rgba32f target, one vec4 per pixel (a mat4 takes four, one per column).

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/GlTestSupport.h"
#include "validation/Validation.h"

namespace rmfx::test {
namespace {

class SemanticVariablesGLTest : public GlTest {};

constexpr int kWidth = 64, kHeight = 48;  // the viewport: aspect 4/3
constexpr double kStep = 50.0;            // seconds per frame; 4 frames end at t = 150 > the 120 s cycle

struct Expected {
    std::string semantic;
    std::string glslType;  // float, vec2, vec4 or mat4
    std::vector<double> values;  // column-major for matrices
};

glm::dmat4 world() {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, -0.25, 1.0));
    m = glm::rotate(m, glm::radians(40.0), glm::dvec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(-20.0), glm::dvec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(10.0), glm::dvec3(1, 0, 0));
    return glm::scale(m, glm::dvec3(2.0, 0.5, 1.5));
}
glm::dvec3 eye() {
    double yaw = glm::radians(-35.0), pitch = glm::radians(20.0);
    return glm::dvec3(0.2, 0.1, -0.3) +
           4.5 * glm::dvec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
}
glm::dmat4 view() { return glm::lookAt(eye(), glm::dvec3(0.2, 0.1, -0.3), glm::dvec3(0, 1, 0)); }
glm::dmat4 projection() { return glm::perspective(glm::radians(55.0), double(kWidth) / kHeight, 0.2, 40.0); }

std::vector<double> columns(const glm::dmat4& m) {
    std::vector<double> out;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out.push_back(m[c][r]);
    return out;
}

std::vector<Expected> expectations() {
    std::vector<Expected> out;
    const std::map<std::string, glm::dmat4> bases = {
        {"World", world()}, {"View", view()}, {"Projection", projection()}, {"WorldView", view() * world()},
        {"ViewProjection", projection() * view()}, {"WorldViewProjection", projection() * view() * world()}};
    for (const auto& [name, m] : bases) {
        out.push_back({name, "mat4", columns(m)});
        out.push_back({name + "Inverse", "mat4", columns(glm::inverse(m))});
        out.push_back({name + "Transpose", "mat4", columns(glm::transpose(m))});
        out.push_back({name + "InverseTranspose", "mat4", columns(glm::transpose(glm::inverse(m)))});
    }
    glm::dvec3 e = eye(), forward = glm::normalize(glm::dvec3(0.2, 0.1, -0.3) - e);
    out.push_back({"ViewPosition", "vec4", {e.x, e.y, e.z, 1.0}});
    out.push_back({"ViewDirection", "vec4", {forward.x, forward.y, forward.z, 0.0}});
    // The last frame runs at t = 3 · 50 = 150 s: 30 s into the second 120 s cycle.
    const double t = 3 * kStep, x = std::fmod(t, 120.0), pi = 3.14159265358979323846;
    out.push_back({"Time0_X", "float", {x}});
    out.push_back({"SinTime0_X", "float", {std::sin(x)}});
    out.push_back({"CosTime0_X", "float", {std::cos(x)}});
    out.push_back({"TanTime0_X", "float", {std::tan(x)}});
    out.push_back({"Time0_1", "float", {x / 120.0}});
    out.push_back({"Time0_2PI", "float", {x / 120.0 * 2.0 * pi}});
    out.push_back({"TimeCyclePeriod", "float", {120.0}});
    out.push_back({"TimeElapsed", "float", {kStep}});
    out.push_back({"ViewportWidth", "float", {double(kWidth)}});
    out.push_back({"ViewportHeight", "float", {double(kHeight)}});
    out.push_back({"ViewportWidthInverse", "float", {1.0 / kWidth}});
    out.push_back({"ViewportHeightInverse", "float", {1.0 / kHeight}});
    out.push_back({"ViewportDimensions", "vec2", {double(kWidth), double(kHeight)}});
    out.push_back({"PassIndex", "float", {1.0}});  // the second pass of the list
    out.push_back({"MouseCoordinateXY", "vec2", {0.0, 0.0}});  // headless
    return out;
}

// One uniform per semantic, named u<index>; pixel k of the 1-row target holds the k-th vec4.
std::string semanticWorkspace(const std::vector<Expected>& all, int& pixels) {
    std::string variables, uniforms, body;
    pixels = 0;
    for (size_t i = 0; i < all.size(); ++i) {
        std::string name = "u" + std::to_string(i);
        variables += "    <" + all[i].glslType + " name=\"" + name + "\" semantic=\"" + all[i].semantic + "\"/>\n";
        uniforms += "uniform " + all[i].glslType + " " + name + ";\n";
        auto at = [&](const std::string& value) {
            body += "    if (x == " + std::to_string(pixels++) + ") v = " + value + ";\n";
        };
        if (all[i].glslType == "mat4")
            for (int c = 0; c < 4; ++c) at(name + "[" + std::to_string(c) + "]");
        else if (all[i].glslType == "vec4") at(name);
        else if (all[i].glslType == "vec2") at("vec4(" + name + ", 0.0, 0.0)");
        else at("vec4(" + name + ", 0.0, 0.0, 0.0)");
    }
    return R"(<workspace version="1" name="semantics" size=")" + std::to_string(kWidth) + "x" + std::to_string(kHeight) + R"(">
  <camera target="0.2 0.1 -0.3" distance="4.5" yaw="-35" pitch="20" fov="55" near="0.2" far="40"/>
  <target name="first" format="rgba8" size="1x1"/>
  <target name="out" format="rgba32f" size=")" + std::to_string(pixels) + R"(x1"/>
  <pass name="before" target="first">
    <shader stage="fragment"><![CDATA[
out vec4 color;
void main() { color = vec4(1.0); }
]]></shader>
  </pass>
  <pass name="semantics" target="out">
)" + variables + R"(    <draw mesh="fullscreen" translate="0.5 -0.25 1" rotate="10 -20 40" scale="2 0.5 1.5"/>
    <shader stage="fragment"><![CDATA[
)" + uniforms + R"(out vec4 color;
void main() {
    int x = int(gl_FragCoord.x);
    vec4 v = vec4(0.0);
)" + body + R"(    color = v;
}
]]></shader>
  </pass>
</workspace>)";
}

TEST_F(SemanticVariablesGLTest, EverySemanticMatchesTheCpuValueInDouble) {
    std::vector<Expected> all = expectations();
    int pixels = 0;
    std::string xml = semanticWorkspace(all, pixels);
    RunSettings settings({kWidth, kHeight}, 4, static_cast<float>(kStep));
    GlRun run = runWorkspace(xml, settings);
    ASSERT_TRUE(run.exec) << xml;
    Image image = readBack(*run.exec, "out");
    ASSERT_EQ(image.width, pixels);
    int pixel = 0;
    for (const Expected& e : all) {
        size_t count = e.glslType == "mat4" ? 16 : e.values.size();
        for (size_t k = 0; k < count; ++k) {
            int px = pixel + static_cast<int>(k / 4), c = static_cast<int>(k % 4);
            double want = e.values[k];
            // float32 storage of values computed in double: relative error of a few ulps, more for inverses.
            EXPECT_NEAR(atGl(image, px, 0, c), want, 2e-5 * std::max(1.0, std::abs(want)))
                << e.semantic << " component " << k;
        }
        pixel += e.glslType == "mat4" ? 4 : 1;
    }
}

TEST_F(SemanticVariablesGLTest, RandomFractionsLieInTheUnitIntervalAndChangeEveryFrame) {
    const char* xml = R"(<workspace version="1" name="random" size="4x1">
  <float name="r1" semantic="RandomFraction1PerPass"/>
  <float name="r2" semantic="RandomFraction2PerPass"/>
  <target name="out" format="rgba32f" size="1x1"/>
  <pass name="write" target="out">
    <shader stage="fragment"><![CDATA[
uniform float r1;
uniform float r2;
out vec4 color;
void main() { color = vec4(r1, r2, 0.0, 1.0); }
]]></shader>
  </pass>
</workspace>)";
    GlRun one = runWorkspace(xml, RunSettings({4, 1}, 1));
    GlRun two = runWorkspace(xml, RunSettings({4, 1}, 2));
    ASSERT_TRUE(one.exec && two.exec);
    Image a = readBack(*one.exec, "out"), b = readBack(*two.exec, "out");
    for (const Image* image : {&a, &b})
        for (int c = 0; c < 2; ++c) {
            EXPECT_GE(image->at(0, 0, c), 0.0f);
            EXPECT_LT(image->at(0, 0, c), 1.0f);
        }
    EXPECT_NE(a.at(0, 0, 0), a.at(0, 0, 1));  // two numbers, not one
    EXPECT_NE(a.at(0, 0, 0), b.at(0, 0, 0));  // a new number next frame
}

// A semantic matrix bound to a vec4 uniform: an error naming the uniform, the variable and the pass.
TEST_F(SemanticVariablesGLTest, SemanticOfTheWrongTypeIsAnErrorNamingUniformVariableAndPass) {
    const char* xml = R"(<workspace version="1" name="mismatch" size="4x4">
  <vec4 name="matViewProjection" semantic="ViewProjection"/>
  <pass name="draw">
    <shader stage="fragment"><![CDATA[
uniform vec4 matViewProjection;
out vec4 color;
void main() { color = matViewProjection; }
]]></shader>
  </pass>
</workspace>)";
    Result<Workspace> parsed = parseWorkspaceText(xml, "mismatch.xml", ".");
    ASSERT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
    for (const Diagnostics& d : {validateWorkspace(*parsed).diagnostics(), [&] {
             return GlExecutor::create(std::make_shared<const Workspace>(*parsed), {4, 4}).takeDiagnostics();
         }()}) {
        std::string all = formatAll(d);
        EXPECT_TRUE(hasErrors(d)) << all;
        EXPECT_NE(all.find("uniform 'matViewProjection' is declared vec4"), std::string::npos) << all;
        EXPECT_NE(all.find("variable 'matViewProjection'"), std::string::npos) << all;
        EXPECT_NE(all.find("ViewProjection, a mat4"), std::string::npos) << all;
        EXPECT_NE(all.find("<pass name=\"draw\">"), std::string::npos) << all;
    }
}

// An unknown semantic: a warning naming the variable and its line; the stored value is used.
TEST_F(SemanticVariablesGLTest, UnknownSemanticWarnsAndKeepsTheStoredValue) {
    const char* xml = R"(<workspace version="1" name="unknown" size="1x1">
  <vec4 name="odd" semantic="NoSuchSemantic" value="0.25 0.5 0.75 1"/>
  <target name="out" format="rgba32f" size="1x1"/>
  <pass name="write" target="out">
    <shader stage="fragment"><![CDATA[
uniform vec4 odd;
out vec4 color;
void main() { color = odd; }
]]></shader>
  </pass>
</workspace>)";
    Result<Workspace> parsed = parseWorkspaceText(xml, "unknown.xml", ".");
    ASSERT_TRUE(parsed.ok());
    std::string all = formatAll(validateWorkspace(*parsed).diagnostics());
    EXPECT_NE(all.find("unknown.xml:2: warning"), std::string::npos) << all;
    EXPECT_NE(all.find("variable 'odd'"), std::string::npos) << all;
    EXPECT_NE(all.find("NoSuchSemantic"), std::string::npos) << all;
    GlRun run = runWorkspace(xml, RunSettings({1, 1}));
    ASSERT_TRUE(run.exec);
    Image image = readBack(*run.exec, "out");
    for (int c = 0; c < 4; ++c) EXPECT_EQ(image.at(0, 0, c), 0.25f * (c + 1));
}

}  // namespace
}  // namespace rmfx::test
