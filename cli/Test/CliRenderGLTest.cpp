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

}  // namespace
}  // namespace rmfx::test
