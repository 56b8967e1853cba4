// rmfx render --input: a user's HDR image in place of the scene an effects workspace draws. The
// scene target must hold the image as the workspace's input pass defines it (float64 reference:
// NaN, ±Inf and negative channels as 0, times Exposure_Level, at most the largest half float,
// stored as half), at the image's own size; --explain says which passes the image replaced.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "reference/CpuImage.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class CliInputGLTest : public GlTest {};

// 37x23 (odd, not the workspace's 512x512), every channel different, with the hard values in
// the last row and column: NaN, ±Inf, negatives, above the largest half float, and tiny ones.
Image hardImage() {
    Image image = blankHdrImage(37, 23);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = 0.01f * static_cast<float>((x * 7 + y * 13 + c * 5) % 97) + 0.003f * c;
    const float special[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                             -std::numeric_limits<float>::infinity(), -2.0f, 1.0e6f, 40000.0f, 1.0e-6f};
    for (int i = 0; i < 7; ++i) {
        image.at(image.width - 1, i, i % 3) = special[i];
        image.at(i, image.height - 1, (i + 1) % 3) = special[i];
    }
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) image.at(x, y, 3) = 1.0f;
    return image;
}

// What input_scene.frag computes, before the rgba16f target stores it.
double expectedChannel(float value, double exposure) {
    double v = std::isfinite(value) && value > 0.0f ? static_cast<double>(value) : 0.0;
    return std::min(v * exposure, 65504.0);
}

// The half the target holds: the nearest one, or (llvmpipe converts by truncation) the one next to
// it toward zero; either is within one step of the half grid, 2^-10 of the value's binade.
void expectStoredAsHalf(double stored, double exact, const std::string& where) {
    const double nearest = roundToHalf(exact);
    const double step = exact > 0.0 ? std::ldexp(1.0, std::ilogb(exact) - 10) : 0.0;
    EXPECT_TRUE(stored == nearest || (stored < nearest && stored >= nearest - step && stored <= exact))
        << where << ": stored " << stored << ", exact " << exact << ", nearest half " << nearest;
}

TEST_F(CliInputGLTest, TheImageReplacesTheSceneAtItsOwnSize) {
    ScratchDir dir;
    Image input = hardImage();
    ASSERT_TRUE(writeImage(dir / "shot.exr", input).ok());
    std::filesystem::path out = dir / "scene.exr";
    std::string workspace = shellQuoted(sourceDir() / "effects/shader_1.xml");
    CommandResult cli = runRmfx("render " + workspace + " --input shot.exr --set Exposure_Level=1.5 --target scene -o " +
                                    shellQuoted(out),
                                dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    Result<Image> scene = readImage(out);
    ASSERT_TRUE(scene.ok()) << scene.error();
    ASSERT_EQ(scene->width, input.width);
    ASSERT_EQ(scene->height, input.height);
    for (int y = 0; y < input.height; ++y)
        for (int x = 0; x < input.width; ++x)
            for (int c = 0; c < 3; ++c)
                expectStoredAsHalf(scene->at(x, y, c), expectedChannel(input.at(x, y, c), 1.5),
                                   "pixel " + std::to_string(x) + "," + std::to_string(y) + " channel " + std::to_string(c));
}

TEST_F(CliInputGLTest, ExplainSaysWhichPassesTheImageReplaced) {
    ScratchDir dir;
    ASSERT_TRUE(writeImage(dir / "shot.exr", hardImage()).ok());
    std::string workspace = shellQuoted(sourceDir() / "effects/shader_1.xml");
    CommandResult with = runRmfx("render " + workspace + " --input scene=shot.exr --explain", dir.path());
    ASSERT_EQ(with.status, 0) << with.err;
    EXPECT_NE(with.out.find("'scene' comes from the image given for input 'scene'"), std::string::npos) << with.out;
    EXPECT_NE(with.out.find("37x23"), std::string::npos) << with.out;
    EXPECT_NE(with.out.find("inputs:\n  scene shot.exr (37x23) in place of target 'scene'\n"), std::string::npos) << with.out;
    CommandResult without = runRmfx("render " + workspace + " --size 16x16 --explain", dir.path());
    ASSERT_EQ(without.status, 0) << without.err;
    EXPECT_NE(without.out.find("no image given for input 'scene'"), std::string::npos) << without.out;
    EXPECT_NE(without.out.find("inputs:\n  scene no image given: the workspace draws target 'scene' itself\n"),
              std::string::npos)
        << without.out;
}

TEST_F(CliInputGLTest, BadInputsFailNamingTheFileAndWriteNothing) {
    ScratchDir dir;
    std::string workspace = shellQuoted(sourceDir() / "effects/shader_1.xml");
    std::filesystem::path out = dir / "never.png";
    CommandResult missing = runRmfx("render " + workspace + " --input nope.exr -o " + shellQuoted(out), dir.path());
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("nope.exr"), std::string::npos) << missing.err;
    ASSERT_TRUE(writeImage(dir / "shot.exr", hardImage()).ok());
    CommandResult unknown = runRmfx("render " + workspace + " --input sky=shot.exr -o " + shellQuoted(out), dir.path());
    EXPECT_EQ(unknown.status, 1);
    EXPECT_NE(unknown.err.find("the workspace has no input 'sky' (its inputs: 'scene')"), std::string::npos) << unknown.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace rmfx::test
