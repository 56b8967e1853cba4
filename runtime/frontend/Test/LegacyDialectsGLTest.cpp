// RenderMonkey-style shaders run: legacy GLSL 1.10 in a compatibility-profile context reading the
// fixed-function matrices, light 0 and material and the built-in vertex arrays; GLSL ES 1.00 with
// named attributes fed by vertex streams. Every expectation is computed on the CPU in double:
// the pixel's ray hits the plane, whose texture coordinates, normal and tangent are known.

#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/GlContext.h"
#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class LegacyDialectsGLTest : public CompatibilityGlTest {};
class GlslEsGLTest : public GlTest {};

constexpr int kSize = 24;

// The camera and draw of every workspace below, as text and as the same numbers.
const char* kScene = R"(
  <camera target="0 0 0" distance="3" yaw="25" pitch="50" fov="50" near="0.1" far="20"/>
  <target name="out" format="rgba32f" scale="1"/>)";
const char* kDraw = R"(<draw mesh="plane" translate="0.1 0 -0.2" rotate="0 30 0" scale="1.2 1 0.9"/>)";

glm::dmat4 cpuView() {
    double yaw = glm::radians(25.0), pitch = glm::radians(50.0);
    glm::dvec3 eye = 3.0 * glm::dvec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
    return glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0, 1, 0));
}
glm::dmat4 cpuProjection(double aspect) { return glm::perspective(glm::radians(50.0), aspect, 0.1, 20.0); }
glm::dmat4 cpuWorld() {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(0.1, 0, -0.2));
    m = glm::rotate(m, glm::radians(30.0), glm::dvec3(0, 1, 0));
    return glm::scale(m, glm::dvec3(1.2, 1, 0.9));
}

// Where the ray through the centre of pixel (x, y) (y from the bottom) meets the plane mesh
// (object space y = 0, x and z in [-1, 1]), in object coordinates; nullopt when it misses the
// plane or lands within `margin` of its edge (a pixel there may be partly covered).
std::optional<glm::dvec3> hitPlane(int x, int y, double margin = 0.08) {
    glm::dmat4 toObject = glm::inverse(cpuProjection(1.0) * cpuView() * cpuWorld());
    glm::dvec2 ndc((x + 0.5) / kSize * 2.0 - 1.0, (y + 0.5) / kSize * 2.0 - 1.0);
    glm::dvec4 nearPoint = toObject * glm::dvec4(ndc, -1.0, 1.0), farPoint = toObject * glm::dvec4(ndc, 1.0, 1.0);
    glm::dvec3 a = glm::dvec3(nearPoint) / nearPoint.w, b = glm::dvec3(farPoint) / farPoint.w;
    if (std::abs(b.y - a.y) < 1e-12) return std::nullopt;
    double t = -a.y / (b.y - a.y);
    glm::dvec3 p = a + t * (b - a);
    if (t < 0 || std::abs(p.x) > 1.0 - margin || std::abs(p.z) > 1.0 - margin) return std::nullopt;
    return p;
}

// The plane's texture coordinates (BuiltinMeshes: u along +x, v along -z) at an object point.
glm::dvec2 planeTexCoord(glm::dvec3 p) { return {(p.x + 1.0) / 2.0, (1.0 - p.z) / 2.0}; }

// The eye-space normal of the plane: gl_NormalMatrix · (0, 1, 0), normalised.
glm::dvec3 eyeNormal() {
    glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(cpuView() * cpuWorld()));
    return glm::normalize(normalMatrix * glm::dvec3(0, 1, 0));
}

// Checks every pixel the plane covers well inside its edges; returns how many were checked.
template <class Expect>
int checkCoveredPixels(const Image& image, Expect expect, double tolerance) {
    int checked = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            auto hit = hitPlane(x, y);
            if (!hit) continue;
            glm::dvec4 want = expect(*hit);
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(atGl(image, x, y, c), want[c], tolerance) << "pixel " << x << "," << y << " channel " << c;
            ++checked;
        }
    return checked;
}

std::string workspace(const std::string& profile, const std::string& passBody) {
    return R"(<workspace version="1" name="legacy" size=")" + std::to_string(kSize) + "x" + std::to_string(kSize) +
           "\" profile=\"" + profile + "\">" + kScene + R"(
  <pass name="mesh" target="out">
    <clear color="-1 -1 -1 -1" depth="1"/>
    )" + kDraw + passBody + R"(
  </pass>
</workspace>)";
}

TEST_F(LegacyDialectsGLTest, ContextReportsTheCompatibilityProfile) {
    auto compatibility = GlContext::createHeadless(GlProfile::Compatibility);
    ASSERT_TRUE(compatibility) << compatibility.error();
    EXPECT_NE((*compatibility)->description().find("Compatibility Profile"), std::string::npos)
        << (*compatibility)->description();
    EXPECT_EQ((*compatibility)->profile(), GlProfile::Compatibility);
}

// ftransform(), gl_MultiTexCoord0, gl_NormalMatrix · gl_Normal, gl_ModelViewProjectionMatrix and
// light 0 with the front material, all from the built-in vertex arrays (no streams declared).
TEST_F(LegacyDialectsGLTest, FixedFunctionMatricesLightAndBuiltinArraysOnAMesh) {
    GlRun run = runWorkspace(workspace("compatibility", R"(
    <shader stage="vertex" dialect="glsl110"><![CDATA[
varying vec2 uv;
varying vec3 normal;
varying float sameAsFtransform;
void main() {
    gl_Position = ftransform();
    vec4 explicitly = gl_ModelViewProjectionMatrix * gl_Vertex;
    sameAsFtransform = length(explicitly - gl_Position) < 1e-4 * abs(gl_Position.w) ? 1.0 : 0.0;
    uv = gl_MultiTexCoord0.xy;
    normal = gl_NormalMatrix * gl_Normal;
}
]]></shader>
    <shader stage="fragment" dialect="glsl110"><![CDATA[
varying vec2 uv;
varying vec3 normal;
varying float sameAsFtransform;
void main() {
    vec3 n = normalize(normal);
    float diffuse = max(dot(n, normalize(gl_LightSource[0].position.xyz)), 0.0) *
                    gl_LightSource[0].diffuse.r * gl_FrontMaterial.diffuse.r;
    gl_FragColor = vec4(uv, diffuse, n.z + sameAsFtransform * 10.0);
}
]]></shader>)"),
                            RunSettings{{kSize, kSize}});
    ASSERT_TRUE(run.exec);
    Image image = readBack(*run.exec, "out");
    glm::dvec3 n = eyeNormal();
    // Light 0 shines from the camera: direction (0, 0, 1) in eye space; material diffuse 0.8.
    double diffuse = std::max(n.z, 0.0) * 1.0 * 0.8;
    int checked = checkCoveredPixels(
        image, [&](glm::dvec3 p) { return glm::dvec4(planeTexCoord(p), diffuse, n.z + 10.0); }, 2e-3);
    EXPECT_GT(checked, kSize * kSize / 8);
}

// Streams: position and texcoord to named attributes, tangent to a named attribute, the normal
// and colour to the built-ins gl_Normal and gl_Color.
TEST_F(LegacyDialectsGLTest, StreamsFeedNamedAttributesAndBuiltins) {
    GlRun run = runWorkspace(workspace("compatibility", R"(
    <stream usage="position" attribute="rm_Vertex"/>
    <stream usage="texcoord" index="0" attribute="rm_TexCoord0"/>
    <stream usage="tangent" attribute="rm_Tangent"/>
    <stream usage="normal"/>
    <stream usage="color"/>
    <shader stage="vertex" dialect="glsl110"><![CDATA[
#version 110
attribute vec4 rm_Vertex;
attribute vec2 rm_TexCoord0;
attribute vec3 rm_Tangent;
varying vec4 values;
void main() {
    gl_Position = gl_ModelViewProjectionMatrix * rm_Vertex;
    // uv, the object-space tangent's x and z, the normal's y and the colour's green.
    values = vec4(rm_TexCoord0.x, rm_TexCoord0.y + 10.0 * rm_Tangent.x + 100.0 * abs(rm_Tangent.z),
                  gl_Normal.y + 10.0 * gl_Color.g, 0.0);
}
]]></shader>
    <shader stage="fragment" dialect="glsl110"><![CDATA[
varying vec4 values;
void main() { gl_FragColor = values; }
]]></shader>)"),
                            RunSettings{{kSize, kSize}});
    ASSERT_TRUE(run.exec);
    Image image = readBack(*run.exec, "out");
    // The plane's tangent (dP/du) is +x, its normal +y, the colour white.
    int checked = checkCoveredPixels(image, [&](glm::dvec3 p) {
        glm::dvec2 uv = planeTexCoord(p);
        return glm::dvec4(uv.x, uv.y + 10.0, 1.0 + 10.0, 0.0);
    }, 2e-3);
    EXPECT_GT(checked, kSize * kSize / 8);
}

// Built-in streams are the executor's to check (validation warns about named attributes the
// shaders lack: LegacyDialectsTest): one the program does not read, and a tangent, which has no
// compatibility built-in, each warn naming the pass and the stream.
TEST_F(LegacyDialectsGLTest, BuiltinStreamsTheProgramCannotTakeWarnNamingPassAndStream) {
    GlRun run = runWorkspace(workspace("compatibility", R"(
    <stream usage="position" attribute="rm_Vertex"/>
    <stream usage="texcoord" index="0" attribute="rm_Missing"/>
    <stream usage="color"/>
    <stream usage="binormal"/>
    <shader stage="vertex" dialect="glsl110"><![CDATA[
attribute vec4 rm_Vertex;
void main() { gl_Position = gl_ModelViewProjectionMatrix * rm_Vertex; }
]]></shader>
    <shader stage="fragment" dialect="glsl110"><![CDATA[
void main() { gl_FragColor = vec4(1.0); }
]]></shader>)"),
                            RunSettings{{kSize, kSize}});
    ASSERT_TRUE(run.exec);
    std::string all = formatAll(run.diagnostics);
    EXPECT_NE(all.find("warning: <pass name=\"mesh\">: stream <stream usage=\"color\"> (line 9) feeds "
                       "the built-in gl_Color, which the shaders do not read"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find("<pass name=\"mesh\">: stream <stream usage=\"binormal\"> (line 10) names no attribute"),
              std::string::npos)
        << all;
    EXPECT_EQ(all.find("rm_Missing"), std::string::npos) << "validation's warning, not the executor's:\n" << all;
}

// GLSL ES 1.00 (precision qualifiers, attribute/varying, "#version 100" added) in rmfx's core
// context, with named attributes and the matrices from semantic variables.
TEST_F(GlslEsGLTest, Es100WithNamedAttributesAndSemanticMatrices) {
    GlRun run = runWorkspace(workspace("core", R"(
    <mat4 name="matWorldViewProjection" semantic="WorldViewProjection"/>
    <stream usage="position" attribute="a_position"/>
    <stream usage="texcoord" attribute="a_texcoord"/>
    <shader stage="vertex" dialect="glsles100"><![CDATA[
uniform mat4 matWorldViewProjection;
attribute vec4 a_position;
attribute vec2 a_texcoord;
varying vec2 v_texcoord;
void main() {
    gl_Position = matWorldViewProjection * a_position;
    v_texcoord = a_texcoord;
}
]]></shader>
    <shader stage="fragment" dialect="glsles100"><![CDATA[
precision mediump float;
varying vec2 v_texcoord;
void main() { gl_FragColor = vec4(v_texcoord, 0.25, 1.0); }
]]></shader>)"),
                            RunSettings{{kSize, kSize}});
    ASSERT_TRUE(run.exec);
    Image image = readBack(*run.exec, "out");
    int checked = checkCoveredPixels(
        image, [&](glm::dvec3 p) { return glm::dvec4(planeTexCoord(p), 0.25, 1.0); }, 2e-3);
    EXPECT_GT(checked, kSize * kSize / 8);
}

TEST_F(GlslEsGLTest, CompatibilityWorkspaceInACoreContextIsAClearError) {
    auto ws = workspaceFromText(workspace("compatibility", R"(
    <shader stage="fragment" dialect="glsl110"><![CDATA[
void main() { gl_FragColor = vec4(1.0); }
]]></shader>)"));
    ASSERT_TRUE(ws);
    auto exec = GlExecutor::create(std::move(ws), {kSize, kSize});
    EXPECT_FALSE(exec);
    const Diagnostics& d = exec.diagnostics();
    EXPECT_NE(formatAll(d).find("compatibility-profile context"), std::string::npos) << formatAll(d);
}

// rmfx render opens the context the workspace asks for: a legacy shader reading light 0 and the
// material renders there (and would not compile in a core context).
TEST_F(LegacyDialectsGLTest, RenderCommandOpensACompatibilityContext) {
    ScratchDir dir;
    std::filesystem::path file = dir.write("legacy.xml", R"(<workspace version="1" name="legacy" size="4x4" profile="compatibility">
  <output format="rgba32f"/>
  <pass name="light">
    <shader stage="fragment" dialect="glsl110"><![CDATA[
void main() { gl_FragColor = vec4(gl_LightSource[0].diffuse.g, gl_FrontMaterial.diffuse.g, gl_LightSource[0].position.z, 1.0); }
]]></shader>
  </pass>
</workspace>
)");
    std::filesystem::path exr = dir / "legacy.exr";
    CommandResult cli = runRmfx("render " + shellQuoted(file) + " -o " + shellQuoted(exr), dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    auto image = readImage(exr);
    ASSERT_TRUE(image) << image.error();
    // The documented defaults: light 0 diffuse 1, material diffuse 0.8, position (0, 0, 1, 0).
    EXPECT_FLOAT_EQ(image->at(1, 1, 0), 1.0f);
    EXPECT_FLOAT_EQ(image->at(1, 1, 1), 0.8f);
    EXPECT_FLOAT_EQ(image->at(1, 1, 2), 1.0f);
}

// A shader without #version written for lenient drivers (int to float, an error in GLSL 1.10)
// renders with GLSL 1.20's rules and says so.
TEST_F(LegacyDialectsGLTest, ALenientShaderRendersWithGlsl120RulesAndAWarning) {
    ScratchDir dir;
    std::filesystem::path file = dir.write("lenient.xml", R"(<workspace version="1" name="lenient" size="4x4" profile="compatibility">
  <output format="rgba32f"/>
  <pass name="light">
    <shader stage="fragment" dialect="glsl110"><![CDATA[
const float PI = 3.14159265;
const float SCALE = 5 * PI;
void main() { float quarter = 1; gl_FragColor = vec4(SCALE / 100.0, quarter / 4.0, 0.0, 1.0); }
]]></shader>
  </pass>
</workspace>
)");
    std::filesystem::path exr = dir / "lenient.exr";
    CommandResult cli = runRmfx("render " + shellQuoted(file) + " -o " + shellQuoted(exr), dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    const std::string warning = "lenient.xml:4: warning: <pass name=\"light\">: fragment shader without #version: GLSL 1.10 rejects it";
    const size_t first = cli.err.find(warning);
    EXPECT_NE(first, std::string::npos) << cli.err;
    EXPECT_EQ(cli.err.find(warning, first + 1), std::string::npos) << "said twice (validation and the GL build):\n" << cli.err;
    auto image = readImage(exr);
    ASSERT_TRUE(image) << image.error();
    EXPECT_NEAR(image->at(1, 1, 0), 5.0 * 3.14159265 / 100.0, 1e-6);
    EXPECT_FLOAT_EQ(image->at(1, 1, 1), 0.25f);
}

// RenderMonkey's window showed colour only: an imported effect's output goes to an 8-bit file
// without alpha (gl_legacy.rfx writes (0.45, 0.525, 0.6), alpha 1); an .exr keeps all four.
TEST_F(LegacyDialectsGLTest, RenderCommandWritesAnImportedEffectsOutputWithoutAlphaTo8BitFiles) {
    ScratchDir dir;
    const std::filesystem::path png = dir / "legacy.png", exr = dir / "legacy.exr";
    const std::string rfx = shellQuoted(sourceDir() / "tests" / "rfx" / "gl_legacy.rfx");
    CommandResult cli = runRmfx("render " + rfx + " --size 8x8 -o " + shellQuoted(png), dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    auto image = readImage(png);
    ASSERT_TRUE(image) << image.error();
    EXPECT_EQ(image->channels, 3);
    EXPECT_NEAR(image->at(3, 3, 0), 0.45, 0.5 / 255 + 1e-6);
    EXPECT_NEAR(image->at(3, 3, 2), 0.6, 0.5 / 255 + 1e-6);
    cli = runRmfx("render " + rfx + " --size 8x8 -o " + shellQuoted(exr), dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    auto full = readImage(exr);
    ASSERT_TRUE(full) << full.error();
    EXPECT_EQ(full->channels, 4);
}

}  // namespace
}  // namespace rmfx::test
