#include "io/media/ImageSequence.h"

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void touch(const test::ScratchDir& dir, const std::vector<std::string>& names) {
    for (const std::string& name : names) dir.write(name, "x");
}

std::vector<int> framesOf(const std::vector<SequenceFrame>& frames) {
    std::vector<int> numbers;
    for (const SequenceFrame& f : frames) numbers.push_back(f.frame);
    return numbers;
}

TEST(ImageSequencePattern, RecognisesPrintfAndHashFields) {
    EXPECT_TRUE(isSequencePattern("frame.%04d.exr"));
    EXPECT_TRUE(isSequencePattern("frame.%d.exr"));
    EXPECT_TRUE(isSequencePattern("frame.####.exr"));
    EXPECT_TRUE(isSequencePattern("frame#.exr"));
    EXPECT_TRUE(isSequencePattern("frame.%4d.exr"));  // recognised, refused by parseFramePattern
    EXPECT_FALSE(isSequencePattern("frame.0001.exr"));
    EXPECT_FALSE(isSequencePattern("100%%.exr"));
    EXPECT_FALSE(isSequencePattern("50%.exr"));
    EXPECT_FALSE(isSequencePattern("%s.exr"));
    EXPECT_FALSE(isSequencePattern(""));
}

TEST(ImageSequencePattern, FrameFileNames) {
    EXPECT_EQ(frameFileName("out/frame.%04d.png", 7), "out/frame.0007.png");
    EXPECT_EQ(frameFileName("out/frame.%04d.png", 12345), "out/frame.12345.png");  // wider than the padding
    EXPECT_EQ(frameFileName("frame.%d.exr", 7), "frame.7.exr");
    EXPECT_EQ(frameFileName("frame.%d.exr", 0), "frame.0.exr");
    EXPECT_EQ(frameFileName("frame.%01d.exr", 3), "frame.3.exr");
    EXPECT_EQ(frameFileName("frame.####.exr", 42), "frame.0042.exr");
    EXPECT_EQ(frameFileName("frame.##.exr", 5), "frame.05.exr");
    EXPECT_EQ(frameFileName("frame.###.exr", 5), "frame.005.exr");
    EXPECT_EQ(frameFileName("frame.#.exr", 5), "frame.0005.exr");  // a single '#' is 4 digits
    EXPECT_EQ(frameFileName("frame####", 9), "frame0009");
    EXPECT_EQ(frameFileName("100%%_%03d.png", 9), "100%_009.png");
    EXPECT_EQ(frameFileName("50%_%d.png", 9), "50%_9.png");
    // Patterns parseFramePattern refuses come back unchanged.
    EXPECT_EQ(frameFileName("a.%04d.%04d.exr", 1), "a.%04d.%04d.exr");
    EXPECT_EQ(frameFileName("still.exr", 1), "still.exr");
}

TEST(ImageSequencePattern, ParseErrorsNameThePattern) {
    const Result<FramePattern> two = parseFramePattern("shot/a.%04d.b.####.exr");
    ASSERT_FALSE(two);
    EXPECT_EQ(two.error(), "shot/a.%04d.b.####.exr: 2 frame-number fields (%04d, ####); a pattern has one");
    const Result<FramePattern> none = parseFramePattern("still.exr");
    ASSERT_FALSE(none);
    EXPECT_EQ(none.error(), "still.exr: no frame-number field (%d, %04d or ####)");
    const Result<FramePattern> spaces = parseFramePattern("f.%4d.exr");
    ASSERT_FALSE(spaces);
    EXPECT_EQ(spaces.error(), "f.%4d.exr: %4d pads with spaces; use %04d");
    const Result<FramePattern> folder = parseFramePattern("shot%02d/frame.exr");
    ASSERT_FALSE(folder);
    EXPECT_TRUE(contains(folder.error(), "shot%02d/frame.exr: the frame number %02d is in a folder name")) << folder.error();
    EXPECT_FALSE(parseFramePattern("f.%012d.exr"));
    EXPECT_FALSE(parseFramePattern("f.##########.exr"));

    const Result<FramePattern> ok = parseFramePattern("shot/f.%05d.exr");
    ASSERT_TRUE(ok) << ok.error();
    EXPECT_EQ(ok->prefix, "shot/f.");
    EXPECT_EQ(ok->suffix, ".exr");
    EXPECT_EQ(ok->digits, 5);
}

TEST(ImageSequence, FindsPaddedFramesInOrderAndIgnoresOtherPaddings) {
    test::ScratchDir dir;
    touch(dir, {"shot/frame.0010.exr", "shot/frame.0008.exr", "shot/frame.0009.exr", "shot/frame.0011.exr",
                "shot/frame.12.exr", "shot/frame.00012.exr", "shot/frame.0013.png", "shot/frame.0014.exr.bak",
                "shot/frame.abcd.exr", "shot/other.0012.exr", "shot/frame..exr"});
    fs::create_directories(dir / "shot/frame.0015.exr");  // a folder, not a frame
    const std::string pattern = (dir / "shot/frame.%04d.exr").string();
    const Result<std::vector<SequenceFrame>> frames = findSequenceFrames(pattern);
    ASSERT_TRUE(frames) << frames.error();
    EXPECT_EQ(framesOf(*frames), (std::vector<int>{8, 9, 10, 11}));
    EXPECT_EQ((*frames)[0].path, dir / "shot/frame.0008.exr");
    EXPECT_EQ((*frames)[3].path, dir / "shot/frame.0011.exr");
}

TEST(ImageSequence, UnpaddedAndWiderThanPaddingFrames) {
    test::ScratchDir dir;
    touch(dir, {"f.9.exr", "f.10.exr", "f.11.exr", "f.011.exr", "f.8.exr"});
    const Result<std::vector<SequenceFrame>> unpadded = findSequenceFrames((dir / "f.%d.exr").string());
    ASSERT_TRUE(unpadded) << unpadded.error();
    EXPECT_EQ(framesOf(*unpadded), (std::vector<int>{8, 9, 10, 11}));  // f.011.exr is not %d's
    EXPECT_EQ((*unpadded)[2].path, dir / "f.10.exr");

    touch(dir, {"g.98.exr", "g.99.exr", "g.100.exr"});
    const Result<std::vector<SequenceFrame>> wide = findSequenceFrames((dir / "g.%02d.exr").string());
    ASSERT_TRUE(wide) << wide.error();
    EXPECT_EQ(framesOf(*wide), (std::vector<int>{98, 99, 100}));
}

TEST(ImageSequence, HashRunsAndFrameZero) {
    test::ScratchDir dir;
    touch(dir, {"r_0000.png", "r_0001.png", "r_0002.png", "r_002.png", "s_00.png", "s_01.png"});
    const Result<std::vector<SequenceFrame>> hashes = findSequenceFrames((dir / "r_####.png").string());
    ASSERT_TRUE(hashes) << hashes.error();
    EXPECT_EQ(framesOf(*hashes), (std::vector<int>{0, 1, 2}));
    const Result<std::vector<SequenceFrame>> single = findSequenceFrames((dir / "r_#.png").string());
    ASSERT_TRUE(single) << single.error();
    EXPECT_EQ(framesOf(*single), (std::vector<int>{0, 1, 2}));
    const Result<std::vector<SequenceFrame>> two = findSequenceFrames((dir / "s_##.png").string());
    ASSERT_TRUE(two) << two.error();
    EXPECT_EQ(framesOf(*two), (std::vector<int>{0, 1}));
}

TEST(ImageSequence, GapIsAnErrorNamingTheFirstMissingFile) {
    test::ScratchDir dir;
    touch(dir, {"f.0001.exr", "f.0002.exr", "f.0004.exr", "f.0005.exr", "f.0009.exr"});
    const std::string pattern = (dir / "f.%04d.exr").string();
    const Result<std::vector<SequenceFrame>> frames = findSequenceFrames(pattern);
    ASSERT_FALSE(frames);
    EXPECT_EQ(frames.error(), pattern + ": frames 1 to 9 have gaps: " + (dir / "f.0003.exr").string() +
                                  " is missing (4 frames missing in all)");

    touch(dir, {"g.1.exr", "g.3.exr"});
    const Result<std::vector<SequenceFrame>> one = findSequenceFrames((dir / "g.%d.exr").string());
    ASSERT_FALSE(one);
    EXPECT_TRUE(contains(one.error(), (dir / "g.2.exr").string() + " is missing (1 frame missing in all)")) << one.error();
}

TEST(ImageSequence, NoMatchingFileOrFolderIsAnErrorNamingPatternAndFolder) {
    test::ScratchDir dir;
    touch(dir, {"empty/readme.txt"});
    const std::string pattern = (dir / "empty/f.%04d.exr").string();
    const Result<std::vector<SequenceFrame>> none = findSequenceFrames(pattern);
    ASSERT_FALSE(none);
    EXPECT_EQ(none.error(), pattern + ": no file in " + (dir / "empty/").string() + " matches");

    const std::string missing = (dir / "absent/f.%04d.exr").string();
    const Result<std::vector<SequenceFrame>> noFolder = findSequenceFrames(missing);
    ASSERT_FALSE(noFolder);
    EXPECT_EQ(noFolder.error(), missing + ": no folder " + (dir / "absent/").string());

    const Result<std::vector<SequenceFrame>> twoFields = findSequenceFrames((dir / "f.%04d.%04d.exr").string());
    ASSERT_FALSE(twoFields);
    EXPECT_TRUE(contains(twoFields.error(), "2 frame-number fields")) << twoFields.error();
}

TEST(ImageSequence, RegexSpecialCharactersInNamesAreLiteral) {
    test::ScratchDir dir;
    const std::string folder = "take [2] (v1.0)+final$^";
    touch(dir, {folder + "/shot.a+b[1].0001.exr", folder + "/shot.a+b[1].0002.exr",
                // Would match if '.', '+' or the brackets were read as regular expression syntax.
                folder + "/shotXa+b[1].0003.exr", folder + "/shot.aab1.0003.exr", folder + "/shot.a+b1.0003.exr"});
    const std::string pattern = (dir / folder / "shot.a+b[1].%04d.exr").string();
    const Result<std::vector<SequenceFrame>> frames = findSequenceFrames(pattern);
    ASSERT_TRUE(frames) << frames.error();
    EXPECT_EQ(framesOf(*frames), (std::vector<int>{1, 2}));
    EXPECT_EQ((*frames)[1].path, dir / folder / "shot.a+b[1].0002.exr");
}

TEST(ImageSequence, PatternWithoutFolderListsTheCurrentFolder) {
    test::ScratchDir dir;
    touch(dir, {"cwd_frame_07.tif", "cwd_frame_08.tif"});
    const fs::path previous = fs::current_path();
    fs::current_path(dir.path());
    const Result<std::vector<SequenceFrame>> frames = findSequenceFrames("cwd_frame_%02d.tif");
    fs::current_path(previous);
    ASSERT_TRUE(frames) << frames.error();
    EXPECT_EQ(framesOf(*frames), (std::vector<int>{7, 8}));
    EXPECT_EQ((*frames)[0].path, fs::path("cwd_frame_07.tif"));
}

}  // namespace
}  // namespace rmfx

namespace rmfx {
namespace {

std::vector<SequenceFrame> numbered(int first, int last) {
    std::vector<SequenceFrame> frames;
    for (int n = first; n <= last; ++n) frames.push_back({n, "f." + std::to_string(n) + ".exr"});
    return frames;
}

TEST(ImageSequenceRange, SelectsTheIndicesOfTheNumberedFrames) {
    const std::vector<SequenceFrame> frames = numbered(1001, 1024);
    Result<std::pair<int, int>> range = selectFrameRange(frames, {1001, 1024});
    ASSERT_TRUE(range) << range.error();
    EXPECT_EQ(*range, std::make_pair(0, 23));
    range = selectFrameRange(frames, {1013, 1013});
    ASSERT_TRUE(range) << range.error();
    EXPECT_EQ(*range, std::make_pair(12, 12));
}

TEST(ImageSequenceRange, OutsideOrBackwardsIsAnErrorNamingTheFramesThereAre) {
    const std::vector<SequenceFrame> frames = numbered(1001, 1024);
    Result<std::pair<int, int>> outside = selectFrameRange(frames, {1000, 1010});
    ASSERT_FALSE(outside);
    EXPECT_EQ(outside.error(), "1000-1010 reaches outside the sequence, whose frames are 1001-1024");
    EXPECT_FALSE(selectFrameRange(frames, {1020, 1025}));
    Result<std::pair<int, int>> backwards = selectFrameRange(frames, {1010, 1005});
    ASSERT_FALSE(backwards);
    EXPECT_EQ(backwards.error(), "1010-1005: the first frame comes after the last");
}

}  // namespace
}  // namespace rmfx
