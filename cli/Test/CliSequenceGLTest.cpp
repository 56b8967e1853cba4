// rmfx render with an image sequence: one output per input frame, in order, with dt = 1 / --fps
// and frame="previous" targets carried from frame to frame; a gap or a bad frame stops the run
// naming the file, keeping the frames already written.

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "reference/HdrLightingReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "cli/Test/AccumulateWorkspace.h"

namespace rmfx::test {
namespace {

class CliSequenceGLTest : public GlTest {};

// Frame k: every channel of pixel (x, y) is k + x / 10 + y / 100.
Image frameImage(int k) {
    Image image = blankHdrImage(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            for (int c = 0; c < 4; ++c) image.at(x, y, c) = static_cast<float>(k) + 0.1f * x + 0.01f * y;
    return image;
}

void writeFrames(const ScratchDir& dir, std::initializer_list<int> frames) {
    std::filesystem::create_directories(dir / "shot");
    for (int k : frames) {
        char name[32];
        std::snprintf(name, sizeof name, "shot/f.%04d.exr", k);
        ASSERT_TRUE(writeImage(dir / name, frameImage(k)).ok());
    }
}

TEST_F(CliSequenceGLTest, EachFrameIsRenderedInOrderCarryingTheLastFramesTargets) {
    ScratchDir dir;
    dir.write("acc.xml", kAccumulateWorkspace);
    writeFrames(dir, {1, 2, 3, 4});
    CommandResult cli = runRmfx("render acc.xml --input frame=shot/f.%04d.exr --fps 8 -o out.####.exr", dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    EXPECT_NE(cli.err.find("rmfx: 4/4 frames"), std::string::npos) << cli.err;  // not a terminal: plain lines
    EXPECT_NE(cli.err.find("rmfx: wrote 4 frames to out.####.exr"), std::string::npos) << cli.err;
    const double dt = 1.0 / 8.0;
    double sum[5][3] = {};
    for (int k = 1; k <= 4; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "out.%04d.exr", k);
        Result<Image> out = readImage(dir / name);
        ASSERT_TRUE(out.ok()) << out.error();
        ASSERT_EQ(out->width, 5);
        ASSERT_EQ(out->height, 3);
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x) {
                sum[x][y] += (k + 0.1 * x + 0.01 * y) * dt;
                EXPECT_NEAR(out->at(x, y, 0), sum[x][y], 1e-6 * sum[x][y]) << name << " pixel " << x << "," << y;
            }
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out.0005.exr"));
}

TEST_F(CliSequenceGLTest, AGapIsAnErrorNamingTheMissingFrameBeforeAnythingIsWritten) {
    ScratchDir dir;
    dir.write("acc.xml", kAccumulateWorkspace);
    writeFrames(dir, {1, 2, 4});
    CommandResult cli = runRmfx("render acc.xml --input frame=shot/f.%04d.exr -o out.%04d.exr", dir.path());
    EXPECT_NE(cli.status, 0);
    EXPECT_NE(cli.err.find("acc.xml: error: --input frame=shot/f.%04d.exr: shot/f.%04d.exr: frames 1 to 4 have gaps: shot/f.0003.exr is missing"),
              std::string::npos)
        << cli.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.0001.exr"));
}

TEST_F(CliSequenceGLTest, ABadFrameStopsTheRunNamingItAndKeepsTheFramesBefore) {
    ScratchDir dir;
    dir.write("acc.xml", kAccumulateWorkspace);
    writeFrames(dir, {1, 2, 3, 4});
    dir.write("shot/f.0003.exr", "not an EXR");
    CommandResult cli = runRmfx("render acc.xml --input frame=shot/f.%04d.exr -o out.%04d.exr", dir.path());
    EXPECT_EQ(cli.status, 2);
    EXPECT_NE(cli.err.find("acc.xml: error: --input frame=shot/f.%04d.exr: shot/f.0003.exr: cannot read image"), std::string::npos)
        << cli.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "out.0001.exr"));
    EXPECT_TRUE(std::filesystem::exists(dir / "out.0002.exr"));
    EXPECT_FALSE(std::filesystem::exists(dir / "out.0003.exr"));
}

TEST_F(CliSequenceGLTest, ASequenceNeedsAnOutputPattern) {
    ScratchDir dir;
    dir.write("acc.xml", kAccumulateWorkspace);
    writeFrames(dir, {1, 2});
    CommandResult cli = runRmfx("render acc.xml --input frame=shot/f.%04d.exr -o out.exr", dir.path());
    EXPECT_EQ(cli.status, 1);
    EXPECT_NE(cli.err.find("name the output frames with a pattern too"), std::string::npos) << cli.err;
}

// An <input> given one image stays the same for every frame of a sequence given for another.
TEST_F(CliSequenceGLTest, AStillImageForAnotherInputServesEveryFrame) {
    ScratchDir dir;
    dir.write("gain.xml", R"(<workspace version="1" name="gain" size="5x3">
  <input name="frame"/>
  <input name="gain"/>
  <pass name="multiply">
    <sampler name="Frame" texture="frame" filter="nearest"/>
    <sampler name="Gain" texture="gain" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
uniform sampler2D Frame;
uniform sampler2D Gain;
out vec4 c;
void main() { c = texelFetch(Frame, ivec2(gl_FragCoord.xy), 0) * texelFetch(Gain, ivec2(gl_FragCoord.xy), 0); }
]]></shader>
  </pass>
  <output format="rgba32f" transform="none"/>
</workspace>
)");
    writeFrames(dir, {1, 2, 3});
    Image gain = blankHdrImage(5, 3);
    auto gainAt = [](int x, int y) { return 0.5 + 0.25 * x - 0.125 * y; };
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            for (int c = 0; c < 4; ++c) gain.at(x, y, c) = static_cast<float>(gainAt(x, y));
    ASSERT_TRUE(writeImage(dir / "gain.exr", gain).ok());
    CommandResult cli = runRmfx("render gain.xml --input frame=shot/f.%04d.exr --input gain=gain.exr -o out.%04d.exr -q",
                                dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    for (int k = 1; k <= 3; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "out.%04d.exr", k);
        Result<Image> out = readImage(dir / name);
        ASSERT_TRUE(out.ok()) << out.error();
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x) {
                const double expected = (k + 0.1 * x + 0.01 * y) * gainAt(x, y);
                EXPECT_NEAR(out->at(x, y, 0), expected, 1e-6 * expected) << name << " pixel " << x << "," << y;
            }
    }
    CommandResult two = runRmfx("render gain.xml --input frame=shot/f.%04d.exr --input gain=shot/f.%04d.exr -o o.%04d.exr",
                                dir.path());
    EXPECT_EQ(two.status, 1);
    EXPECT_NE(two.err.find("one --input may be a sequence"), std::string::npos) << two.err;
}

// --preroll N: N frames of the first image before the first output, time running from -N dt, so
// the first output holds what N + 1 frames of the first image accumulate, and every later frame
// adds its own on top: sum after output k = (N + 1) image(1) dt + Σ_{j=2..k} image(j) dt.
TEST_F(CliSequenceGLTest, PrerollRendersTheFirstImageBeforeTheFirstOutput) {
    ScratchDir dir;
    dir.write("acc.xml", kAccumulateWorkspace);
    writeFrames(dir, {1, 2, 3});
    CommandResult cli = runRmfx("render acc.xml --input frame=shot/f.%04d.exr --fps 8 --preroll 5 -o out.%04d.exr", dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    const double dt = 1.0 / 8.0;
    for (int k = 1; k <= 3; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "out.%04d.exr", k);
        Result<Image> out = readImage(dir / name);
        ASSERT_TRUE(out.ok()) << out.error();
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x) {
                double expected = 6 * (1 + 0.1 * x + 0.01 * y) * dt;
                for (int j = 2; j <= k; ++j) expected += (j + 0.1 * x + 0.01 * y) * dt;
                EXPECT_NEAR(out->at(x, y, 0), expected, 1e-6 * expected) << name << " pixel " << x << "," << y;
            }
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out.0000.exr"));
}

// --dt sets a sequence's step (as 1 / --fps does); both at once is refused, never one ignored.
TEST_F(CliSequenceGLTest, DtIsTheStepOfASequenceAndCannotBeGivenWithFps) {
    ScratchDir dir;
    dir.write("acc.xml", kAccumulateWorkspace);
    writeFrames(dir, {1, 2});
    CommandResult cli = runRmfx("render acc.xml --input frame=shot/f.%04d.exr --dt 0.5 -o out.%04d.exr", dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    Result<Image> second = readImage(dir / "out.0002.exr");
    ASSERT_TRUE(second.ok()) << second.error();
    EXPECT_NEAR(second->at(4, 2, 0), (1.42 + 2.42) * 0.5, 1e-6);

    CommandResult both = runRmfx("render acc.xml --input frame=shot/f.%04d.exr --dt 0.5 --fps 2 -o both.%04d.exr", dir.path());
    EXPECT_EQ(both.status, 1);
    EXPECT_NE(both.err.find("--fps and --dt both set a sequence's time step"), std::string::npos) << both.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "both.0001.exr"));

    CommandResult single = runRmfx("render acc.xml --input frame=shot/f.0001.exr --preroll 3 -o single.exr", dir.path());
    EXPECT_EQ(single.status, 1);
    EXPECT_NE(single.err.find("--preroll is for sequences"), std::string::npos) << single.err;
}

// hdr_lighting's adaptation starts from 1.0; with --preroll N the first output has adapted for
// N + 1 frames of the first image, as the float64 closed form says (the tolerance as in
// HdrLightingGLTest.AdaptationConvergesToTheMeasuredLuminance).
TEST_F(CliSequenceGLTest, PrerollStartsHdrLightingAdaptedToTheFirstImage) {
    ScratchDir dir;
    std::filesystem::create_directories(dir / "shot");
    for (int k = 1; k <= 2; ++k) {
        Image grey = blankHdrImage(16, 16);
        for (float& v : grey.pixels) v = 0.05f;
        char name[32];
        std::snprintf(name, sizeof name, "shot/g.%04d.exr", k);
        ASSERT_TRUE(writeImage(dir / name, grey).ok());
    }
    const std::string workspace = shellQuoted(sourceDir() / "effects" / "hdr_lighting.xml");
    const double measured = 0.05 + hdr::kLogDelta;  // Lavg of a uniform image is Y + delta
    for (int preroll : {0, 9}) {
        const std::string out = "adapted" + std::to_string(preroll) + ".%04d.exr";
        CommandResult cli = runRmfx("render " + workspace + " --input shot/g.%04d.exr --dt 0.1 --preroll " +
                                        std::to_string(preroll) + " --target adapted -o " + out, dir.path());
        ASSERT_EQ(cli.status, 0) << cli.err;
        Result<Image> first = readImage(dir / ("adapted" + std::to_string(preroll) + ".0001.exr"));
        ASSERT_TRUE(first.ok()) << first.error();
        const double expected = hdr::adaptedAfter(1.0, measured, (preroll + 1) * 0.1);
        EXPECT_NEAR(first->at(0, 0, 0), expected, 2e-5 * (1.0 - measured) + 1e-4 * measured) << "preroll " << preroll;
    }
}

// A target or input name that does not exist is an argument error (exit status 1) for a sequence
// too, found before any frame renders.
TEST_F(CliSequenceGLTest, UnknownNamesAreArgumentErrorsBeforeTheFirstFrame) {
    ScratchDir dir;
    dir.write("acc.xml", kAccumulateWorkspace);
    writeFrames(dir, {1, 2});
    CommandResult target = runRmfx("render acc.xml --input frame=shot/f.%04d.exr --target nosuch -o t.%04d.exr", dir.path());
    EXPECT_EQ(target.status, 1) << target.err;
    EXPECT_NE(target.err.find("--target nosuch: the workspace has no such target"), std::string::npos) << target.err;
    CommandResult input = runRmfx("render acc.xml --input nosuch=shot/f.%04d.exr -o i.%04d.exr", dir.path());
    EXPECT_EQ(input.status, 1) << input.err;
    EXPECT_NE(input.err.find("--input nosuch=shot/f.%04d.exr: the workspace has no input 'nosuch' (its inputs: 'frame')"),
              std::string::npos)
        << input.err;
    for (const CommandResult* r : {&target, &input}) EXPECT_EQ(r->err.find("frames,"), std::string::npos) << r->err;
    EXPECT_FALSE(std::filesystem::exists(dir / "t.0001.exr"));
    EXPECT_FALSE(std::filesystem::exists(dir / "i.0001.exr"));
}

// Where the frames go is checked before the first one renders: exit status 1, no progress line.
TEST_F(CliSequenceGLTest, AnOutputPatternThatCannotBeWrittenFailsBeforeTheFirstFrame) {
    ScratchDir dir;
    dir.write("acc.xml", kAccumulateWorkspace);
    writeFrames(dir, {1, 2});
    for (const char* pattern : {"missing/out.%04d.exr", "out.%04d.xyz", "out.%4d.exr"}) {
        CommandResult cli = runRmfx(std::string("render acc.xml --input frame=shot/f.%04d.exr -o ") + pattern, dir.path());
        EXPECT_EQ(cli.status, 1) << pattern << ": " << cli.err;
        EXPECT_NE(cli.err.find(std::string("rmfx render: -o ") + pattern + ": "), std::string::npos) << cli.err;
        EXPECT_EQ(cli.err.find("frames,"), std::string::npos) << "a frame rendered first: " << cli.err;
    }
}

}  // namespace
}  // namespace rmfx::test
