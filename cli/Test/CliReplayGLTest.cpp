// `rmfx replay` against stored references: --update writes them and the replay passes; a changed
// variable or shader fails with the metrics, the diff and actual images and a JUnit report; an itp
// compare's diff holds ΔE_ITP; stored targets name the pass that broke; check="true" finds an
// infinity the compare accepts.

#include <cmath>

#include <gtest/gtest.h>

#include "io/image/ColorDifferenceItp.h"
#include "tests/support/GlTestSupport.h"
#include "CliReplayTestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;
using namespace cli_replay;

class CliReplayGLTest : public GlTest {};

TEST_F(CliReplayGLTest, UpdateWritesTheReferencesAndTheReplayPasses) {
    Project p;
    CommandResult update = p.replay("--update");
    ASSERT_EQ(update.status, 0) << update.out << update.err;
    EXPECT_EQ(withoutTimes(update.out), lines({
                                            "[1/2] tiny ... updated (… s)",
                                            "    wrote refs/tiny.exr (output, 16x16, 4 channels, half)",
                                            "    wrote refs/tiny_base.exr (base, 16x16, 4 channels, float)",
                                            "[2/2] second ... updated (… s)",
                                            "    wrote refs/second.exr (output, 8x4, 4 channels, float)",
                                            "replay: 2 of 2 cases passed, 0 failed; 3 references written",
                                        }));
    EXPECT_EQ(update.err, "");

    // The references hold the render: row 0 is the top, so pixel (15, 0) is u = v = 31/32.
    Image output = readOk(p / "refs/tiny.exr");
    ASSERT_EQ(output.width, 16);
    ASSERT_EQ(output.height, 16);
    ASSERT_EQ(output.channels, 4);
    EXPECT_EQ(output.bitsPerChannel, 16);  // store="half"
    EXPECT_EQ(output.at(15, 0, 0), 31.0f / 32);
    EXPECT_EQ(output.at(15, 0, 1), 31.0f / 32);
    EXPECT_EQ(output.at(0, 15, 0), 1.0f / 32);
    EXPECT_EQ(output.at(0, 15, 1), 1.0f / 32);
    EXPECT_EQ(output.at(3, 7, 2), 0.25f);
    EXPECT_EQ(output.at(3, 7, 3), 1.0f);
    Image base = readOk(p / "refs/tiny_base.exr");
    EXPECT_EQ(base.bitsPerChannel, 32);
    EXPECT_EQ(base.at(5, 0, 0), 11.0f / 32);
    Image second = readOk(p / "refs/second.exr");
    EXPECT_EQ(second.width, 8);
    EXPECT_EQ(second.height, 4);
    EXPECT_EQ(second.at(7, 0, 1), 7.0f / 8);  // v of the top row of 4: 3.5 / 4

    CommandResult replay = p.replay();
    EXPECT_EQ(replay.status, 0) << replay.out << replay.err;
    EXPECT_EQ(withoutTimes(replay.out), lines({"[1/2] tiny ... ok (… s)", "[2/2] second ... ok (… s)",
                                               "replay: 2 of 2 cases passed, 0 failed; 3 of 3 compares passed, 0 failed"}));
    EXPECT_FALSE(fs::exists(p / "replay-out/tiny"));
}

TEST_F(CliReplayGLTest, AChangedVariableFailsWithMetricsImagesAndJUnit) {
    Project p;
    p.update();
    p.dir().write("manifest.xml", tinyManifest("1.5"));
    CommandResult r = p.replay("--junit reports/junit.xml");
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    // Gain 1.5 adds half of u and v: the largest error is 31/64 = 0.484375 (the top row's v,
    // the right column's u; the first found is the top left pixel's v); base is unchanged.
    EXPECT_EQ(withoutTimes(r.out), lines({
                                       "[1/2] tiny ... FAILED (… s)",
                                       "    output: FAILED: max error 0.484375 > 0.01 at x=0 y=0 channel 1",
                                       "      diff:   replay-out/tiny/output.diff.exr",
                                       "      actual: replay-out/tiny/output.actual.exr",
                                       "    base: ok (max relative error 0 ≤ 0.2)",
                                       "    which pass broke: no targets stored in refs/tiny.targets/ (rmfx replay --update "
                                       "--all-targets stores them)",
                                       "[2/2] second ... ok (… s)",
                                       "replay: 1 of 2 cases passed, 1 failed; 2 of 3 compares passed, 1 failed",
                                       "replay: wrote reports/junit.xml",
                                   }));

    Image diff = readOk(p / "replay-out/tiny/output.diff.exr");
    ASSERT_EQ(diff.width, 16);
    ASSERT_EQ(diff.channels, 4);
    EXPECT_EQ(diff.at(15, 0, 0), 31.0f / 64);
    EXPECT_EQ(diff.at(15, 0, 1), 31.0f / 64);
    EXPECT_EQ(diff.at(0, 15, 0), 1.0f / 64);
    EXPECT_EQ(diff.at(4, 4, 2), 0.125f);
    EXPECT_EQ(diff.at(4, 4, 3), 0.0f);
    Image actual = readOk(p / "replay-out/tiny/output.actual.exr");
    EXPECT_EQ(actual.at(15, 0, 0), 1.5f * 31 / 32);
    EXPECT_FALSE(fs::exists(p / "replay-out/tiny/base.diff.exr"));
    EXPECT_FALSE(fs::exists(p / "replay-out/second"));

    tinyxml2::XMLDocument doc;
    const tinyxml2::XMLElement* suite = junitSuite(doc, p / "reports/junit.xml", "2", "1", "0");
    ASSERT_TRUE(suite);
    const tinyxml2::XMLElement* tiny = suite->FirstChildElement("testcase");
    ASSERT_TRUE(tiny);
    EXPECT_STREQ(tiny->Attribute("name"), "tiny");
    EXPECT_STREQ(tiny->Attribute("classname"), "replay.manifest");
    const tinyxml2::XMLElement* failure = tiny->FirstChildElement("failure");
    ASSERT_TRUE(failure);
    EXPECT_EQ(std::string(failure->Attribute("message")).rfind("output: max error 0.484375 > 0.01 at x=", 0), 0u)
        << failure->Attribute("message");
    EXPECT_TRUE(has(failure->GetText(), "replay-out/tiny/output.diff.exr")) << failure->GetText();
    const tinyxml2::XMLElement* second = tiny->NextSiblingElement("testcase");
    ASSERT_TRUE(second);
    EXPECT_STREQ(second->Attribute("name"), "second");
    EXPECT_EQ(second->FirstChildElement(), nullptr);

    // Fixed again: the case passes and its old failure images are gone.
    p.dir().write("manifest.xml", tinyManifest("1"));
    CommandResult fixed = p.replay();
    EXPECT_EQ(fixed.status, 0) << fixed.out;
    EXPECT_FALSE(fs::exists(p / "replay-out/tiny/output.diff.exr"));
    EXPECT_FALSE(fs::exists(p / "replay-out/tiny/output.actual.exr"));
}

TEST_F(CliReplayGLTest, AChangedShaderFailsTheTargetsRelativeLimit) {
    Project p;
    p.update();
    p.dir().write("fx/tiny.xml", tinyWorkspace("0.3125"));
    CommandResult r = p.replay("--out results/run1 --case tiny");
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    // Blue 0.25 → 0.3125: absolute error 0.0625 in the output, relative 0.0625 / 0.25 in base.
    EXPECT_TRUE(has(r.out, "    output: FAILED: max error 0.0625 > 0.01 at x=")) << r.out;
    EXPECT_TRUE(has(r.out, "channel 2\n")) << r.out;
    EXPECT_TRUE(has(r.out, "    base: FAILED: max relative error 0.25 > 0.2 at x=")) << r.out;
    EXPECT_TRUE(has(r.out, "      diff:   results/run1/tiny/base.diff.exr\n")) << r.out;
    EXPECT_TRUE(has(r.out, "replay: 0 of 1 case passed, 1 failed; 0 of 2 compares passed, 2 failed\n")) << r.out;
    Image relative = readOk(p / "results/run1/tiny/base.diff.exr");
    EXPECT_EQ(relative.at(9, 9, 2), 0.25f);
    EXPECT_EQ(relative.at(9, 9, 0), 0.0f);
    EXPECT_FALSE(fs::exists(p / "replay-out"));
}

TEST_F(CliReplayGLTest, AnItpCompareFailsWithDeltaEPerPixelInItsDiff) {
    auto manifest = [](const std::string& gain) {
        return lines({"<replay version=\"1\">", "  <case name=\"hdr\" workspace=\"fx/tiny.xml\">",
                      "    <set name=\"Gain\" value=\"" + gain + "\"/>",
                      "    <compare reference=\"refs/hdr.exr\" error=\"itp\" luminance=\"1000\" mean=\"0.5\" "
                      "percentile=\"99\" percentile-max=\"1\"/>",
                      "  </case>", "</replay>"});
    };
    Project p;
    p.dir().write("manifest.xml", manifest("10"));
    p.update();
    // Gain 10 → 11: HDR values up to 10.7 (10 700 cd/m²) grow by 10 %, several ΔE_ITP.
    p.dir().write("manifest.xml", manifest("11"));
    CommandResult r = p.replay();
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "    output: FAILED: mean ΔE_ITP ")) << r.out;
    EXPECT_TRUE(has(r.out, "; 99th percentile ΔE_ITP ")) << r.out;
    Image diff = readOk(p / "replay-out/hdr/output.diff.exr");
    Image actual = readOk(p / "replay-out/hdr/output.actual.exr");
    Image reference = readOk(p / "refs/hdr.exr");
    ASSERT_EQ(diff.width, 16);
    ASSERT_EQ(diff.channels, 1);
    for (const auto& pixel : {std::pair{0, 0}, std::pair{15, 0}, std::pair{7, 9}}) {
        const int x = pixel.first, y = pixel.second;  // clang 14 cannot capture structured bindings
        auto itp = [&](const Image& image) {
            return itpFromBt709(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2), 1000);
        };
        double expected = deltaEItp(itp(actual), itp(reference));
        EXPECT_GT(expected, 1.0);
        EXPECT_NEAR(diff.at(x, y, 0), expected, 1e-6 * expected) << x << " " << y;
    }
}

// --update --all-targets stores base and output in pass order; a changed Gain then breaks the
// second pass (base still matches), a changed gradient the first, each named in the log and JUnit.
TEST_F(CliReplayGLTest, StoredTargetsNameThePassThatBroke) {
    Project p;
    CommandResult notAlone = p.replay("--all-targets");
    EXPECT_EQ(notAlone.status, 1);
    EXPECT_TRUE(has(notAlone.err, "rmfx replay: --all-targets goes with --update")) << notAlone.err;

    CommandResult update = p.replay("--update --all-targets");
    ASSERT_EQ(update.status, 0) << update.out << update.err;
    EXPECT_TRUE(has(update.out, "    wrote refs/tiny.targets/ (2 targets, in pass order: base, output)\n")) << update.out;
    EXPECT_TRUE(has(update.out, "    wrote refs/second.targets/ (2 targets, in pass order: base, output)\n"))
        << update.out;
    Image storedBase = readOk(p / "refs/tiny.targets/base.exr");
    ASSERT_EQ(storedBase.width, 16);
    EXPECT_EQ(storedBase.at(5, 0, 0), 11.0f / 32);
    EXPECT_EQ(readOk(p / "refs/second.targets/output.exr").width, 8);

    p.dir().write("manifest.xml", tinyManifest("1.5"));
    CommandResult gain = p.replay("--case tiny --junit junit.xml");
    EXPECT_EQ(gain.status, 1) << gain.out << gain.err;
    EXPECT_TRUE(has(gain.out, "    first difference: pass 'final' writing target 'output' (2 of 2 targets in pass "
                              "order): max error 0.484375 > 0.01 at x="))
        << gain.out;
    EXPECT_TRUE(has(gain.out, "      targets before it that match: base\n")) << gain.out;
    EXPECT_TRUE(has(gain.out, "      actual: replay-out/tiny/targets/output.actual.exr\n")) << gain.out;
    EXPECT_EQ(readOk(p / "replay-out/tiny/targets/output.diff.exr").at(15, 0, 0), 31.0f / 64);
    tinyxml2::XMLDocument doc;
    const tinyxml2::XMLElement* suite = junitSuite(doc, p / "junit.xml", "1", "1", "0");
    ASSERT_TRUE(suite);
    const tinyxml2::XMLElement* failure = suite->FirstChildElement("testcase")->FirstChildElement("failure");
    ASSERT_TRUE(failure);
    EXPECT_TRUE(has(failure->Attribute("message"), " | first difference at pass 'final' (target 'output')"))
        << failure->Attribute("message");

    // The gradient's blue 0.25 → 0.3125 breaks the first pass: base is compared with its own
    // compare's relative limit 0.2 (error 0.25), and the output after it is not looked at.
    p.dir().write("manifest.xml", tinyManifest("1"));
    p.dir().write("fx/tiny.xml", tinyWorkspace("0.3125"));
    CommandResult shader = p.replay("--case tiny");
    EXPECT_EQ(shader.status, 1) << shader.out << shader.err;
    EXPECT_TRUE(has(shader.out, "    first difference: pass 'gradient' writing target 'base' (1 of 2 targets in pass "
                                "order): max relative error 0.25 > 0.2 at x="))
        << shader.out;
    EXPECT_TRUE(has(shader.out, "      targets before it that match: none\n")) << shader.out;
    EXPECT_FALSE(fs::exists(p / "replay-out/tiny/targets/output.diff.exr"));
    EXPECT_TRUE(fs::exists(p / "replay-out/tiny/targets/base.diff.exr"));

    // An intended change: --update alone keeps the stored targets current, and the case passes.
    CommandResult again = p.replay("--update --case tiny");
    ASSERT_EQ(again.status, 0) << again.out << again.err;
    EXPECT_TRUE(has(again.out, "    wrote refs/tiny.targets/ (2 targets")) << again.out;
    EXPECT_EQ(readOk(p / "refs/tiny.targets/base.exr").at(3, 3, 2), 0.3125f);
    CommandResult passes = p.replay("--case tiny");
    EXPECT_EQ(passes.status, 0) << passes.out;
    EXPECT_FALSE(fs::exists(p / "replay-out/tiny"));
}

// check="true": an infinity the compare cannot see (the reference holds the same one) fails the
// case, naming the pass and pixel; without check the case passes.
TEST_F(CliReplayGLTest, ACheckedCaseFailsOnAnInfinityItsCompareAccepts) {
    auto manifest = [](const std::string& check) {
        return lines({"<replay version=\"1\">", "  <case name=\"inf\" workspace=\"fx/inf.xml\" size=\"8x2\"" + check + ">",
                      "    <compare reference=\"refs/inf.exr\"/>", "  </case>", "</replay>"});
    };
    Project p;
    p.dir().write("fx/inf.xml", tinyWorkspace("1.0 / (gl_FragCoord.x - 3.5)"));
    p.dir().write("manifest.xml", manifest(""));
    p.update();
    CommandResult unchecked = p.replay();
    EXPECT_EQ(unchecked.status, 0) << unchecked.out;
    p.dir().write("manifest.xml", manifest(" check=\"true\""));
    CommandResult checked = p.replay("--junit junit.xml");
    EXPECT_EQ(checked.status, 1) << checked.out;
    EXPECT_TRUE(has(checked.out, "[1/1] inf ... FAILED")) << checked.out;
    EXPECT_TRUE(has(checked.out, "manifest.xml:2: error: <case name=\"inf\" check=\"true\">: frame 0: pass 'gradient' wrote "
                                 "+Inf into target 'base' (2 pixels; first at x=3 y=1: (0.4375, 0.25, inf, 1)"))
        << checked.out;
    tinyxml2::XMLDocument doc;
    ASSERT_TRUE(junitSuite(doc, p / "junit.xml", "1", "0", "1"));
}

}  // namespace
}  // namespace rmfx::test
