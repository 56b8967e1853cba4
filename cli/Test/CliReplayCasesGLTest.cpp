// `rmfx replay`'s cases and arguments: --case selects what runs and updates, broken cases fail with
// their diagnostics while the others run, bad manifests and arguments and no GL context give their
// exit statuses, --quiet, and a case run on its own input image.

#include <gtest/gtest.h>

#include "tests/support/GlTestSupport.h"
#include "CliReplayTestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;
using namespace cli_replay;

class CliReplayCasesGLTest : public GlTest {};

TEST_F(CliReplayCasesGLTest, CaseSelectsWhatRunsAndWhatUpdates) {
    Project p;
    CommandResult update = p.replay("--update --case second");
    ASSERT_EQ(update.status, 0) << update.out << update.err;
    EXPECT_TRUE(has(update.out, "[1/1] second ... updated")) << update.out;
    EXPECT_FALSE(has(update.out, "tiny")) << update.out;
    EXPECT_TRUE(fs::exists(p / "refs/second.exr"));
    EXPECT_FALSE(fs::exists(p / "refs/tiny.exr"));

    CommandResult second = p.replay("--case second");
    EXPECT_EQ(second.status, 0) << second.out;
    EXPECT_TRUE(has(second.out, "replay: 1 of 1 case passed, 0 failed; 1 of 1 compares passed, 0 failed\n"))
        << second.out;

    // Without references the compares fail, and the render is kept to look at.
    CommandResult both = p.replay("--case tiny --case second");
    EXPECT_EQ(both.status, 1) << both.out;
    EXPECT_TRUE(has(both.out, "[1/2] tiny ... FAILED")) << both.out;
    EXPECT_TRUE(has(both.out,
                    "    output: FAILED: cannot read the reference: refs/tiny.exr: no such file (rmfx replay --update "
                    "writes it)\n      actual: replay-out/tiny/output.actual.exr\n"))
        << both.out;
    EXPECT_TRUE(has(both.out, "[2/2] second ... ok")) << both.out;
    EXPECT_TRUE(fs::exists(p / "replay-out/tiny/output.actual.exr"));
    EXPECT_FALSE(fs::exists(p / "replay-out/tiny/output.diff.exr"));

    CommandResult unknown = p.replay("--case third");
    EXPECT_EQ(unknown.status, 1);
    EXPECT_EQ(unknown.err, "rmfx replay: --case third: manifest.xml has no such case (it has: tiny, second)\n");
    EXPECT_EQ(unknown.out, "");
}

TEST_F(CliReplayCasesGLTest, BrokenCasesFailWithTheirDiagnosticsAndTheOthersStillRun) {
    ScratchDir dir;
    dir.write("fx/tiny.xml", tinyWorkspace());
    dir.write("fx/broken.xml", tinyWorkspace("undeclared_blue"));
    dir.write("m.xml", lines({
                           "<replay version=\"1\">",
                           "  <case name=\"broken\" workspace=\"fx/broken.xml\" size=\"4x4\">",
                           "    <compare reference=\"a.exr\"/>",
                           "  </case>",
                           "  <case name=\"unknown-target\" workspace=\"fx/tiny.xml\" size=\"4x4\">",
                           "    <set name=\"Gain\" value=\"2\"/>",
                           "    <compare target=\"glare9\" reference=\"b.exr\"/>",
                           "  </case>",
                           "  <case name=\"good\" workspace=\"fx/tiny.xml\" size=\"4x4\">",
                           "    <compare reference=\"c.exr\"/>",
                           "  </case>",
                           "</replay>",
                       }));
    CommandResult r = runRmfx("replay m.xml --update --junit j.xml", dir.path());
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    // Each line whole; glslang's own lines after its first error are not pinned.
    const std::string out = withoutTimes(r.out);
    EXPECT_TRUE(hasLine(out, "[1/3] broken ... FAILED (… s)")) << out;
    // The shader error is located in the workspace that has it.
    EXPECT_TRUE(hasLine(out, "    fx/broken.xml:9: error: <pass name=\"gradient\">: 'undeclared_blue' : undeclared identifier"))
        << out;
    EXPECT_TRUE(hasLine(out, "[2/3] unknown-target ... FAILED (… s)")) << out;
    EXPECT_TRUE(hasLine(out, "    m.xml:7: error: <compare target=\"glare9\">: case 'unknown-target': the workspace has no "
                             "render target 'glare9' (it has: base; the output is 'output')"))
        << out;
    EXPECT_TRUE(hasLine(out, "[3/3] good ... updated (… s)")) << out;
    EXPECT_TRUE(hasLine(out, "    wrote c.exr (output, 4x4, 4 channels, float)")) << out;
    EXPECT_TRUE(hasLine(out, "replay: 1 of 3 cases passed, 2 failed; 1 reference written, 2 not run")) << out;
    EXPECT_TRUE(hasLine(out, "replay: wrote j.xml")) << out;
    EXPECT_TRUE(fs::exists(dir / "c.exr"));
    EXPECT_FALSE(fs::exists(dir / "a.exr"));
    EXPECT_FALSE(fs::exists(dir / "b.exr"));

    tinyxml2::XMLDocument doc;
    const tinyxml2::XMLElement* suite = junitSuite(doc, dir / "j.xml", "3", "0", "2");
    ASSERT_TRUE(suite);
    const tinyxml2::XMLElement* unknown = suite->FirstChildElement("testcase")->NextSiblingElement("testcase");
    ASSERT_TRUE(unknown && unknown->FirstChildElement("error"));
    EXPECT_STREQ(unknown->FirstChildElement("error")->Attribute("message"),
                 "m.xml:7: error: <compare target=\"glare9\">: case 'unknown-target': the workspace has no render "
                 "target 'glare9' (it has: base; the output is 'output')");
}

TEST_F(CliReplayCasesGLTest, InvalidManifestOrArgumentsExitWith1) {
    ScratchDir dir;
    dir.write("m.xml", lines({"<replay version=\"1\">", "  <case name=\"a\" workspace=\"x.xml\">",
                              "    <compare reference=\"a.png\"/>", "  </case>", "</replay>"}));
    CommandResult bad = runRmfx("replay m.xml", dir.path());
    EXPECT_EQ(bad.status, 1);
    EXPECT_EQ(bad.err, "m.xml:3: error: <compare>: attribute 'reference': 'a.png' is not an OpenEXR file: references "
                       "are .exr files, which keep the render's float values\n");
    EXPECT_EQ(bad.out, "");

    CommandResult none = runRmfx("replay", dir.path());
    EXPECT_EQ(none.status, 1);
    EXPECT_EQ(none.err, "rmfx replay: name a manifest file (see rmfx --help and docs/replay.md)\n");
    CommandResult option = runRmfx("replay m.xml --outdir x", dir.path());
    EXPECT_EQ(option.status, 1);
    EXPECT_EQ(option.err, "rmfx replay: unknown option '--outdir' (see rmfx --help)\n");
    CommandResult value = runRmfx("replay m.xml --junit", dir.path());
    EXPECT_EQ(value.status, 1);
    EXPECT_EQ(value.err, "rmfx replay: --junit needs a value\n");
    CommandResult missing = runRmfx("replay nothere.xml", dir.path());
    EXPECT_EQ(missing.status, 1);
    EXPECT_EQ(missing.err, "nothere.xml: error: the file does not exist\n");
}

TEST_F(CliReplayCasesGLTest, QuietPrintsOnlyFailingCases) {
    Project p;
    p.update();
    CommandResult passing = p.replay("-q");
    EXPECT_EQ(passing.status, 0);
    EXPECT_EQ(passing.out, "");
    EXPECT_EQ(passing.err, "");
    p.dir().write("manifest.xml", tinyManifest("0.5"));
    CommandResult failing = p.replay("-q");
    EXPECT_EQ(failing.status, 1);
    EXPECT_EQ(failing.out.rfind("[1/2] tiny ... FAILED (", 0), 0u) << failing.out;
    EXPECT_FALSE(has(failing.out, "second")) << failing.out;
    EXPECT_FALSE(has(failing.out, "replay:")) << failing.out;
}

TEST_F(CliReplayCasesGLTest, NoGlContextExitsWith2) {
    Project p;
    // libglvnd finds no EGL vendor library: no display can be opened.
    CommandResult r = runRmfx("replay manifest.xml", p.dir().path(), "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json");
    EXPECT_EQ(r.status, 2) << r.out << r.err;
    EXPECT_TRUE(has(r.err, "rmfx replay: cannot open an EGL display")) << r.err;
    EXPECT_EQ(r.out, "");
}

// <input>: a case runs the effect on the user's own image, at the image's size. The workspace
// scales its scene by Gain = 2 in rgba32f with nearest sampling, so the reference --update writes
// is the image times 2 exactly; a changed image then fails the replay, and a missing one is an
// error at its <input> naming the file.
TEST_F(CliReplayCasesGLTest, ACaseRunsTheEffectOnItsOwnInputImage) {
    ScratchDir dir;
    dir.write("lift.xml", R"(<workspace version="1" name="lift" size="16x16">
  <float name="Gain" value="2"/>
  <target name="scene" format="rgba32f" scale="1"/>
  <input name="scene" replaces="scene"/>
  <pass name="draw" target="scene">
    <shader stage="fragment">#version 450 core
out vec4 fragColor;
void main() { fragColor = vec4(1.0); }</shader>
  </pass>
  <pass name="from_input" target="scene">
    <sampler name="Image" texture="scene" filter="nearest"/>
    <shader stage="fragment">#version 450 core
uniform sampler2D Image;
in vec2 vTexCoord;
out vec4 fragColor;
void main() { fragColor = texture(Image, vTexCoord); }</shader>
  </pass>
  <pass name="final">
    <sampler name="src" target="scene" filter="nearest"/>
    <shader stage="fragment">#version 450 core
uniform sampler2D src;
uniform float Gain;
in vec2 vTexCoord;
out vec4 fragColor;
void main() { fragColor = vec4(texture(src, vTexCoord).rgb * Gain, 1.0); }</shader>
  </pass>
  <output format="rgba32f" transform="none"/>
</workspace>)");
    auto shot = [&](float offset) {
        Image image = blankHdrImage(8, 4);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 8; ++x) {
                for (int c = 0; c < 3; ++c) image.at(x, y, c) = offset + 0.125f * x + 0.25f * y + 0.5f * c;
                image.at(x, y, 3) = 1.0f;
            }
        return image;
    };
    ASSERT_TRUE(writeImage(dir / "shot.exr", shot(0.0f)).ok());
    dir.write("m.xml", lines({"<replay version=\"1\">", "  <case name=\"mine\" workspace=\"lift.xml\">",
                              "    <input file=\"shot.exr\"/>", "    <compare reference=\"refs/mine.exr\"/>", "  </case>",
                              "  <case name=\"missing\" workspace=\"lift.xml\">", "    <input name=\"scene\" file=\"gone.exr\"/>",
                              "    <compare reference=\"refs/missing.exr\"/>", "  </case>", "</replay>"}));
    CommandResult update = runRmfx("replay m.xml --update --case mine", dir.path());
    ASSERT_EQ(update.status, 0) << update.out << update.err;
    Result<Image> reference = readImage(dir / "refs/mine.exr");
    ASSERT_TRUE(reference.ok()) << reference.error();
    ASSERT_EQ(reference->width, 8);
    ASSERT_EQ(reference->height, 4);
    Image original = shot(0.0f);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(reference->at(x, y, c), 2.0f * original.at(x, y, c)) << x << "," << y << "," << c;

    EXPECT_EQ(runRmfx("replay m.xml --case mine", dir.path()).status, 0);
    ASSERT_TRUE(writeImage(dir / "shot.exr", shot(0.5f)).ok());
    CommandResult changed = runRmfx("replay m.xml --case mine", dir.path());
    EXPECT_EQ(changed.status, 1);
    EXPECT_NE(changed.out.find("[1/1] mine ... FAILED"), std::string::npos) << changed.out;

    CommandResult missing = runRmfx("replay m.xml --case missing", dir.path());
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.out.find("m.xml:7: error: <input name=\"scene\" file=\"gone.exr\">: case 'missing': "),
              std::string::npos)
        << missing.out << missing.err;
    EXPECT_NE(missing.out.find("gone.exr"), std::string::npos) << missing.out;
}

}  // namespace
}  // namespace rmfx::test
