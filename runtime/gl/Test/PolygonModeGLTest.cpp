// <polygon-mode> (RenderMonkey's GL_PolyFrontMode, GL_PolyBackMode, GL_LineWidth and Direct3D's
// D3DRS_FILLMODE): a quad drawn as outlines of a given width, back faces outlined while front
// faces fill, counted pixel by pixel against where the edges are.

#include <string>

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/GlTestSupport.h"
#include "validation/Validation.h"

namespace rmfx::test {
namespace {

class PolygonModeGLTest : public CompatibilityGlTest {};

constexpr int kSize = 64;

// The quad (2x2 in XY, counter-clockwise seen from +Z) at half size: its edges on pixel
// boundaries 16 and 48, its diagonal from (16, 16) to (48, 48). `mirror` -1 turns it to show its
// back face.
std::string quadWorkspace(const std::string& polygonMode, float mirror, const std::string& profile = "compatibility") {
    return R"(<workspace version="1" name="outline" size="64x64" profile=")" + profile + R"(">
  <target name="out" format="rgba32f" scale="1"/>
  <pass name="outline" target="out">
    <clear color="0 0 0 0"/>
    <draw mesh="quad"/>
    )" + polygonMode + R"(
    <shader stage="vertex"><![CDATA[
#version 450 core
layout(location = 0) in vec3 rm_Position;
void main() { gl_Position = vec4(rm_Position.xy * 0.5 * vec2()" +
           std::to_string(mirror) + R"(, 1.0), 0.0, 1.0); }
]]></shader>
    <shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() { fragColor = vec4(1.0); }
]]></shader>
  </pass>
</workspace>)";
}

Image render(const std::string& xml) {
    GlRun run = runWorkspace(xml, RunSettings{{kSize, kSize}});
    if (!run.exec) return {};
    return readBack(*run.exec, "out");
}

// Lit pixels of GL row `row` (from the bottom) in columns [from, to).
int litInRow(const Image& image, int row, int from, int to) {
    int lit = 0;
    for (int x = from; x < to; ++x) lit += image.at(x, kSize - 1 - row, 0) > 0.5f ? 1 : 0;
    return lit;
}

}  // namespace

TEST_F(PolygonModeGLTest, LinesOfTheGivenWidthOutlineEveryTriangle) {
    for (int width : {1, 3, 5}) {
        SCOPED_TRACE("line-width " + std::to_string(width));
        Image out = render(quadWorkspace(R"(<polygon-mode front="line" line-width=")" + std::to_string(width) + "\"/>", 1.0f));
        ASSERT_EQ(out.width, kSize);
        // Row 40 crosses the left edge (x = 16), the diagonal (x = 40) and the right edge (x = 48).
        EXPECT_EQ(litInRow(out, 40, 8, 24), width) << "the left edge";
        EXPECT_EQ(litInRow(out, 40, 24, 36), 0) << "inside, off the diagonal";
        EXPECT_GE(litInRow(out, 40, 36, 44), width) << "the diagonal";
        EXPECT_EQ(litInRow(out, 40, 44, 52), width) << "the right edge";
        EXPECT_EQ(litInRow(out, 40, 52, 64), 0) << "beyond the right edge";
        EXPECT_EQ(litInRow(out, 4, 0, kSize), 0) << "below the quad";
    }
}

TEST_F(PolygonModeGLTest, BackFacesOutlinedWhileFrontFacesFill) {
    const std::string mode = R"(<polygon-mode front="fill" back="line"/>)";
    Image front = render(quadWorkspace(mode, 1.0f)), back = render(quadWorkspace(mode, -1.0f));
    ASSERT_EQ(front.width, kSize);
    ASSERT_EQ(back.width, kSize);
    EXPECT_EQ(litInRow(front, 40, 0, kSize), 32) << "filled: columns 16 to 47";
    // Mirrored, the diagonal runs from (48, 16) to (16, 48): at row 40 it is at x = 24.
    EXPECT_EQ(litInRow(back, 40, 28, 44), 0) << "outlined: nothing inside, off the diagonal";
    EXPECT_EQ(litInRow(back, 40, 8, 20), 1) << "outlined: the left edge, one pixel";
}

TEST_F(PolygonModeGLTest, ACoreProfileWorkspaceCannotDrawFacesApartOrWideLines) {
    for (const auto& [mode, message] :
         {std::pair<std::string, std::string>{R"(<polygon-mode front="fill" back="line"/>)", "draws front and back faces differently"},
          {R"(<polygon-mode front="line" line-width="3"/>)", "draws lines 3 pixels wide"}}) {
        SCOPED_TRACE(mode);
        Result<Workspace> ws = parseWorkspaceText(quadWorkspace(mode, 1.0f, "core"), "outline.xml", ".");
        ASSERT_TRUE(ws) << formatAll(ws.diagnostics());
        const std::string errors = formatAll(validateWorkspace(*ws).diagnostics());
        EXPECT_NE(errors.find("outline.xml:6: error: <polygon-mode>: <pass name=\"outline\"> " + message), std::string::npos)
            << errors;
        EXPECT_NE(errors.find("<workspace profile=\"compatibility\">"), std::string::npos) << errors;
    }
    Result<Workspace> both = parseWorkspaceText(quadWorkspace(R"(<polygon-mode front="line" back="line"/>)", 1.0f, "core"),
                                                "outline.xml", ".");
    ASSERT_TRUE(both);
    EXPECT_FALSE(hasErrors(validateWorkspace(*both).diagnostics())) << formatAll(validateWorkspace(*both).diagnostics());
}

}  // namespace rmfx::test
