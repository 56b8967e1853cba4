// `rmfx edit` in a real window under Xvfb (Mesa llvmpipe through GLX): the effect must appear 1:1
// at the window's top-left corner exactly as `rmfx render` writes it, with the panel beside it.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

bool haveXvfbRun() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// Runs rmfx with `arguments` under a fresh Xvfb display (1280x800, 24-bit) in `folder`. Under the
// sanitizer preset the window's GLX driver, unloaded before exit, leaves 240 bytes that LeakSanitizer
// can only attribute to "<unknown module>" (no frame of rmfx's), so leak checking is off for this
// child alone; AddressSanitizer and UBSan still check it.
CommandResult runUnderXvfb(const std::string& arguments, const std::filesystem::path& folder) {
    return runRmfx(arguments, folder,
                   "xvfb-run -a -s '-screen 0 1280x800x24' env ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\"");
}

int byteAt(const Image& image, int x, int y, int c) { return static_cast<int>(std::lround(image.at(x, y, c) * 255.0f)); }

}  // namespace

TEST(EditorWindowGLTest, ShowsTheEffectAsRenderWritesItBesideThePanel) {
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is not installed: the editor's window test needs it "
                                  "(Debian packages xvfb and xauth; bash scripts/setup.sh installs them)";
    ScratchDir dir;
    const std::string workspace = shellQuoted(sourceDir() / "effects/shader_1.xml");
    CommandResult edit = runUnderXvfb("edit " + workspace + " --size 256x256 --frames 5 --screenshot window.png", dir.path());
    ASSERT_EQ(edit.status, 0) << edit.err;
    CommandResult render = runRmfx("render " + workspace + " --size 256x256 -o render.png -q", dir.path());
    ASSERT_EQ(render.status, 0) << render.err;

    Result<Image> window = readImage(dir / "window.png");
    Result<Image> expected = readImage(dir / "render.png");
    ASSERT_TRUE(window) << window.error();
    ASSERT_TRUE(expected) << expected.error();
    ASSERT_EQ(window->width, 256 + 460);  // the effect plus the panel
    ASSERT_EQ(window->height, 720);       // at least 720 tall

    int worst = 0, worstX = 0, worstY = 0;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x)
            for (int c = 0; c < 3; ++c) {
                int d = std::abs(byteAt(*window, x, y, c) - byteAt(*expected, x, y, c));
                if (d > worst) worst = d, worstX = x, worstY = y;
            }
    EXPECT_LE(worst, 2) << "the window's effect region differs from rmfx render by " << worst << " codes at " << worstX
                        << ", " << worstY;

    // The panel draws text and widgets: many pixels well brighter than its dark background.
    int bright = 0;
    for (int y = 0; y < window->height; ++y)
        for (int x = 256; x < window->width; ++x)
            if (byteAt(*window, x, y, 0) + byteAt(*window, x, y, 1) + byteAt(*window, x, y, 2) > 300) ++bright;
    EXPECT_GT(bright, 2000) << "the panel looks empty";
}

TEST(EditorWindowGLTest, SetOverridesAsRenderDoes) {
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is not installed (Debian packages xvfb and xauth; bash scripts/setup.sh)";
    ScratchDir dir;
    const std::string workspace = shellQuoted(sourceDir() / "effects/shader_1.xml");
    CommandResult edit = runUnderXvfb("edit " + workspace +
                                          " --size 64x48 --set Exposure_Level=3 --frames 2 --output-screenshot edit.png",
                                      dir.path());
    ASSERT_EQ(edit.status, 0) << edit.err;
    CommandResult render =
        runRmfx("render " + workspace + " --size 64x48 --set Exposure_Level=3 --frames 2 -o render.png -q", dir.path());
    ASSERT_EQ(render.status, 0) << render.err;
    EXPECT_EQ(readText(dir / "edit.png").size() > 0, true);
    Result<Image> a = readImage(dir / "edit.png"), b = readImage(dir / "render.png");
    ASSERT_TRUE(a && b);
    ASSERT_EQ(a->width, 64);
    ASSERT_EQ(a->height, 48);
    EXPECT_EQ(a->pixels, b->pixels);
}

// rmfx edit --input: the effect takes the image's size; with --split the input shows left of the
// line (clamped and sRGB-encoded, computed here in double) and the output right of it, as
// rmfx render --input writes it.
TEST(EditorWindowGLTest, BeforeAndAfterShowTheInputBesideTheOutput) {
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is not installed (Debian packages xvfb and xauth; bash scripts/setup.sh)";
    ScratchDir dir;
    const int w = 80, h = 60;
    Image shot = blankHdrImage(w, h);
    auto input = [&](int x, int y, int c) { return c == 0 ? 3.0 * x / w : c == 1 ? static_cast<double>(y) / h : 0.25; };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c)
                shot.pixels[(static_cast<size_t>(y) * w + x) * 4 + c] = c == 3 ? 1.0f : static_cast<float>(input(x, y, c));
    ASSERT_TRUE(writeImage(dir / "shot.exr", shot));
    const std::string workspace = shellQuoted(sourceDir() / "effects/shader_1.xml");
    CommandResult edit = runUnderXvfb("edit " + workspace + " --input shot.exr --split 0.5 --frames 2 --screenshot window.png",
                                      dir.path());
    ASSERT_EQ(edit.status, 0) << edit.err;
    CommandResult render = runRmfx("render " + workspace + " --input shot.exr --frames 2 -o render.png -q", dir.path());
    ASSERT_EQ(render.status, 0) << render.err;
    Result<Image> window = readImage(dir / "window.png"), output = readImage(dir / "render.png");
    ASSERT_TRUE(window && output);
    ASSERT_EQ(window->width, w + 460) << "the effect is the image's width";

    auto srgbByte = [](double v) {
        v = std::clamp(v, 0.0, 1.0);
        v = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
        return static_cast<int>(std::lround(v * 255.0));
    };
    // Clear of the line (x = 40) and of its labels (the top 20 rows).
    int worstBefore = 0, worstAfter = 0, differing = 0, compared = 0;
    for (int y = 20; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (std::abs(x - w / 2) <= 2) continue;
            for (int c = 0; c < 3; ++c) {
                const int before = srgbByte(input(x, y, c)), after = byteAt(*output, x, y, c);
                const int shown = byteAt(*window, x, y, c);
                if (x < w / 2) {
                    worstBefore = std::max(worstBefore, std::abs(shown - before));
                    differing += std::abs(after - before) > 8;
                    ++compared;
                } else {
                    worstAfter = std::max(worstAfter, std::abs(shown - after));
                }
            }
        }
    EXPECT_LE(worstBefore, 1) << "left of the line: the input image";
    EXPECT_LE(worstAfter, 2) << "right of the line: the output";
    EXPECT_GT(differing, compared / 2) << "the input and the output must differ for this test to tell them apart";
}

TEST(EditorWindowGLTest, AnInvalidWorkspaceIsAnErrorNamingIt) {
    ScratchDir dir;
    dir.write("broken.xml", "<workspace version=\"1\">\n  <float name=\"x\"/>\n</workspace>\n");
    CommandResult edit = runRmfx("edit broken.xml --frames 1", dir.path());
    EXPECT_EQ(edit.status, 1);
    EXPECT_NE(edit.err.find("broken.xml:2"), std::string::npos) << edit.err;
}

TEST(EditorWindowGLTest, AnInputThatCannotBeReadIsAnErrorNamingItBeforeAnyWindow) {
    ScratchDir dir;
    const std::string workspace = shellQuoted(sourceDir() / "effects/shader_1.xml");
    CommandResult edit = runRmfx("edit " + workspace + " --input missing.exr --frames 1", dir.path());
    EXPECT_EQ(edit.status, 1);
    EXPECT_NE(edit.err.find("missing.exr"), std::string::npos) << edit.err;
}

// rmfx edit --check: a target holding NaN gets a red badge under its thumbnail; without --check
// the same window has no such red.
TEST(EditorWindowGLTest, TheHealthCheckPutsARedBadgeUnderATargetHoldingNan) {
    ASSERT_TRUE(haveXvfbRun()) << "xvfb-run is not installed (Debian packages xvfb and xauth; bash scripts/setup.sh)";
    ScratchDir dir;
    dir.write("nan.xml", R"(<workspace version="1" name="nan" size="64x64">
  <target name="broken" format="rgba16f" scale="1"/>
  <pass name="divide" target="broken">
    <shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() { float zero = gl_FragCoord.x * 0.0; fragColor = vec4(zero / zero, 0.2, 0.2, 1.0); }
]]></shader>
  </pass>
  <pass name="final">
    <sampler name="b" target="broken" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D b;
out vec4 fragColor;
void main() { fragColor = vec4(vec3(0.2) + 0.0 * texelFetch(b, ivec2(gl_FragCoord.xy), 0).g, 1.0); }
]]></shader>
  </pass>
</workspace>
)");
    auto redPixels = [&](const std::string& options) {
        CommandResult edit = runUnderXvfb("edit nan.xml --frames 2 --screenshot window.png " + options, dir.path());
        EXPECT_EQ(edit.status, 0) << edit.err;
        Result<Image> window = readImage(dir / "window.png");
        EXPECT_TRUE(window) << window.error();
        int red = 0;
        if (window)
            for (int y = 0; y < window->height; ++y)
                for (int x = 64; x < window->width; ++x)
                    if (byteAt(*window, x, y, 0) > 220 && byteAt(*window, x, y, 1) < 110 && byteAt(*window, x, y, 2) < 110) ++red;
        return red;
    };
    EXPECT_GT(redPixels("--check"), 20) << "no red badge text in the panel";
    EXPECT_EQ(redPixels(""), 0);
}

}  // namespace rmfx::test
