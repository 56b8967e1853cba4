// The rmfx binary: `rmfx render` writes what the executor renders, and a bad workspace exits
// non-zero with a file:line message.

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

class CliRenderGLTest : public GlTest {};

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST_F(CliRenderGLTest, RenderWritesTheOutputTargetAsExr) {
    ScratchDir dir;
    std::filesystem::path exr = dir / "default.exr";
    CommandResult cli = runRmfx("render -o " + shellQuoted(exr) + " --size 32x32", dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    auto image = readImage(exr);
    ASSERT_TRUE(image) << image.error();

    Result<Workspace> loaded = loadDefaultWorkspace();
    ASSERT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
    GlRun run = runWorkspace(std::make_unique<Workspace>(std::move(*loaded)), {{32, 32}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    Image expected = readBack(*run.exec, "output");
    ASSERT_EQ(image->width, 32);
    ASSERT_EQ(image->height, 32);
    ASSERT_GE(image->channels, 3);
    int channels = std::min(image->channels, expected.channels);
    // The EXR holds the rgba16f output's values as float (no display transform for EXR), so the
    // same rendering on the same driver matches exactly.
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            for (int c = 0; c < channels; ++c)
                ASSERT_EQ(image->at(x, y, c), expected.at(x, y, c)) << x << "," << y << " channel " << c;
}

TEST_F(CliRenderGLTest, BadWorkspaceExitsNonZeroWithFileAndLine) {
    ScratchDir dir;
    std::filesystem::path bad = dir.write("bad.xml", R"(<workspace version="1" name="bad">
  <float name="Ok" value="1"/>
  <target name="t" format="rgba99" size="4x4"/>
</workspace>
)");
    std::filesystem::path png = dir / "never.png";
    CommandResult run = runRmfx("render " + shellQuoted(bad) + " -o " + shellQuoted(png), dir.path());
    const std::string& err = run.err;
    EXPECT_NE(run.status, 0);
    EXPECT_NE(err.find(bad.string() + ":3:"), std::string::npos) << err;
    EXPECT_NE(err.find("rgba99"), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(png));
}

// --check: a pass that divides by zero in the middle of a chain is named with the pixel and its
// input there, the image is still written, and the exit status is 4; the same chain without the
// division passes with 0 and says what it found none of.
TEST_F(CliRenderGLTest, CheckNamesThePassThatWroteAnInfinityAndExitsWith4) {
    auto workspace = [](const std::string& expression) {
        return R"(<workspace version="1" name="chain" size="8x4">
  <target name="ramp" format="rgba16f" scale="1"/>
  <target name="ratio" format="rgba32f" scale="1"/>
  <pass name="ramp" target="ramp">
    <shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() { fragColor = vec4(gl_FragCoord.x - 2.5, 1.0, 0.0, 1.0); }
]]></shader>
  </pass>
  <pass name="ratio" target="ratio">
    <sampler name="ramp" target="ramp" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D ramp;
out vec4 fragColor;
void main() { vec4 r = texelFetch(ramp, ivec2(gl_FragCoord.xy), 0); fragColor = vec4()" + expression + R"(, 0.5, 0.5, 1.0); }
]]></shader>
  </pass>
  <pass name="final">
    <sampler name="ratio" target="ratio" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D ratio;
out vec4 fragColor;
void main() { fragColor = texelFetch(ratio, ivec2(gl_FragCoord.xy), 0); }
]]></shader>
  </pass>
</workspace>
)";
    };
    ScratchDir dir;
    dir.write("bad.xml", workspace("1.0 / r.x"));
    CommandResult bad = runRmfx("render bad.xml --check -o bad.exr", dir.path());
    EXPECT_EQ(bad.status, 4) << bad.err;
    // The ramp is x - 2.5 at pixel centres x + 0.5: 0 in column 2, negative left of it.
    EXPECT_TRUE(has(bad.err, "rmfx: check: error: frame 0: pass 'ratio' wrote +Inf into target 'ratio' (4 pixels; first at "
                             "x=2 y=3: (inf, 0.5, 0.5, 1); there the inputs held: ramp → target 'ramp' (0, 1, 0, 1))\n"))
        << bad.err;
    EXPECT_TRUE(has(bad.err, "rmfx: check: warning: frame 0: pass 'ramp' wrote negative values into target 'ramp' (8 pixels; "
                             "first at x=0 y=3: (-2, 1, 0, 1); the pass reads no 2D input)\n"))
        << bad.err;
    EXPECT_TRUE(has(bad.err, "rmfx: check: 3 passes a frame, 1 frame: no NaN, -Inf, values at the format's largest\n"))
        << bad.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "bad.exr"));
    // The passes' own shaders counting what they write find the same, and say they did.
    CommandResult drawing = runRmfx("render bad.xml --check-method while-drawing -o bad.exr", dir.path());
    EXPECT_EQ(drawing.status, 4) << drawing.err;
    EXPECT_TRUE(has(drawing.err, "pass 'ratio' wrote +Inf into target 'ratio' (4 pixels; first at x=2 y=3: (inf, 0.5, 0.5, 1); "
                                 "there the inputs held: ramp → target 'ramp' (0, 1, 0, 1))\n"))
        << drawing.err;
    EXPECT_TRUE(has(drawing.err, "rmfx: check: 3 passes counted what they wrote while drawing, 0 inspected after they ran\n"))
        << drawing.err;
    CommandResult after = runRmfx("render bad.xml --check-method after-pass -o bad.exr", dir.path());
    EXPECT_TRUE(has(after.err, "rmfx: check: 0 passes counted what they wrote while drawing, 3 inspected after they ran\n"))
        << after.err;
    EXPECT_NE(runRmfx("render bad.xml --check-method sometimes -o bad.exr", dir.path()).status, 0);
    CommandResult quiet = runRmfx("render bad.xml --check -q -o bad.exr", dir.path());
    EXPECT_EQ(quiet.status, 4);
    EXPECT_TRUE(has(quiet.err, "rmfx: check: error: frame 0: pass 'ratio' wrote +Inf")) << quiet.err;
    EXPECT_FALSE(has(quiet.err, "warning")) << quiet.err;

    dir.write("good.xml", workspace("abs(r.x) + 1.0"));
    CommandResult good = runRmfx("render good.xml --check --frames 2 -o good.exr", dir.path());
    EXPECT_EQ(good.status, 0) << good.err;
    EXPECT_TRUE(has(good.err, "rmfx: check: 3 passes a frame, 2 frames: no NaN, +Inf, -Inf, values at the format's largest\n"))
        << good.err;

    CommandResult sequence = runRmfx("render good.xml --check --input shot.%04d.exr -o out.%04d.png", dir.path());
    EXPECT_EQ(sequence.status, 1);
    EXPECT_TRUE(has(sequence.err, "--check inspects a single run")) << sequence.err;
}

}  // namespace
}  // namespace rmfx::test
