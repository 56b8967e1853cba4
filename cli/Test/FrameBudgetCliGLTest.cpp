// A fragment shader that loops for hours does not hang `rmfx render` or `rmfx replay`: the frame
// budget stops the process with exit status 3 and a message naming the frame and workspace, and
// replay leaves a JUnit report with the case as an error.
#include <gtest/gtest.h>

#include "core/FrameWatchdog.h"
#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;

// 4M fragments of up to 2^40 dependent iterations each: far longer than the budget anywhere.
// llvmpipe ends loops after 65535 iterations, so there it is the fragment count that makes the
// frame last (tens of seconds on two cores).
const char* kSpinningWorkspace = R"(<workspace version="1" size="2048x2048">
  <float name="Seed" value="0.1"/>
  <pass name="spin">
    <shader stage="fragment"><![CDATA[
uniform float Seed;
out vec4 color;
void main() {
    float x = Seed + gl_FragCoord.x;
    for (int i = 0; i < 1048576; ++i)
        for (int j = 0; j < 1048576; ++j) x = fract(x * 1.618034 + Seed);
    color = vec4(x);
}
]]></shader>
  </pass>
</workspace>
)";

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(FrameBudgetCliGLTest, RenderStopsASpinningShaderWithStatusThree) {
    ScratchDir dir;
    dir.write("spin.xml", kSpinningWorkspace);
    auto started = std::chrono::steady_clock::now();
    CommandResult r = runRmfx("render spin.xml --frame-budget 1 -o spin.png", dir.path());
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_EQ(r.status, kExitFrameBudget) << r.err;
    EXPECT_TRUE(has(r.err, "rmfx: error: frame 1 of spin.xml did not finish within the frame budget of 1 s")) << r.err;
    EXPECT_FALSE(fs::exists(dir / "spin.png"));
    EXPECT_LT(seconds, 60.0);  // not a timing assertion: the shader alone runs for hours
}

TEST(FrameBudgetCliGLTest, ASequenceStopsAtTheFrameThatSpins) {
    ScratchDir dir;
    std::string spinning = kSpinningWorkspace;
    spinning.replace(spinning.find("  <pass"), 0, "  <input name=\"frame\"/>\n");
    spinning.replace(spinning.find("    <shader"), 0, "    <sampler name=\"Frame\" texture=\"frame\"/>\n");
    spinning.replace(spinning.find("uniform float Seed;"), 0, "uniform sampler2D Frame;\n");
    spinning.replace(spinning.find("float x = Seed"), 0, "float x0 = texture(Frame, vec2(0.5)).r;\n    ");
    spinning.replace(spinning.find("color = vec4(x);"), 16, "color = vec4(x + x0);");
    dir.write("spin.xml", spinning);
    std::filesystem::create_directories(dir / "shot");
    ASSERT_TRUE(writeImage(dir / "shot/f.0001.exr", blankHdrImage(4, 4)));
    ASSERT_TRUE(writeImage(dir / "shot/f.0002.exr", blankHdrImage(4, 4)));
    CommandResult r = runRmfx("render spin.xml --input shot/f.%04d.exr --frame-budget 1 -o out.%04d.png", dir.path());
    EXPECT_EQ(r.status, kExitFrameBudget) << r.err;
    EXPECT_TRUE(has(r.err, "frame 1 (shot/f.0001.exr) of spin.xml did not finish within the frame budget of 1 s")) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.0001.png"));
}

TEST(FrameBudgetCliGLTest, ReplayReportsTheCaseAsAnErrorAndStops) {
    ScratchDir dir;
    dir.write("spin.xml", kSpinningWorkspace);
    dir.write("manifest.xml", R"(<replay version="1">
  <case name="spinning" workspace="spin.xml">
    <compare reference="refs/spin.exr"/>
  </case>
  <case name="after" workspace="spin.xml">
    <compare reference="refs/after.exr"/>
  </case>
</replay>
)");
    CommandResult r = runRmfx("replay manifest.xml --frame-budget 1 --junit report.xml", dir.path());
    EXPECT_EQ(r.status, kExitFrameBudget) << r.err;
    EXPECT_TRUE(has(r.err, "rmfx replay: error: case 'spinning': frame 1 of ")) << r.err;
    EXPECT_TRUE(has(r.err, "stopping, the cases after it did not run")) << r.err;
    EXPECT_FALSE(has(r.out, "after ...")) << r.out;
    std::string report = readText(dir / "report.xml");
    EXPECT_TRUE(has(report, "<testcase name=\"spinning\"")) << report;
    EXPECT_TRUE(has(report, "<error message=\"frame 1 of ")) << report;
}

}  // namespace
}  // namespace rmfx::test
