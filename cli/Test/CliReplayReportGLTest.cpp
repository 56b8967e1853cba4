// The HTML report `rmfx replay` leaves, as headless Chromium shows it: the failing case first, every
// image painted, the exposure control brightening by what the maths says, links that exist.

#include <cmath>
#include <cstdlib>
#include <regex>

#include <gtest/gtest.h>

#include "io/image/RgbePacking.h"
#include "tests/support/GlTestSupport.h"
#include "CliReplayTestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;
using namespace cli_replay;

class CliReplayReportGLTest : public GlTest {};

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
TEST_F(CliReplayReportGLTest, TheHtmlReportShowsTheFailingCaseFirstWithItsImagesAndAnExposureControl) {
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

}  // namespace
}  // namespace rmfx::test
