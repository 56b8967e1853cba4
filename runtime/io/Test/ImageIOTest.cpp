#include "io/image/ImageIO.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

double encodeReference(double v) {
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

double decodeReference(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

Image makeImage(int width, int height, int channels, std::vector<float> pixels) {
    Image image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.pixels = std::move(pixels);
    return image;
}

// Reads a file's raw 8- or 16-bit samples with OpenImageIO directly, bypassing readImage.
template <class Int>
std::vector<Int> rawSamples(const std::filesystem::path& file, int& channels) {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(file.string(), &config);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return {};
    const OIIO::ImageSpec& spec = in->spec();
    channels = spec.nchannels;
    std::vector<Int> data(size_t(spec.width) * spec.height * spec.nchannels);
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::BaseTypeFromC<Int>::value, data.data()));
    return data;
}

void writeRawPng(const std::filesystem::path& file, int width, int height, int channels,
                 const std::vector<uint8_t>& bytes) {
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
    if (channels == 4) spec.alpha_channel = 3;
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(out->open(file.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, bytes.data()));
    ASSERT_TRUE(out->close());
}

void truncateFile(const std::filesystem::path& file, double keep) {
    const auto size = std::filesystem::file_size(file);
    std::filesystem::resize_file(file, static_cast<uintmax_t>(double(size) * keep));
}

void expectErrorNames(const std::string& message, const std::filesystem::path& file) {
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
}

TEST(Srgb, EncodeAndDecodeMatchPiecewiseFormula) {
    for (int i = -100; i <= 12000; ++i) {
        const float v = float(i) / 10000.0f;
        EXPECT_NEAR(srgbEncode(v), encodeReference(v), 2e-7) << v;
        EXPECT_NEAR(srgbDecode(v), decodeReference(v), 2e-7) << v;
    }
    EXPECT_EQ(srgbEncode(0.0f), 0.0f);
    EXPECT_NEAR(srgbEncode(1.0f), 1.0f, 1e-7);
    EXPECT_NEAR(srgbEncode(0.5f), 0.735356983, 1e-7);
    EXPECT_NEAR(srgbEncode(0.003f), 12.92 * double(0.003f), 1e-8);  // linear segment
    EXPECT_NEAR(srgbDecode(0.5f), 0.214041140, 1e-7);
    EXPECT_NEAR(srgbDecode(0.04045f), 0.0031308050, 1e-9);
    EXPECT_TRUE(std::isnan(srgbEncode(kNaN)));
}

TEST(Srgb, RoundTripsAndIsMonotonic) {
    float previousEncoded = -1.0f;
    float previousDecoded = -1.0f;
    for (int i = 0; i <= 100000; ++i) {
        const float v = float(i) / 100000.0f;
        const float encoded = srgbEncode(v);
        EXPECT_NEAR(srgbDecode(encoded), v, 1e-6) << v;
        EXPECT_NEAR(srgbEncode(srgbDecode(v)), v, 1e-6) << v;
        EXPECT_GE(encoded, previousEncoded) << v;
        EXPECT_GE(srgbDecode(v), previousDecoded) << v;
        previousEncoded = encoded;
        previousDecoded = srgbDecode(v);
    }
}

TEST(ImageIO, ExrRoundTripKeepsFloat32Exactly) {
    test::ScratchDir dir;
    const std::vector<float> values = {1e-5f, 1.0f, 3.5e4f, 1e6f, -2.5f, 0.1234567f, 65520.0f, 3.0e-9f,
                                       0.0f, 7.0f, 1e-30f, 123456.789f};
    const Image image = makeImage(3, 1, 4, values);
    // The display transform does not apply to float files.
    ASSERT_TRUE(writeImage(dir / "a.exr", image, DisplayTransform::Srgb));
    const Result<Image> read = readImage(dir / "a.exr");
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(read->width, 3);
    EXPECT_EQ(read->height, 1);
    EXPECT_EQ(read->channels, 4);
    EXPECT_TRUE(read->highDynamicRange);
    EXPECT_EQ(read->bitsPerChannel, 32);
    EXPECT_EQ(read->pixels, values);
}

TEST(ImageIO, ExrHalfOption) {
    test::ScratchDir dir;
    const std::vector<float> values = {0.5f, 1.0f, 2048.0f, 65504.0f, 0.1f, -3.0f};
    WriteOptions options;
    options.exrHalf = true;
    ASSERT_TRUE(writeImage(dir / "h.exr", makeImage(2, 1, 3, values), options));
    const Result<Image> read = readImage(dir / "h.exr");
    ASSERT_TRUE(read) << read.error();
    EXPECT_TRUE(read->highDynamicRange);
    EXPECT_EQ(read->bitsPerChannel, 16);
    EXPECT_EQ(read->pixels[0], 0.5f);
    EXPECT_EQ(read->pixels[2], 2048.0f);
    EXPECT_EQ(read->pixels[3], 65504.0f);
    EXPECT_EQ(read->pixels[4], 0.0999755859375f);  // nearest half to 0.1
    EXPECT_EQ(read->pixels[5], -3.0f);
}

// integerOpaque: 8-bit formats keep colour only (rmfx render of an imported RenderMonkey effect);
// float formats keep every channel.
TEST(ImageIO, IntegerOpaqueDropsAlphaFromIntegerFormatsOnly) {
    test::ScratchDir dir;
    const Image rgba = makeImage(2, 1, 4, {0.2f, 0.4f, 0.6f, 0.0f, 1.0f, 0.0f, 0.5f, 0.25f});
    WriteOptions options;
    options.integerOpaque = true;
    for (const char* name : {"o.png", "o.tga", "o.bmp"}) {
        ASSERT_TRUE(writeImage(dir / name, rgba, options)) << name;
        const Result<Image> read = readImage(dir / name);
        ASSERT_TRUE(read) << read.error();
        EXPECT_EQ(read->channels, 3) << name;
        EXPECT_NEAR(read->at(0, 0, 1), 0.4f, 0.5f / 255) << name;  // colour kept although alpha was 0
    }
    ASSERT_TRUE(writeImage(dir / "o.exr", rgba, options));
    const Result<Image> exr = readImage(dir / "o.exr");
    ASSERT_TRUE(exr) << exr.error();
    EXPECT_EQ(exr->channels, 4);
    ASSERT_TRUE(writeImage(dir / "a.png", rgba));
    EXPECT_EQ(readImage(dir / "a.png")->channels, 4);  // without the option alpha stays
}

TEST(ImageIO, FloatChannelCountsSurviveExr) {
    test::ScratchDir dir;
    for (int channels : {1, 2, 3, 4}) {
        std::vector<float> values(size_t(4 * 3 * channels));
        for (size_t i = 0; i < values.size(); ++i) values[i] = 0.25f * float(i) - 1.0f;
        const auto file = dir / ("c" + std::to_string(channels) + ".exr");
        ASSERT_TRUE(writeImage(file, makeImage(4, 3, channels, values)));
        const Result<Image> read = readImage(file);
        ASSERT_TRUE(read) << read.error();
        EXPECT_EQ(read->channels, channels);
        EXPECT_EQ(read->pixels, values);
    }
}

TEST(ImageIO, PngSrgbWriteQuantisesEncodedClampedValues) {
    test::ScratchDir dir;
    const std::vector<float> values = {kNaN, -1.0f, 0.0f, 1e-4f, 0.0031308f, 0.01f, 0.05f, 0.18f,
                                       0.2f, 0.5f, 0.75f, 0.9f, 1.0f, 2.0f, kInf, -kInf};
    const auto file = dir / "s.png";
    ASSERT_TRUE(writeImage(file, makeImage(4, 4, 1, values), DisplayTransform::Srgb));
    int channels = 0;
    const std::vector<uint8_t> bytes = rawSamples<uint8_t>(file, channels);
    ASSERT_EQ(channels, 1);
    ASSERT_EQ(bytes.size(), values.size());
    for (size_t i = 0; i < values.size(); ++i) {
        const double clamped = std::isnan(values[i]) ? 0.0 : std::clamp(double(values[i]), 0.0, 1.0);
        EXPECT_EQ(int(bytes[i]), int(std::round(255.0 * encodeReference(clamped)))) << values[i];
    }
    EXPECT_EQ(int(bytes[9]), 188);  // 0.5 linear is 0.7354 encoded
}

TEST(ImageIO, PngWithoutTransformAndAlphaIsNeverEncoded) {
    test::ScratchDir dir;
    const std::vector<float> rgba = {0.5f, 0.2f, 1.5f, 0.5f, 0.0f, 0.01f, kNaN, 0.2f};
    ASSERT_TRUE(writeImage(dir / "srgb.png", makeImage(2, 1, 4, rgba), DisplayTransform::Srgb));
    ASSERT_TRUE(writeImage(dir / "none.png", makeImage(2, 1, 4, rgba), DisplayTransform::None));
    int channels = 0;
    const auto srgb = rawSamples<uint8_t>(dir / "srgb.png", channels);
    ASSERT_EQ(channels, 4);
    const auto none = rawSamples<uint8_t>(dir / "none.png", channels);
    ASSERT_EQ(channels, 4);
    const std::vector<int> srgbExpected = {188, 124, 255, 128, 0, 25, 0, 51};
    const std::vector<int> noneExpected = {128, 51, 255, 128, 0, 3, 0, 51};
    for (size_t i = 0; i < rgba.size(); ++i) {
        EXPECT_EQ(int(srgb[i]), srgbExpected[i]) << i;
        EXPECT_EQ(int(none[i]), noneExpected[i]) << i;
    }
}

TEST(ImageIO, EightBitPngReadsAsByteOver255WithoutPremultiplying) {
    test::ScratchDir dir;
    std::vector<uint8_t> bytes(256 * 4);
    for (int i = 0; i < 256; ++i) {
        bytes[i * 4 + 0] = uint8_t(i);
        bytes[i * 4 + 1] = uint8_t(255 - i);
        bytes[i * 4 + 2] = 200;
        bytes[i * 4 + 3] = uint8_t((i * 7) % 256);  // alpha 0 included: colour must survive
    }
    const auto file = dir / "bytes.png";
    writeRawPng(file, 16, 16, 4, bytes);
    const Result<Image> read = readImage(file);
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(read->channels, 4);
    EXPECT_FALSE(read->highDynamicRange);
    EXPECT_EQ(read->bitsPerChannel, 8);
    for (size_t i = 0; i < bytes.size(); ++i)
        ASSERT_EQ(read->pixels[i], float(bytes[i]) / 255.0f) << i;
}

TEST(ImageIO, PngChannelCounts) {
    test::ScratchDir dir;
    for (int channels : {1, 2, 3, 4}) {
        std::vector<uint8_t> bytes(size_t(5 * 2 * channels));
        for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = uint8_t(i * 13);
        const auto file = dir / ("c" + std::to_string(channels) + ".png");
        writeRawPng(file, 5, 2, channels, bytes);
        const Result<Image> read = readImage(file);
        ASSERT_TRUE(read) << read.error();
        EXPECT_EQ(read->channels, channels);
        EXPECT_EQ(read->width, 5);
        EXPECT_EQ(read->height, 2);
        for (size_t i = 0; i < bytes.size(); ++i)
            EXPECT_EQ(read->pixels[i], float(bytes[i]) / 255.0f);
        // And back out through writeImage, unchanged.
        const auto copy = dir / ("copy" + std::to_string(channels) + ".png");
        ASSERT_TRUE(writeImage(copy, *read));
        int stored = 0;
        EXPECT_EQ(rawSamples<uint8_t>(copy, stored), bytes);
        EXPECT_EQ(stored, channels);
    }
}

TEST(ImageIO, SixteenBitPng) {
    test::ScratchDir dir;
    const std::vector<float> values = {0.0f, 0.5f, 1.0f / 65535.0f, 0.123456f, 1.0f, 2.0f};
    WriteOptions options;
    options.pngBits = 16;
    ASSERT_TRUE(writeImage(dir / "w.png", makeImage(2, 1, 3, values), options));
    const Result<Image> read = readImage(dir / "w.png");
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(read->bitsPerChannel, 16);
    EXPECT_FALSE(read->highDynamicRange);
    for (size_t i = 0; i < values.size(); ++i) {
        const double expected = std::round(65535.0 * std::clamp(double(values[i]), 0.0, 1.0)) / 65535.0;
        EXPECT_EQ(read->pixels[i], float(expected)) << i;
    }
}

TEST(ImageIO, OtherFormatsWriteAndReadBack) {
    test::ScratchDir dir;
    const std::vector<float> rgb = {0.0f, 0.25f, 0.55f, 1.0f, 0.75f, 0.2f, 0.6f, 0.4f, 0.15f, 0.85f, 0.35f, 0.8f};
    const Image image = makeImage(2, 2, 3, rgb);
    for (const char* name : {"a.tga", "a.bmp"}) {
        ASSERT_TRUE(writeImage(dir / name, image)) << name;
        const Result<Image> read = readImage(dir / name);
        ASSERT_TRUE(read) << read.error();
        EXPECT_EQ(read->channels, 3) << name;
        for (size_t i = 0; i < rgb.size(); ++i)
            EXPECT_EQ(read->pixels[i], std::round(rgb[i] * 255.0f) / 255.0f) << name << " " << i;
    }
    // JPEG is lossy and drops alpha.
    std::vector<float> flat(size_t(8 * 8 * 4));
    for (size_t i = 0; i < flat.size(); ++i) flat[i] = (i % 4 == 3) ? 0.5f : 0.4f;
    ASSERT_TRUE(writeImage(dir / "a.jpg", makeImage(8, 8, 4, flat)));
    const Result<Image> jpeg = readImage(dir / "a.jpg");
    ASSERT_TRUE(jpeg) << jpeg.error();
    EXPECT_EQ(jpeg->channels, 3);
    for (float v : jpeg->pixels) EXPECT_NEAR(v, 0.4f, 2.0f / 255.0f);
    // Radiance RGBE keeps HDR values to about 1% and stores RGB only.
    const std::vector<float> hdr = {1e-3f, 1.0f, 3.5e4f, 0.5f};
    ASSERT_TRUE(writeImage(dir / "a.hdr", makeImage(2, 1, 2, hdr), DisplayTransform::Srgb));
    const Result<Image> radiance = readImage(dir / "a.hdr");
    ASSERT_TRUE(radiance) << radiance.error();
    EXPECT_TRUE(radiance->highDynamicRange);
    EXPECT_EQ(radiance->channels, 3);
    EXPECT_NEAR(radiance->at(0, 0, 0), 1e-3f, 1e-5f);
    EXPECT_NEAR(radiance->at(0, 0, 2), 1e-3f, 1e-5f);
    EXPECT_NEAR(radiance->at(1, 0, 1), 3.5e4f, 3.5e2f);
}

TEST(ImageIO, TransparentColourSurvivesPngAndTga) {
    test::ScratchDir dir;
    // Colour under zero alpha must not be lost to premultiplication on either side.
    const std::vector<float> rgba = {0.8f, 0.4f, 0.2f, 0.0f, 0.6f, 1.0f, 0.0f, 0.2f};
    for (const char* name : {"a.png", "a.tga"}) {
        ASSERT_TRUE(writeImage(dir / name, makeImage(2, 1, 4, rgba))) << name;
        const Result<Image> read = readImage(dir / name);
        ASSERT_TRUE(read) << read.error();
        ASSERT_EQ(read->channels, 4) << name;
        for (size_t i = 0; i < rgba.size(); ++i)
            EXPECT_EQ(read->pixels[i], std::round(rgba[i] * 255.0f) / 255.0f) << name << " " << i;
    }
}

TEST(ImageIO, MoreThanFourChannelsKeepsTheFirstFour) {
    test::ScratchDir dir;
    const auto file = dir / "six.exr";
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(2, 1, 6, OIIO::TypeDesc::FLOAT);
    ASSERT_TRUE(out->open(file.string(), spec));
    const std::vector<float> values = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, values.data()));
    ASSERT_TRUE(out->close());
    const Result<Image> read = readImage(file);
    ASSERT_TRUE(read) << read.error();
    EXPECT_EQ(read->channels, 4);
    EXPECT_EQ(read->pixels, (std::vector<float>{1, 2, 3, 4, 7, 8, 9, 10}));
}

TEST(ImageIO, MissingFileErrorNamesIt) {
    test::ScratchDir dir;
    const auto file = dir / "nowhere.exr";
    const Result<Image> read = readImage(file);
    ASSERT_FALSE(read);
    expectErrorNames(read.error(), file);
    EXPECT_NE(read.error().find("no such file"), std::string::npos) << read.error();
}

TEST(ImageIO, TruncatedFilesFail) {
    test::ScratchDir dir;
    std::vector<float> values(size_t(64 * 64 * 3));
    for (size_t i = 0; i < values.size(); ++i) values[i] = float((i * 37) % 101) / 100.0f;
    const Image image = makeImage(64, 64, 3, values);
    for (const char* name : {"cut.png", "cut.exr"}) {
        const auto file = dir / name;
        ASSERT_TRUE(writeImage(file, image));
        truncateFile(file, 0.5);
        const Result<Image> read = readImage(file);
        ASSERT_FALSE(read) << name;
        expectErrorNames(read.error(), file);
    }
}

TEST(ImageIO, GarbageHeaderFails) {
    test::ScratchDir dir;
    for (const char* name : {"junk.png", "junk.exr", "junk.jpg"}) {
        const auto file = dir.write(name, std::string("this is not an image at all\n") + std::string(200, 'x'));
        const Result<Image> read = readImage(file);
        ASSERT_FALSE(read) << name;
        expectErrorNames(read.error(), file);
    }
}

TEST(ImageIO, RejectsAbsurdSizesBeforeReading) {
    test::ScratchDir dir;
    // A Radiance header promising 70000 x 1 pixels and no pixel data.
    const auto wide = dir.write("wide.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 70000\n");
    const Result<Image> read = readImage(wide);
    ASSERT_FALSE(read);
    expectErrorNames(read.error(), wide);
    EXPECT_NE(read.error().find("too large"), std::string::npos) << read.error();
    // 20000 x 20000 is within the side limit but over 2^28 pixels.
    const auto big = dir.write("big.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 20000 +X 20000\n");
    const Result<Image> bigRead = readImage(big);
    ASSERT_FALSE(bigRead);
    EXPECT_NE(bigRead.error().find("too large"), std::string::npos) << bigRead.error();
}

TEST(ImageIO, WriteErrorsNameTheFile) {
    test::ScratchDir dir;
    const Image image = makeImage(1, 1, 3, {0.1f, 0.2f, 0.3f});
    const auto unknown = dir / "a.xyz";
    Result<void> written = writeImage(unknown, image);
    ASSERT_FALSE(written);
    expectErrorNames(written.error(), unknown);
    EXPECT_NE(written.error().find(".xyz"), std::string::npos);

    const auto noFolder = dir / "missing" / "a.png";
    written = writeImage(noFolder, image);
    ASSERT_FALSE(written);
    expectErrorNames(written.error(), noFolder);

    const auto inconsistent = dir / "b.exr";
    written = writeImage(inconsistent, makeImage(2, 2, 3, {1.0f}));
    ASSERT_FALSE(written);
    expectErrorNames(written.error(), inconsistent);
    EXPECT_FALSE(std::filesystem::exists(inconsistent));
}

}  // namespace
}  // namespace rmfx
