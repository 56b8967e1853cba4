// Every workspace in effects/ writes an alpha that means something: 1 everywhere (opaque), as
// docs/effects.md ("Output alpha") states. The additive combines blend colour only
// (src-alpha="zero" dst-alpha="one"); before, their alpha summed to 1.36 .. 2.0, which a
// compositor reads as coverage. Rendered through the CLI to EXR, as a user would.

#include <filesystem>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;

class EffectsAlphaGLTest : public GlTest {};

TEST_F(EffectsAlphaGLTest, EveryEffectWritesAlphaOne) {
    ScratchDir dir;
    int effects = 0;
    for (const auto& entry : fs::directory_iterator(sourceDir() / "effects")) {
        if (entry.path().extension() != ".xml") continue;
        ++effects;
        const std::string name = entry.path().stem().string();
        const fs::path out = dir / (name + ".exr");
        CommandResult cli = runRmfx("render " + shellQuoted(entry.path()) + " --size 32x24 --frames 2 -q -o " + shellQuoted(out),
                                    dir.path());
        ASSERT_EQ(cli.status, 0) << name << ": " << cli.err;
        Result<Image> image = readImage(out);
        ASSERT_TRUE(image.ok()) << image.error();
        ASSERT_EQ(image->channels, 4) << name << ": the EXR has no alpha channel";
        float lowest = 1.0f, highest = 1.0f;
        for (int y = 0; y < image->height; ++y)
            for (int x = 0; x < image->width; ++x) {
                lowest = std::min(lowest, image->at(x, y, 3));
                highest = std::max(highest, image->at(x, y, 3));
            }
        EXPECT_EQ(lowest, 1.0f) << name << ": alpha from " << lowest << " to " << highest;
        EXPECT_EQ(highest, 1.0f) << name << ": alpha from " << lowest << " to " << highest;
    }
    EXPECT_GE(effects, 12);
}

}  // namespace
}  // namespace rmfx::test
