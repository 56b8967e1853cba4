// rmfx render --content-skip and --explain on a dim image: hdr_lighting's bloom and star are
// skipped by content, the explanation says why, and the image equals --content-skip off bit for
// bit (the acceptance, run as a user would).

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// 48x32 of 0.03: nothing reaches hdr_lighting's bright pass, and its gate (a bound of the bright pass
// from the luminance chain) says so.
Image dimImage() {
    Image dim = blankHdrImage(48, 32);
    for (size_t i = 0; i < dim.pixels.size(); ++i) dim.pixels[i] = i % 4 == 3 ? 1.0f : 0.03f;
    return dim;
}

TEST(CliContentSkipGLTest, ADimImageSkipsBloomAndStarAndTheImageIsTheSameBitForBit) {
    ScratchDir dir;
    ASSERT_TRUE(writeImage(dir / "dim.exr", dimImage()));
    const std::string workspace = shellQuoted(sourceDir() / "effects/hdr_lighting.xml");
    CommandResult on = runRmfx("render " + workspace + " --input dim.exr --frames 3 --explain -o on.exr", dir.path());
    ASSERT_EQ(on.status, 0) << on.err;
    EXPECT_TRUE(has(on.out, "  bloom: skipped by content: its gate 'glare_gate' holds no pixel with a non-zero red value, so its "
                            "source 'bright' holds none either\n"))
        << on.out;
    EXPECT_TRUE(has(on.out, "  bright_pass: drawn only where bloom, star run (only they read what it writes)\n")) << on.out;
    EXPECT_TRUE(has(on.out, "  star_source: drawn only where bloom, star run (only they read what it writes)\n")) << on.out;
    EXPECT_TRUE(has(on.out, "  star: skipped by content:")) << on.out;
    EXPECT_TRUE(has(on.out, "  final: drawn compiled without bloom, star where they are skipped (it reads what they hand on)\n"))
        << on.out;
    CommandResult off = runRmfx("render " + workspace + " --input dim.exr --frames 3 --content-skip off --explain -o off.exr",
                                dir.path());
    ASSERT_EQ(off.status, 0) << off.err;
    EXPECT_TRUE(has(off.out, "skipped by content (the last frame): nothing: --content-skip off")) << off.out;
    Result<Image> a = readImage(dir / "on.exr"), b = readImage(dir / "off.exr");
    ASSERT_TRUE(a && b);
    ASSERT_EQ(a->pixels.size(), b->pixels.size());
    EXPECT_TRUE(a->pixels == b->pixels) << "the image with content skip differs from the image without it";

    CommandResult bad = runRmfx("render " + workspace + " --content-skip maybe", dir.path());
    EXPECT_EQ(bad.status, 1);
    EXPECT_TRUE(has(bad.err, "--content-skip: expected on or off, got 'maybe'")) << bad.err;
}

// Asked for one of an effect's targets, the user gets what its passes write, not content skip's
// zeros (hdr_lighting's bloom writes alpha 1 from a zero source in the float encoding): the effect
// runs whatever its source holds, and --explain says why; star, which bloom does not need, is
// culled, not reported as run or skipped.
TEST(CliContentSkipGLTest, AnEffectsTargetAskedForRunsTheEffectOnADimImage) {
    ScratchDir dir;
    ASSERT_TRUE(writeImage(dir / "dim.exr", dimImage()));
    const std::string workspace = shellQuoted(sourceDir() / "effects/hdr_lighting.xml");
    CommandResult on = runRmfx("render " + workspace + " --input dim.exr --target bloom --explain -o on.exr", dir.path());
    ASSERT_EQ(on.status, 0) << on.err;
    EXPECT_TRUE(has(on.out, "  bloom: run whatever 'bright' holds: its target 'bloom' is read back after the frame, and holds "
                            "what its passes write\n"))
        << on.out;
    EXPECT_FALSE(has(on.out, "  star:")) << on.out;
    CommandResult off = runRmfx("render " + workspace + " --input dim.exr --target bloom --content-skip off -o off.exr", dir.path());
    ASSERT_EQ(off.status, 0) << off.err;
    Result<Image> a = readImage(dir / "on.exr"), b = readImage(dir / "off.exr");
    ASSERT_TRUE(a && b);
    ASSERT_FALSE(a->pixels.empty());
    EXPECT_EQ(a->at(0, 0, 3), 1.0f) << "what the bloom pass writes from a zero source";
    EXPECT_TRUE(a->pixels == b->pixels) << "the target with content skip differs from the target without it";
}

// The article's pipeline: its tone map reads the one skippable effect, bloom.
TEST(CliContentSkipGLTest, ExplainNamesThePassDrawnWithoutASkippedEffect) {
    ScratchDir dir;
    CommandResult run = runRmfx("render " + shellQuoted(sourceDir() / "effects/article_pipeline.xml") + " --size 64x64 --explain",
                                dir.path());
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_TRUE(has(run.out, "  tonemap: drawn compiled without bloom where it is skipped (it reads what it hands on)\n"))
        << run.out;
}

}  // namespace
}  // namespace rmfx::test
