// rmfx render --frame-range A-B --preroll N: one chunk of a shot, each frame at the time the whole
// shot's run gives it, after a warm-up of the N frames before A as that run renders them
// (io/media/SequenceChunk.h). Without frame-to-frame state a chunk equals the whole run bit for bit;
// with state it starts N frames early from the initial values, which hdr_lighting's adaptation
// forgets as 0.98^(30 dt) per frame (docs/sequences.md).

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "reference/HdrLightingReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "cli/Test/AccumulateWorkspace.h"

namespace rmfx::test {
namespace {

class CliFrameRangeGLTest : public GlTest {};

// No state: each output is its frame's image plus the frame's time in red.
const char* kTimed = R"(<workspace version="1" name="timed" size="5x3">
  <target name="out" format="rgba32f"/>
  <input name="frame"/>
  <pass name="timed" target="out">
    <sampler name="Frame" texture="frame" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
uniform sampler2D Frame;
uniform float rm_Time;
out vec4 c;
void main() { c = texelFetch(Frame, ivec2(gl_FragCoord.xy), 0) + vec4(rm_Time, 0.0, 0.0, 0.0); }
]]></shader>
  </pass>
  <output target="out" transform="none"/>
</workspace>
)";

std::string frameName(const std::string& prefix, int k) {
    char name[64];
    std::snprintf(name, sizeof name, "%s.%04d.exr", prefix.c_str(), k);
    return name;
}

// Frame k of a 5x3 shot (the size of the workspaces), asymmetric: pixel (x, y) holds k + x / 10 + y / 100 (row 0 the top).
void writeShot(const ScratchDir& dir, int first, int last) {
    std::filesystem::create_directories(dir / "shot");
    for (int k = first; k <= last; ++k) {
        Image image = blankHdrImage(5, 3);
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x)
                for (int c = 0; c < 4; ++c) image.at(x, y, c) = static_cast<float>(k) + 0.1f * x + 0.01f * y;
        ASSERT_TRUE(writeImage(dir / frameName("shot/f", k), image).ok());
    }
}

Image read(const ScratchDir& dir, const std::string& name) {
    Result<Image> image = readImage(dir / name);
    EXPECT_TRUE(image.ok()) << name << ": " << image.error();
    return image ? std::move(*image) : Image{};
}

TEST_F(CliFrameRangeGLTest, ChunksOfAStatelessEffectEqualTheWholeRunBitForBit) {
    ScratchDir dir;
    dir.write("timed.xml", kTimed);
    writeShot(dir, 101, 108);
    const std::string run = "render timed.xml --input frame=shot/f.%04d.exr --fps 4 --preroll 3 ";
    CommandResult whole = runRmfx(run + "-o whole.%04d.exr", dir.path());
    ASSERT_EQ(whole.status, 0) << whole.err;
    for (const char* range : {"101-103", "104-106", "107-108"}) {
        CommandResult chunk = runRmfx(run + "--frame-range " + range + " -o chunk.%04d.exr", dir.path());
        ASSERT_EQ(chunk.status, 0) << range << ": " << chunk.err;
        if (std::string(range) == "104-106")
            EXPECT_NE(chunk.err.find("wrote 3 frames to chunk.%04d.exr"), std::string::npos) << chunk.err;
    }
    for (int k = 101; k <= 108; ++k) {
        Image w = read(dir, frameName("whole", k)), c = read(dir, frameName("chunk", k));
        ASSERT_EQ(c.pixels.size(), w.pixels.size());
        EXPECT_EQ(c.pixels, w.pixels) << "frame " << k;
        // Frame k is the shot's (k - 101)th: time (k - 101) / 4, whichever chunk renders it.
        EXPECT_FLOAT_EQ(c.at(3, 1, 0), static_cast<float>(k) + 0.31f + (k - 101) * 0.25f) << "frame " << k;
        EXPECT_FLOAT_EQ(c.at(0, 0, 1), static_cast<float>(k)) << "frame " << k;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "whole.0100.exr"));
}

// The warm-up, frame by frame: the chunk 106-107 with --preroll 3 renders frames 103, 104 and 105
// before it, and nothing of the shot before 103; the chunk 102-103 with --preroll 3 reaches back
// before the shot, so it renders frame 101's image twice at negative times, then frame 101.
TEST_F(CliFrameRangeGLTest, TheWarmUpIsTheLastNFramesOfTheWholeRun) {
    ScratchDir dir;
    dir.write("acc.xml", kAccumulateWorkspace);
    writeShot(dir, 101, 108);
    const double dt = 0.5;
    const std::string run = "render acc.xml --input frame=shot/f.%04d.exr --dt 0.5 --preroll 3 ";
    ASSERT_EQ(runRmfx(run + "--frame-range 106-107 -o late.%04d.exr", dir.path()).status, 0);
    ASSERT_EQ(runRmfx(run + "--frame-range 102-103 -o early.%04d.exr", dir.path()).status, 0);
    EXPECT_FALSE(std::filesystem::exists(dir / "late.0105.exr"));
    EXPECT_FALSE(std::filesystem::exists(dir / "late.0108.exr"));
    EXPECT_FALSE(std::filesystem::exists(dir / "early.0101.exr"));
    auto value = [](int k, int x, int y) { return k + 0.1 * x + 0.01 * y; };
    for (int x = 0; x < 5; ++x)
        for (int y = 0; y < 3; ++y) {
            double late = 0;
            for (int k = 103; k <= 106; ++k) late += value(k, x, y) * dt;
            EXPECT_NEAR(read(dir, frameName("late", 106)).at(x, y, 0), late, 1e-6 * late);
            late += value(107, x, y) * dt;
            EXPECT_NEAR(read(dir, frameName("late", 107)).at(x, y, 0), late, 1e-6 * late);
            double early = 3 * value(101, x, y) * dt + value(102, x, y) * dt;  // two pre-roll frames and 101, then 102
            EXPECT_NEAR(read(dir, frameName("early", 102)).at(x, y, 0), early, 1e-6 * early);
        }
}

// hdr_lighting's adaptation a' = a + (m - a)(1 - 0.98^(30 dt)) is a contraction: two runs that see
// the same measurements differ, after n frames, by their first difference times 0.98^(30 dt n).
// A chunk starts from the target's initial 1 where the whole run had adapted to a_w, so at its
// frames the difference is |1 - a_w| 0.98^(30 dt n), n counting from the start of its warm-up.
TEST_F(CliFrameRangeGLTest, HdrLightingsAdaptationInAChunkFollowsItsStatedBound) {
    ScratchDir dir;
    std::filesystem::create_directories(dir / "shot");
    for (int k = 1; k <= 8; ++k) {
        Image grey = blankHdrImage(16, 16);
        for (float& v : grey.pixels) v = 0.02f * k;  // a brightening shot: every frame measures anew
        ASSERT_TRUE(writeImage(dir / frameName("shot/g", k), grey).ok());
    }
    const std::string workspace = shellQuoted(sourceDir() / "effects" / "hdr_lighting.xml");
    const std::string run = "render " + workspace + " --input shot/g.%04d.exr --dt 0.1 --preroll 2 --target adapted ";
    ASSERT_EQ(runRmfx(run + "-o whole.%04d.exr", dir.path()).status, 0);
    CommandResult chunk = runRmfx(run + "--frame-range 5-8 -o chunk.%04d.exr", dir.path());
    ASSERT_EQ(chunk.status, 0) << chunk.err;
    EXPECT_NE(chunk.err.find("2 frames of warm-up"), std::string::npos) << chunk.err;
    // The warm-up is frames 3 and 4; the whole run had adapted to a_w after frame 2.
    const double before = read(dir, frameName("whole", 2)).at(0, 0, 0);
    for (int k = 5; k <= 8; ++k) {
        const double w = read(dir, frameName("whole", k)).at(0, 0, 0), c = read(dir, frameName("chunk", k)).at(0, 0, 0);
        const double bound = std::abs(1.0 - before) * std::pow(0.98, 30 * 0.1 * (k - 2));
        EXPECT_NEAR(std::abs(c - w), bound, 2e-6 + 1e-4 * bound) << "frame " << k << ": whole " << w << ", chunk " << c;
    }
}

TEST_F(CliFrameRangeGLTest, BadRangesAreArgumentErrorsBeforeAnyFrame) {
    ScratchDir dir;
    dir.write("acc.xml", kAccumulateWorkspace);
    writeShot(dir, 1, 4);
    const std::string run = "render acc.xml --input frame=shot/f.%04d.exr ";
    for (const char* bad : {"x", "3-", "-3", "1-2-3", "1:3", ""}) {
        CommandResult cli = runRmfx(run + "--frame-range '" + bad + "' -o out.%04d.exr", dir.path());
        EXPECT_EQ(cli.status, 1) << bad;
        EXPECT_NE(cli.err.find("--frame-range"), std::string::npos) << cli.err;
    }
    CommandResult backwards = runRmfx(run + "--frame-range 3-2 -o out.%04d.exr", dir.path());
    EXPECT_EQ(backwards.status, 1);
    EXPECT_NE(backwards.err.find("--frame-range: 3-2: the first frame comes after the last"), std::string::npos) << backwards.err;
    CommandResult outside = runRmfx(run + "--frame-range 3-9 -o out.%04d.exr", dir.path());
    EXPECT_NE(outside.status, 0);
    EXPECT_NE(outside.err.find("3-9 reaches outside the sequence, whose frames are 1-4"), std::string::npos) << outside.err;
    CommandResult still = runRmfx("render acc.xml --input frame=shot/f.0001.exr --frame-range 1-2 -o out.exr", dir.path());
    EXPECT_EQ(still.status, 1);
    EXPECT_NE(still.err.find("--frame-range chooses frames of a sequence"), std::string::npos) << still.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.0003.exr"));
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

}  // namespace
}  // namespace rmfx::test
