// Outputs checked before the work: a missing folder, a folder where a file is meant, an unknown
// extension; and image files written whole or not at all.
#include "io/file/OutputPath.h"

#include <sys/resource.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "io/image/ImageOutputPath.h"
#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

namespace fs = std::filesystem;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(OutputPath, AFileInAnExistingFolderIsFine) {
    test::ScratchDir dir;
    EXPECT_TRUE(checkOutputFile(dir / "new.png"));
    dir.write("old.png", "x");
    EXPECT_TRUE(checkOutputFile(dir / "old.png"));
}

TEST(OutputPath, AMissingFolderIsNamed) {
    test::ScratchDir dir;
    Result<void> usable = checkOutputFile(dir / "missing" / "a.png");
    ASSERT_FALSE(usable);
    EXPECT_TRUE(has(usable.error(), (dir / "missing" / "a.png").string())) << usable.error();
    EXPECT_TRUE(has(usable.error(), "the folder '" + (dir / "missing").string() + "' does not exist")) << usable.error();
}

TEST(OutputPath, AFolderIsNotAFile) {
    test::ScratchDir dir;
    fs::create_directories(dir / "out.png");
    Result<void> usable = checkOutputFile(dir / "out.png");
    ASSERT_FALSE(usable);
    EXPECT_TRUE(has(usable.error(), "is a folder, not a file")) << usable.error();
    EXPECT_FALSE(checkOutputFile(dir.path() / ""));
}

TEST(OutputPath, AFileInPlaceOfTheFolderIsNamed) {
    test::ScratchDir dir;
    dir.write("plain", "x");
    Result<void> usable = checkOutputFile(dir / "plain" / "a.png");
    ASSERT_FALSE(usable);
    EXPECT_TRUE(has(usable.error(), "is not a folder")) << usable.error();
}

TEST(OutputPath, AFolderToCreateNeedsAWritableAncestor) {
    test::ScratchDir dir;
    EXPECT_TRUE(checkOutputFolder(dir / "a" / "b" / "c"));
    EXPECT_TRUE(checkOutputFolder(dir.path()));
    dir.write("plain", "x");
    Result<void> usable = checkOutputFolder(dir / "plain" / "sub");
    ASSERT_FALSE(usable);
    EXPECT_TRUE(has(usable.error(), "is a file, not a folder")) << usable.error();
}

TEST(ImageOutputPath, TheExtensionMustBeOneRmfxWrites) {
    test::ScratchDir dir;
    for (const char* name : {"a.exr", "a.hdr", "a.png", "a.jpg", "a.JPEG", "a.tga", "a.bmp"})
        EXPECT_TRUE(checkImageOutputPath(dir / name)) << name;
    for (const char* name : {"a.xyz", "a", "a.tif"}) {
        Result<void> usable = checkImageOutputPath(dir / name);
        ASSERT_FALSE(usable) << name;
        EXPECT_TRUE(has(usable.error(), (dir / name).string())) << usable.error();
        EXPECT_TRUE(has(usable.error(), "known: .exr .hdr .png .jpg .jpeg .tga .bmp")) << usable.error();
    }
}

// A file-size limit (RLIMIT_FSIZE) in this process for the scope, with SIGXFSZ ignored so that a
// write past it fails with EFBIG, as it does on a full disk.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        ::getrlimit(RLIMIT_FSIZE, &saved_);
        previous_ = std::signal(SIGXFSZ, SIG_IGN);
        struct rlimit limit {bytes, saved_.rlim_max};
        ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() {
        ::setrlimit(RLIMIT_FSIZE, &saved_);
        std::signal(SIGXFSZ, previous_);
    }

private:
    struct rlimit saved_ {};
    void (*previous_)(int) = SIG_DFL;
};

Image gradient(int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    image.channels = 4;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.pixels.insert(image.pixels.end(), {float(x) / width, float(y) / height, float((x * 7 + y * 13) % 17) / 17.0f, 1.0f});
    return image;
}

std::vector<std::string> filesIn(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Every format: a write that runs out of room fails naming the file and the system's reason,
// and leaves the previous file byte for byte and nothing else.
TEST(ImageWrite, AWriteThatRunsOutOfRoomLeavesThePreviousFileAndNothingElse) {
    for (const char* name : {"out.exr", "out.hdr", "out.png", "out.jpg", "out.tga", "out.bmp"}) {
        test::ScratchDir dir;
        const fs::path file = dir / name;
        ASSERT_TRUE(writeImage(file, gradient(8, 4))) << name;
        const std::string previous = test::readText(file);
        ASSERT_FALSE(previous.empty());
        Result<void> written = Error{""};
        {
            FileSizeLimit limit(256);
            written = writeImage(file, gradient(96, 64));
        }
        ASSERT_FALSE(written) << name << ": a 96x64 image fits in 256 bytes?";
        EXPECT_TRUE(has(written.error(), file.string())) << written.error();
        EXPECT_TRUE(has(written.error(), "File too large")) << written.error();
        EXPECT_EQ(test::readText(file), previous) << name;
        EXPECT_EQ(filesIn(dir.path()), std::vector<std::string>{name}) << name;
        // Without the limit the same write goes through and replaces the file whole.
        ASSERT_TRUE(writeImage(file, gradient(96, 64))) << name;
        Result<Image> read = readImage(file);
        ASSERT_TRUE(read) << read.error();
        EXPECT_EQ(read->width, 96);
        EXPECT_EQ(filesIn(dir.path()), std::vector<std::string>{name}) << name;
    }
}

}  // namespace
}  // namespace rmfx
