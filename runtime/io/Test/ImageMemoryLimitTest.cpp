// Images refused from their header by the memory they would take decoded.
#include "io/image/ImageMemoryLimit.h"

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "io/image/InputImage.h"
#include "tests/support/ClaimedSizeExr.h"
#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class ScopedImageMemoryLimit {
public:
    explicit ScopedImageMemoryLimit(std::uint64_t bytes) : saved_(imageMemoryLimit()) { setImageMemoryLimit(bytes); }
    ~ScopedImageMemoryLimit() { setImageMemoryLimit(saved_); }

private:
    std::uint64_t saved_;
};

TEST(ImageMemoryLimit, DecodedBytesAreFourFloatsAPixelForRgba) {
    EXPECT_EQ(decodedImageBytes(16000, 16000, 1, 4), 4096000000ull);
    EXPECT_EQ(decodedImageBytes(16384, 8192, 1, 4), kDefaultImageMemoryLimit);
    EXPECT_TRUE(checkImageMemory("pano.exr", 16384, 8192, 1, 4));
    Result<void> over = checkImageMemory("pano.exr", 16384, 8193, 1, 4);
    ASSERT_FALSE(over);
    EXPECT_EQ(over.error(), "pano.exr: image is 16384x8193: decoded it would take 2049 MiB, over the limit of 2048 MiB "
                            "(--max-image-memory MiB raises it)");
}

// The file the report found: 8 KB claiming 16000x16000 cost 9.8 s and 3.1 GB before. Now the
// header alone refuses it, for --input images and for textures alike.
TEST(ImageMemoryLimit, ASmallFileClaimingAHugeImageIsRefusedFromItsHeader) {
    test::ScratchDir dir;
    const auto file = dir / "claims.exr";
    ASSERT_TRUE(test::writeExrClaimingSize(file, 16000, 16000));
    EXPECT_LT(std::filesystem::file_size(file), 10000u);

    Result<InputImage> input = readInputImage(file);
    ASSERT_FALSE(input);
    EXPECT_TRUE(has(input.error(), "16000x16000")) << input.error();
    EXPECT_TRUE(has(input.error(), "--max-image-memory")) << input.error();

    Result<Image> texture = readImage(file);
    ASSERT_FALSE(texture);
    EXPECT_TRUE(has(texture.error(), "--max-image-memory")) << texture.error();
}

// From the header alone, before anything else: refused only when no part of the file fits; a file
// that is not there or not an image is the reader's to report.
TEST(ImageMemoryLimit, TheFileAloneIsCheckedBeforeAnythingElse) {
    test::ScratchDir dir;
    const auto claims = dir / "claims.exr";
    ASSERT_TRUE(test::writeExrClaimingSize(claims, 16000, 16000));
    Result<void> refused = checkImageFileMemory(claims);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error(), claims.string() + ": image is 16000x16000: decoded it would take 3907 MiB, over the limit of "
                                                 "2048 MiB (--max-image-memory MiB raises it)");
    EXPECT_TRUE(checkImageFileMemory(dir / "nothere.exr"));
    EXPECT_TRUE(checkImageFileMemory(dir.write("garbage.exr", "not an image")));
    Image small;
    small.width = 4;
    small.height = 2;
    small.channels = 4;
    small.pixels.assign(4 * 2 * 4, 0.5f);
    ASSERT_TRUE(writeImage(dir / "small.exr", small));
    EXPECT_TRUE(checkImageFileMemory(dir / "small.exr"));
}

TEST(ImageMemoryLimit, TheLimitIsTheRunsToSet) {
    test::ScratchDir dir;
    Image small;
    small.width = 64;
    small.height = 32;
    small.channels = 4;
    small.pixels.assign(64 * 32 * 4, 0.25f);
    const auto file = dir / "small.exr";
    ASSERT_TRUE(writeImage(file, small));
    {
        ScopedImageMemoryLimit limit(64 * 32 * 16 - 1);
        Result<InputImage> refused = readInputImage(file);
        ASSERT_FALSE(refused);
        EXPECT_TRUE(has(refused.error(), "--max-image-memory")) << refused.error();
    }
    ScopedImageMemoryLimit limit(64 * 32 * 16);
    Result<InputImage> read = readInputImage(file);
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(read->image.width, 64);
}

}  // namespace
}  // namespace rmfx
