// DDS textures through OpenImageIO: DXT1/3/5 blocks written here byte by byte, whose decoded
// colours are worked out by hand from the S3TC rules, and cube maps in one file.

#include "io/image/DdsCubeMap.h"

#include <cstdint>
#include <fstream>
#include <tuple>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/DdsBytes.h"
#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

using namespace test::dds;

// Writes the bytes as `name` and reads the image back: a 4x4 RGBA image.
Image readDds(const test::ScratchDir& dir, const std::string& name, const Bytes& bytes) {
    auto image = readImage(writeBytes(dir, name, bytes));
    EXPECT_TRUE(image) << image.error();
    if (!image) return {};
    EXPECT_EQ(image->width, 4);
    EXPECT_EQ(image->height, 4);
    EXPECT_EQ(image->channels, 4);
    return *image;
}

// One DXT1 block (end points c0, c1 and a 2-bit index per texel) decoded by OpenImageIO.
Image decodeDxt1(const test::ScratchDir& dir, const std::string& name, uint16_t c0, uint16_t c1,
                 const std::array<int, 16>& index) {
    Bytes b = header("DXT1");
    colorBlock(b, c0, c1, index);
    return readDds(dir, name, b);
}

void expectTexel(const Image& image, int x, int y, std::array<int, 4> bytes) {
    for (int c = 0; c < 4; ++c)
        EXPECT_FLOAT_EQ(image.at(x, y, c), bytes[c] / 255.0f) << "texel " << x << "," << y << " channel " << c;
}

}  // namespace

TEST(DdsTexture, Dxt1FourColourBlock) {
    test::ScratchDir dir;
    // c0 = red > c1 = blue: four colours, c2 = (2 c0 + c1) / 3, c3 = (c0 + 2 c1) / 3. Every row
    // holds indices 0 1 2 3.
    Image image = decodeDxt1(dir, "four.dds", kRed, kBlue, {0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3});
    ASSERT_FALSE(image.empty());
    for (int y = 0; y < 4; ++y) {
        expectTexel(image, 0, y, {255, 0, 0, 255});
        expectTexel(image, 1, y, {0, 0, 255, 255});
        expectTexel(image, 2, y, {170, 0, 85, 255});  // 2·255/3, 255/3
        expectTexel(image, 3, y, {85, 0, 170, 255});
    }
}

TEST(DdsTexture, Dxt1ThreeColourBlockHasTransparentBlack) {
    test::ScratchDir dir;
    // c0 = blue ≤ c1 = red: three colours and index 3 is transparent black: at (0, 0), (1, 1),
    // (2, 2), (3, 3); the end points elsewhere.
    Image image = decodeDxt1(dir, "three.dds", kBlue, kRed, {3, 0, 1, 0, 1, 3, 0, 1, 0, 1, 3, 0, 1, 0, 1, 3});
    ASSERT_FALSE(image.empty());
    const std::array<int, 4> transparent{0, 0, 0, 0}, blue{0, 0, 255, 255}, red{255, 0, 0, 255};
    for (auto [x, y, expected] : {std::tuple{0, 0, transparent}, {1, 0, blue}, {2, 0, red}, {1, 1, transparent},
                                  {3, 3, transparent}, {0, 3, red}})
        expectTexel(image, x, y, expected);
}

TEST(DdsTexture, Dxt3ExplicitAlpha) {
    test::ScratchDir dir;
    Bytes b = header("DXT3");
    // Texel i has the 4-bit alpha i (i·17 in 8 bits), then a green colour block.
    for (int pair = 0; pair < 8; ++pair) b.push_back(static_cast<uint8_t>((2 * pair) | ((2 * pair + 1) << 4)));
    colorBlock(b, kGreen, 0, kAllZero);
    Image image = readDds(dir, "dxt3.dds", b);
    ASSERT_FALSE(image.empty());
    for (int i = 0; i < 16; ++i) expectTexel(image, i % 4, i / 4, {0, 255, 0, 17 * i});
}

TEST(DdsTexture, Dxt5InterpolatedAlpha) {
    test::ScratchDir dir;
    Bytes b = header("DXT5");
    // a0 = 238 > a1 = 0: eight alphas, index k ≥ 2 gives ((8 − k)·a0 + (k − 1)·a1) / 7 = (8 − k)·34.
    b.push_back(238);
    b.push_back(0);
    uint64_t bits = 0;
    for (int i = 0; i < 16; ++i) bits |= static_cast<uint64_t>(i % 8) << (3 * i);
    for (int i = 0; i < 6; ++i) b.push_back(static_cast<uint8_t>(bits >> (8 * i)));
    colorBlock(b, kWhite, 0, kAllZero);
    Image image = readDds(dir, "dxt5.dds", b);
    ASSERT_FALSE(image.empty());
    const int alpha[8] = {238, 0, 204, 170, 136, 102, 68, 34};
    for (int i = 0; i < 16; ++i) expectTexel(image, i % 4, i / 4, {255, 255, 255, alpha[i % 8]});
}

TEST(DdsTexture, CubeMapInOneFileGivesSixFacesInGlOrder) {
    test::ScratchDir dir;
    Bytes b = header("DXT1", kCubeMap | kAllFaces);
    const uint16_t colors[6] = {kRed, kGreen, kBlue, kYellow, kMagenta, kWhite};  // +x -x +y -y +z -z
    for (uint16_t c : colors) colorBlock(b, c, 0, kAllZero);
    auto file = writeBytes(dir, "sky.DDS", b);
    EXPECT_TRUE(isDdsFile(file));
    auto faces = readDdsCubeMap(file);
    ASSERT_TRUE(faces) << faces.error();
    const std::array<int, 4> expected[6] = {
        {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 0, 255}, {255, 0, 255, 255}, {255, 255, 255, 255}};
    for (int f = 0; f < 6; ++f) {
        const Image& face = (*faces)[f];
        ASSERT_EQ(face.width, 4);
        ASSERT_EQ(face.height, 4);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) expectTexel(face, x, y, expected[f]);
    }
}

TEST(DdsTexture, WhatIsNoFullCubeMapIsAClearError) {
    test::ScratchDir dir;
    Bytes flat = header("DXT1");
    colorBlock(flat, kRed, 0, kAllZero);
    auto flatFile = writeBytes(dir, "flat.dds", flat);
    auto notCube = readDdsCubeMap(flatFile);
    ASSERT_FALSE(notCube);
    EXPECT_EQ(notCube.error(), "'" + flatFile.string() +
                                   "' is a 2D DDS texture, not a cube map: use it as a texture, or give six faces");

    Bytes partial = header("DXT1", kCubeMap | kPositiveX | kPositiveZ);
    colorBlock(partial, kRed, 0, kAllZero);
    colorBlock(partial, kBlue, 0, kAllZero);
    auto partialFile = writeBytes(dir, "partial.dds", partial);
    auto two = readDdsCubeMap(partialFile);
    ASSERT_FALSE(two);
    EXPECT_EQ(two.error(), "'" + partialFile.string() + "' is a cube map with only the faces '+x +z': a cube texture needs all six");

    Bytes volume = header("DXT1", kVolume, 2);
    colorBlock(volume, kRed, 0, kAllZero);
    colorBlock(volume, kBlue, 0, kAllZero);
    auto volumeFile = writeBytes(dir, "volume.dds", volume);
    auto asCube = readDdsCubeMap(volumeFile);
    ASSERT_FALSE(asCube);
    EXPECT_EQ(asCube.error(), "'" + volumeFile.string() + "' is a volume texture (depth 2), not a cube map: declare it a <volume>");
    auto as2d = readImage(volumeFile);
    ASSERT_FALSE(as2d);
    EXPECT_NE(as2d.error().find("a volume image (2 slices): it can only be a volume texture"), std::string::npos) << as2d.error();
}

// RenderMonkey's NoiseVolume.dds is such a file: an uncompressed DDS volume texture (here
// A8R8G8B8, 4x2 texels, 3 slices, each texel's colour telling where it is), read slice by slice.
TEST(DdsTexture, AVolumeTextureReadsAsSlicesInFileOrder) {
    test::ScratchDir dir;
    Bytes volume = uncompressedVolumeHeader(4, 2, 3);
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 4; ++x)
                volume.insert(volume.end(), {static_cast<uint8_t>(z * 100), static_cast<uint8_t>(y * 100),
                                             static_cast<uint8_t>(x * 60), 255});  // B G R A
    auto file = writeBytes(dir, "volume.dds", volume);
    auto image = readVolumeImage(file);
    ASSERT_TRUE(image) << image.error();
    EXPECT_EQ(image->width, 4);
    EXPECT_EQ(image->height, 2);
    EXPECT_EQ(image->depth, 3);
    EXPECT_EQ(image->channels, 4);
    ASSERT_EQ(image->pixels.size(), 4u * 2 * 3 * 4);
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 4; ++x) {
                const float* t = &image->pixels[((static_cast<size_t>(z) * 2 + y) * 4 + x) * 4];
                EXPECT_EQ(t[0], x * 60 / 255.0f) << x << "," << y << "," << z;
                EXPECT_EQ(t[1], y * 100 / 255.0f) << x << "," << y << "," << z;
                EXPECT_EQ(t[2], z * 100 / 255.0f) << x << "," << y << "," << z;
                EXPECT_EQ(t[3], 1.0f);
            }

    Bytes flat = header("DXT1");
    colorBlock(flat, kRed, 0, kAllZero);
    auto flatFile = writeBytes(dir, "flat.dds", flat);
    auto notVolume = readVolumeImage(flatFile);
    ASSERT_FALSE(notVolume);
    EXPECT_NE(notVolume.error().find("a 2D image, not a volume"), std::string::npos) << notVolume.error();

}

// Block-compressed volumes are decoded by rmfx (OpenImageIO 2.4 decodes only their first slice):
// every slice, every block in its place, each texel as the S3TC rules give it (worked out here).
TEST(DdsTexture, ADxtCompressedVolumeDecodesEverySlice) {
    test::ScratchDir dir;
    // DXT1, 4x4x2: slice 0 all red; slice 1 red, blue and the two thirds between, a column each.
    Bytes dxt1 = header("DXT1", kVolume, 2);
    colorBlock(dxt1, kRed, 0, kAllZero);
    colorBlock(dxt1, kRed, kBlue, {0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3});
    auto one = readVolumeImage(writeBytes(dir, "dxt1-volume.dds", dxt1));
    ASSERT_TRUE(one) << one.error();
    ASSERT_EQ(one->depth, 2);
    ASSERT_EQ(one->channels, 4);
    auto texel = [](const Image& image, int x, int y, int z, int c) {
        return image.pixels[((static_cast<size_t>(z) * image.height + y) * image.width + x) * 4 + c];
    };
    const std::array<std::array<int, 4>, 4> column{{{255, 0, 0, 255}, {0, 0, 255, 255}, {170, 0, 85, 255}, {85, 0, 170, 255}}};
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 4; ++c) {
                EXPECT_EQ(texel(*one, x, y, 0, c), (c == 0 || c == 3 ? 255 : 0) / 255.0f) << x << "," << y << " slice 0";
                EXPECT_EQ(texel(*one, x, y, 1, c), column[size_t(x)][size_t(c)] / 255.0f) << x << "," << y << " slice 1";
            }

    // DXT5, 6x5x2 (two blocks across and down, the outer ones cut): in slice 1, block (1, 1) has
    // alphas a0 = 238 > a1 = 0, index i % 8 for texel i, so ((8 − k)·a0 + (k − 1)·a1) / 7 for k ≥ 2;
    // every other block is opaque white (a0 = a1 = 255).
    Bytes dxt5 = header("DXT5", kVolume, 2, 6, 5);
    for (int z = 0; z < 2; ++z)
        for (int block = 0; block < 4; ++block) {
            const bool graded = z == 1 && block == 3;
            dxt5.push_back(graded ? 238 : 255);
            dxt5.push_back(graded ? 0 : 255);
            uint64_t bits = 0;
            for (int i = 0; graded && i < 16; ++i) bits |= static_cast<uint64_t>(i % 8) << (3 * i);
            for (int i = 0; i < 6; ++i) dxt5.push_back(static_cast<uint8_t>(bits >> (8 * i)));
            colorBlock(dxt5, kWhite, 0, kAllZero);
        }
    auto five = readVolumeImage(writeBytes(dir, "dxt5-volume.dds", dxt5));
    ASSERT_TRUE(five) << five.error();
    EXPECT_EQ(five->width, 6);
    EXPECT_EQ(five->height, 5);
    EXPECT_EQ(five->depth, 2);
    const int alpha[8] = {238, 0, 204, 170, 136, 102, 68, 34};
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 6; ++x) {
                const bool graded = z == 1 && x >= 4 && y >= 4;
                const int i = (y % 4) * 4 + x % 4;
                EXPECT_EQ(texel(*five, x, y, z, 3), (graded ? alpha[i % 8] : 255) / 255.0f) << x << "," << y << "," << z;
                EXPECT_EQ(texel(*five, x, y, z, 0), 1.0f);
            }

    // DXT3, 4x4x2: slice 1's texel i has the 4-bit alpha i (i·17 in 8 bits), slice 0's 15 (255).
    Bytes dxt3 = header("DXT3", kVolume, 2);
    for (int pair = 0; pair < 8; ++pair) dxt3.push_back(0xFF);
    colorBlock(dxt3, kGreen, 0, kAllZero);
    for (int pair = 0; pair < 8; ++pair) dxt3.push_back(static_cast<uint8_t>((2 * pair) | ((2 * pair + 1) << 4)));
    colorBlock(dxt3, kGreen, 0, kAllZero);
    auto three = readVolumeImage(writeBytes(dir, "dxt3-volume.dds", dxt3));
    ASSERT_TRUE(three) << three.error();
    for (int i = 0; i < 16; ++i) {
        EXPECT_EQ(texel(*three, i % 4, i / 4, 0, 3), 1.0f);
        EXPECT_EQ(texel(*three, i % 4, i / 4, 1, 3), 17 * i / 255.0f) << i;
        EXPECT_EQ(texel(*three, i % 4, i / 4, 1, 1), 1.0f) << i;
    }

    // One slice short: an error naming the file and what is missing.
    Bytes truncated = header("DXT1", kVolume, 3);
    colorBlock(truncated, kRed, 0, kAllZero);
    colorBlock(truncated, kBlue, 0, kAllZero);
    const auto truncatedFile = writeBytes(dir, "short.dds", truncated);
    auto refused = readVolumeImage(truncatedFile);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error(), truncatedFile.string() + ": truncated: 3 slices of 4x4 DXT1 need 24 bytes after the header, the "
                                                         "file has 16");
}

}  // namespace rmfx
