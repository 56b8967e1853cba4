// `rmfx replay`: a tiny workspace and manifest in a scratch folder, references written with
// --update, replays that pass, then a changed variable or shader that fails with the metrics,
// the diff and actual images and a JUnit report; an itp compare whose diff holds ΔE_ITP; --case,
// broken cases, exit statuses.

#include <cmath>
#include <cstdlib>
#include <regex>

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include "io/image/ColorDifferenceItp.h"
#include "io/image/ImageIO.h"
#include "io/image/RgbePacking.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;

class CliReplayGLTest : public GlTest {};

// 16x16 by default. `base` holds (u, v, blue, 1) with u, v the pixel centre's texture coordinate:
// (x + 0.5) / 16 = (2x + 1) / 32, exact in half and float. The output is base.rgb · Gain.
std::string tinyWorkspace(const std::string& blue = "0.25") {
    return R"(<workspace version="1" name="tiny" size="16x16">
  <float name="Gain" value="1"/>
  <target name="base" format="rgba32f" scale="1"/>
  <pass name="gradient" target="base">
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform vec2 rm_InvTargetSize;
out vec4 fragColor;
void main() { fragColor = vec4(gl_FragCoord.xy * rm_InvTargetSize, )" +
           blue + R"(, 1.0); }
]]></shader>
  </pass>
  <pass name="final">
    <sampler name="src" target="base" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D src;
uniform float Gain;
out vec4 fragColor;
void main() { fragColor = vec4(texelFetch(src, ivec2(gl_FragCoord.xy), 0).rgb * Gain, 1.0); }
]]></shader>
  </pass>
</workspace>
)";
}

std::string tinyManifest(const std::string& gain = "1") {
    return lines({
        "<replay version=\"1\">",
        "  <defaults size=\"16x16\"/>",
        "  <case name=\"tiny\" workspace=\"fx/tiny.xml\">",
        "    <set name=\"Gain\" value=\"" + gain + "\"/>",
        "    <compare reference=\"refs/tiny.exr\" max=\"0.01\" store=\"half\"/>",
        "    <compare target=\"base\" reference=\"refs/tiny_base.exr\" error=\"relative\" max=\"0.2\"/>",
        "  </case>",
        "  <case name=\"second\" workspace=\"fx/tiny.xml\" size=\"8x4\">",
        "    <compare reference=\"refs/second.exr\"/>",
        "  </case>",
        "</replay>",
    });
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

Image readOk(const fs::path& file) {
    auto image = readImage(file);
    EXPECT_TRUE(image) << image.error();
    return image ? *image : Image{};
}

// The one <testsuite> of a JUnit report file, after checking its counts; nullptr (a test failure)
// when the file does not parse.
const tinyxml2::XMLElement* junitSuite(tinyxml2::XMLDocument& doc, const fs::path& file, const char* tests,
                                       const char* failures, const char* errors) {
    EXPECT_EQ(doc.LoadFile(file.c_str()), tinyxml2::XML_SUCCESS) << file;
    const tinyxml2::XMLElement* suite = doc.RootElement() ? doc.RootElement()->FirstChildElement("testsuite") : nullptr;
    EXPECT_TRUE(suite) << file;
    if (!suite) return nullptr;
    EXPECT_STREQ(suite->Attribute("tests"), tests);
    EXPECT_STREQ(suite->Attribute("failures"), failures);
    EXPECT_STREQ(suite->Attribute("errors"), errors);
    return suite;
}

// A scratch folder holding fx/tiny.xml and manifest.xml, references written with --update.
class Project {
public:
    Project() {
        dir_.write("fx/tiny.xml", tinyWorkspace());
        dir_.write("manifest.xml", tinyManifest());
    }
    const ScratchDir& dir() const { return dir_; }
    fs::path operator/(const std::string& name) const { return dir_ / name; }
    CommandResult replay(const std::string& options = "") const {
        return runRmfx("replay manifest.xml " + options, dir_.path());
    }
    void update() const {
        CommandResult r = replay("--update");
        ASSERT_EQ(r.status, 0) << r.out << r.err;
    }

private:
    ScratchDir dir_;
};

TEST_F(CliReplayGLTest, UpdateWritesTheReferencesAndTheReplayPasses) {
    Project p;
    CommandResult update = p.replay("--update");
    ASSERT_EQ(update.status, 0) << update.out << update.err;
    EXPECT_TRUE(has(update.out, "[1/2] tiny ... updated")) << update.out;
    EXPECT_TRUE(has(update.out, "    wrote refs/tiny.exr (output, 16x16, 4 channels, half)\n")) << update.out;
    EXPECT_TRUE(has(update.out, "    wrote refs/tiny_base.exr (base, 16x16, 4 channels, float)\n")) << update.out;
    EXPECT_TRUE(has(update.out, "[2/2] second ... updated")) << update.out;
    EXPECT_TRUE(has(update.out, "    wrote refs/second.exr (output, 8x4, 4 channels, float)\n")) << update.out;
    EXPECT_TRUE(has(update.out, "replay: 2 of 2 cases passed, 0 failed; 3 references written\n")) << update.out;
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
    EXPECT_TRUE(has(replay.out, "[1/2] tiny ... ok (")) << replay.out;
    EXPECT_TRUE(has(replay.out, "[2/2] second ... ok (")) << replay.out;
    EXPECT_TRUE(has(replay.out, "replay: 2 of 2 cases passed, 0 failed; 3 of 3 compares passed, 0 failed\n"))
        << replay.out;
    EXPECT_FALSE(fs::exists(p / "replay-out/tiny"));
}

TEST_F(CliReplayGLTest, AChangedVariableFailsWithMetricsImagesAndJUnit) {
    Project p;
    p.update();
    p.dir().write("manifest.xml", tinyManifest("1.5"));
    CommandResult r = p.replay("--junit reports/junit.xml");
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    // Gain 1.5 adds half of u and v: the largest error is 31/64 = 0.484375 (the top row's v,
    // the right column's u); base is unchanged.
    EXPECT_TRUE(has(r.out, "[1/2] tiny ... FAILED (")) << r.out;
    EXPECT_TRUE(has(r.out, "    output: FAILED: max error 0.484375 > 0.01 at x=")) << r.out;
    EXPECT_TRUE(has(r.out, "      diff:   replay-out/tiny/output.diff.exr\n")) << r.out;
    EXPECT_TRUE(has(r.out, "      actual: replay-out/tiny/output.actual.exr\n")) << r.out;
    EXPECT_TRUE(has(r.out, "    base: ok (max relative error 0 ≤ 0.2)\n")) << r.out;
    EXPECT_TRUE(has(r.out, "    which pass broke: no targets stored in refs/tiny.targets/ (rmfx replay --update "
                           "--all-targets stores them)\n"))
        << r.out;
    EXPECT_TRUE(has(r.out, "[2/2] second ... ok (")) << r.out;
    EXPECT_TRUE(has(r.out, "replay: 1 of 2 cases passed, 1 failed; 2 of 3 compares passed, 1 failed\n")) << r.out;
    EXPECT_TRUE(has(r.out, "replay: wrote reports/junit.xml\n")) << r.out;

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

// Chromium ($RMFX_BROWSER, else chromium on the PATH; scripts/setup.sh installs it for the tests),
// or "" when there is none.
std::string browser() {
    if (const char* named = std::getenv("RMFX_BROWSER"); named && *named) return named;
    return std::system("command -v chromium >/dev/null 2>&1") == 0 ? "chromium" : "";
}

// The page after its scripts ran, as headless Chromium serialises it.
std::string browserDom(const std::string& program, const fs::path& page, const std::string& fragment,
                       const ScratchDir& dir) {
    fs::path dom = dir / "dom.html";
    std::string command = "timeout 120 " + program + " --headless --no-sandbox --disable-gpu --user-data-dir=" +
                          shellQuoted(dir / "browser-profile") + " --virtual-time-budget=10000 --dump-dom " +
                          shellQuoted("file://" + fs::absolute(page).string() + fragment) + " >" + shellQuoted(dom) +
                          " 2>" + shellQuoted(dir / "browser-stderr.txt");
    EXPECT_EQ(std::system(command.c_str()), 0) << command << "\n" << readText(dir / "browser-stderr.txt");
    return readText(dom);
}

std::vector<std::string> allMatches(const std::string& text, const std::string& pattern) {
    std::vector<std::string> found;
    const std::regex re(pattern);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
        found.push_back(it->size() > 1 ? (*it)[1].str() : it->str());
    return found;
}

// What the page shows of an HDR image at `ev`: each colour value packed as the report packs it,
// decoded, times 2^ev, clipped, sRGB-encoded and rounded to 8 bits; the mean of those bytes.
double expectedCanvasMean(const Image& image, double ev) {
    Image packed = packRgbe(image);
    auto byte = [&](int x, int y, int c) { return static_cast<int>(std::lround(packed.at(x, y, c) * 255.0)); };
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                double v = std::clamp(unpackRgbe(byte(x, y, c), byte(x, image.height + y, c)) * std::exp2(ev), 0.0, 1.0);
                double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
                sum += std::round(255.0 * encoded);
            }
    return sum / (3.0 * image.width * image.height);
}

// A replay with a failing case leaves a report a person can read: the failing case first (the
// manifest lists it second), every image painted, the exposure control brightening the picture
// by what the maths says, and links to EXRs that exist.
TEST_F(CliReplayGLTest, TheHtmlReportShowsTheFailingCaseFirstWithItsImagesAndAnExposureControl) {
    auto manifest = [](const std::string& gain) {
        return lines({"<replay version=\"1\">", "  <case name=\"second\" workspace=\"fx/tiny.xml\" size=\"8x4\">",
                      "    <compare reference=\"refs/second.exr\"/>", "  </case>",
                      "  <case name=\"tiny\" workspace=\"fx/tiny.xml\" size=\"16x16\">",
                      "    <set name=\"Gain\" value=\"" + gain + "\"/>",
                      "    <compare reference=\"refs/tiny.exr\" max=\"0.01\"/>",
                      "    <compare target=\"base\" reference=\"refs/tiny_base.exr\" pixel=\"0.001\"/>", "  </case>",
                      "</replay>"});
    };
    Project p;
    p.dir().write("manifest.xml", manifest("3"));
    CommandResult update = p.replay("--update --all-targets");
    ASSERT_EQ(update.status, 0) << update.out << update.err;
    CommandResult withUpdate = p.replay("--update --report report");
    EXPECT_EQ(withUpdate.status, 1);
    EXPECT_TRUE(has(withUpdate.err, "--report shows what a replay compared")) << withUpdate.err;

    p.dir().write("manifest.xml", manifest("4"));
    p.dir().write("report/img/notes.txt", "mine");  // not the report's: it stays
    p.dir().write("report/img/c7-gone.js", "stale");  // an earlier report's: it goes
    CommandResult r = p.replay("--report report");
    EXPECT_TRUE(fs::exists(p / "report/img/notes.txt"));
    EXPECT_FALSE(fs::exists(p / "report/img/c7-gone.js"));
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    EXPECT_TRUE(has(r.out, "replay: wrote report/index.html\n")) << r.out;
    const std::string html = readText(p / "report/index.html");
    ASSERT_FALSE(html.empty());
    EXPECT_LT(html.find("id=\"case-tiny\""), html.find("id=\"case-second\""));
    EXPECT_TRUE(fs::exists(p / "report/img/c1-tiny.js"));
    EXPECT_TRUE(fs::exists(p / "report/img/c1-tiny-0-output-heat0.png"));
    EXPECT_FALSE(has(html, "http://") || has(html, "https://")) << "the page must work offline";

    const std::string program = browser();
    if (program.empty()) GTEST_SKIP() << "no chromium to load the report in (scripts/setup.sh installs it)";
    const std::string dark = browserDom(program, p / "report/index.html", "#ev=-2", p.dir());
    const std::string bright = browserDom(program, p / "report/index.html", "#ev=1.5", p.dir());
    for (const std::string* dom : {&dark, &bright}) {
        EXPECT_FALSE(has(*dom, "data-error")) << *dom;
        std::vector<std::string> statuses = allMatches(*dom, "<section[^>]*data-status=\"([a-z]+)\"");
        ASSERT_EQ(statuses, (std::vector<std::string>{"failed", "passed"}));
        std::vector<std::string> canvases = allMatches(*dom, "<canvas[^>]*>");
        ASSERT_FALSE(canvases.empty());
        EXPECT_EQ(allMatches(*dom, "<body[^>]*data-painted=\"([0-9]+)\""),
                  std::vector<std::string>{std::to_string(canvases.size())});
        for (const std::string& canvas : canvases) EXPECT_TRUE(has(canvas, "data-state=\"shown\"")) << canvas;
        std::vector<std::string> heats = allMatches(*dom, "<img class=\"heat\"[^>]*>");
        EXPECT_EQ(heats.size(), 4u);  // output at its largest error and at its limit; base; first difference
        for (const std::string& heat : heats) EXPECT_TRUE(has(heat, "data-state=\"shown\"")) << heat;
    }
    auto mean = [](const std::string& dom, const std::string& id) {
        std::vector<std::string> m = allMatches(dom, "<canvas data-hdr=\"" + id + "\"[^>]*data-mean=\"([0-9.]+)\"");
        EXPECT_FALSE(m.empty()) << id;
        return m.empty() ? -1.0 : std::stod(m.front());
    };
    // Gain 4 puts values up to 3.9 in the output: the exposure decides what the page shows.
    Image actual = readOk(p / "replay-out/tiny/output.actual.exr");
    Image reference = readOk(p / "refs/tiny.exr");
    EXPECT_NEAR(mean(dark, "c1-tiny-0-output-actual"), expectedCanvasMean(actual, -2), 0.01);
    EXPECT_NEAR(mean(bright, "c1-tiny-0-output-actual"), expectedCanvasMean(actual, 1.5), 0.01);
    EXPECT_NEAR(mean(dark, "c1-tiny-0-output-reference"), expectedCanvasMean(reference, -2), 0.01);
    EXPECT_GT(mean(bright, "c1-tiny-0-output-actual"), mean(dark, "c1-tiny-0-output-actual") + 50);
    // The first difference is the last pass (base still matches), with its stored target.
    EXPECT_TRUE(has(bright, "first difference: pass 'final', target 'output'")) << bright;
    for (const std::string& href : allMatches(bright, "<a href=\"([^\"]+)\"")) {
        EXPECT_TRUE(has(href, ".exr")) << href;
        EXPECT_TRUE(fs::exists(p / "report" / href)) << href;
    }
    EXPECT_GE(allMatches(bright, "<a href=").size(), 6u);
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

TEST_F(CliReplayGLTest, CaseSelectsWhatRunsAndWhatUpdates) {
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

TEST_F(CliReplayGLTest, BrokenCasesFailWithTheirDiagnosticsAndTheOthersStillRun) {
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
    EXPECT_TRUE(has(r.out, "[1/3] broken ... FAILED")) << r.out;
    // The shader error is located in the workspace that has it.
    EXPECT_TRUE(has(r.out, "    fx/broken.xml:9: error: ")) << r.out;
    EXPECT_TRUE(has(r.out, "undeclared_blue")) << r.out;
    EXPECT_TRUE(has(r.out, "[2/3] unknown-target ... FAILED")) << r.out;
    EXPECT_TRUE(has(r.out, "    m.xml:7: error: <compare target=\"glare9\">: case 'unknown-target': the workspace has no "
                           "render target 'glare9' (it has: base; the output is 'output')\n"))
        << r.out;
    EXPECT_TRUE(has(r.out, "[3/3] good ... updated")) << r.out;
    EXPECT_TRUE(has(r.out, "replay: 1 of 3 cases passed, 2 failed; 1 reference written, 2 not run\n")) << r.out;
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

TEST_F(CliReplayGLTest, InvalidManifestOrArgumentsExitWith1) {
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

TEST_F(CliReplayGLTest, QuietPrintsOnlyFailingCases) {
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

TEST_F(CliReplayGLTest, NoGlContextExitsWith2) {
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
TEST_F(CliReplayGLTest, ACaseRunsTheEffectOnItsOwnInputImage) {
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
