#include "io/image/InputImage.h"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

namespace fs = std::filesystem;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// The sRGB decoding written out in double precision, independent of srgbDecode.
double decodeReference(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

// One part of an EXR file the test writes: its name ("" for none), channel names and pixels.
struct ExrPart {
    std::string name;
    std::vector<std::string> channels;
    std::vector<float> pixels;  // width * height * channels.size()
    OIIO::TypeDesc type = OIIO::TypeDesc::FLOAT;
};

OIIO::ImageSpec exrSpec(int width, int height, const ExrPart& part) {
    OIIO::ImageSpec spec(width, height, int(part.channels.size()), part.type);
    spec.channelnames = part.channels;
    spec.alpha_channel = -1;
    spec.attribute("compression", "none");  // the pixel data's size is then known (a test cuts it off)
    if (!part.name.empty()) spec.attribute("oiio:subimagename", part.name);
    return spec;
}

void writeExr(const fs::path& file, int width, int height, const std::vector<ExrPart>& parts) {
    std::vector<OIIO::ImageSpec> specs;
    for (const ExrPart& part : parts) specs.push_back(exrSpec(width, height, part));
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(file.string(), int(specs.size()), specs.data())) << out->geterror();
    for (size_t p = 0; p < parts.size(); ++p) {
        if (p > 0) {
            ASSERT_TRUE(out->open(file.string(), specs[p], OIIO::ImageOutput::AppendSubimage)) << out->geterror();
        }
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, parts[p].pixels.data())) << out->geterror();
    }
    ASSERT_TRUE(out->close());
}

template <class Int>
void writePng(const fs::path& file, int width, int height, int channels, const std::vector<Int>& samples) {
    const OIIO::TypeDesc type = OIIO::BaseTypeFromC<Int>::value;
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(width, height, channels, type);
    spec.alpha_channel = channels == 2 || channels == 4 ? channels - 1 : -1;
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(out->open(file.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(type, samples.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The one note containing `part`; "" when none does. Every note names the file.
std::string noteWith(const InputImage& input, const fs::path& file, const std::string& part) {
    std::string found;
    for (const std::string& note : input.notes) {
        EXPECT_TRUE(contains(note, file.string())) << note;
        if (contains(note, part)) found = note;
    }
    return found;
}

std::vector<float> rgba(const InputImage& input, int x, int y) {
    return {input.image.at(x, y, 0), input.image.at(x, y, 1), input.image.at(x, y, 2), input.image.at(x, y, 3)};
}

Image constantImage(int width, int height, int channels, float value) {
    Image image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.pixels.assign(size_t(width) * size_t(height) * size_t(channels), value);
    return image;
}

double sum(const Image& image) {
    double total = 0.0;
    for (float v : image.pixels) total += v;
    return total;
}

TEST(InputImage, FloatRgbaExrIsReadUnchanged) {
    test::ScratchDir dir;
    const std::vector<float> pixels = {0.25f, 1.5f, 1000.0f, 0.5f, 0.0f, 1e-6f, 3.0f, 1.0f,
                                       7.0f,  0.1f, 0.2f,    0.0f, 2.0f, 4.0f,  8.0f, 0.75f};
    writeExr(dir / "a.exr", 2, 2, {{"", {"R", "G", "B", "A"}, pixels}});
    const Result<InputImage> input = readInputImage(dir / "a.exr");
    ASSERT_TRUE(input) << input.error();
    EXPECT_EQ(input->image.width, 2);
    EXPECT_EQ(input->image.height, 2);
    EXPECT_EQ(input->image.channels, 4);
    EXPECT_TRUE(input->image.highDynamicRange);
    EXPECT_EQ(input->image.pixels, pixels);
    EXPECT_EQ(input->layer, "");
    EXPECT_TRUE(input->notes.empty()) << input->notes[0];
}

TEST(InputImage, HalfRgbExrGetsAlphaOne) {
    test::ScratchDir dir;
    writeExr(dir / "h.exr", 2, 1, {{"", {"R", "G", "B"}, {0.5f, 2048.0f, 0.1f, 65504.0f, 0.0f, 3.0f}, OIIO::TypeDesc::HALF}});
    const Result<InputImage> input = readInputImage(dir / "h.exr");
    ASSERT_TRUE(input) << input.error();
    EXPECT_EQ(input->image.bitsPerChannel, 16);
    EXPECT_EQ(rgba(*input, 0, 0), (std::vector<float>{0.5f, 2048.0f, 0.0999755859375f, 1.0f}));
    EXPECT_EQ(rgba(*input, 1, 0), (std::vector<float>{65504.0f, 0.0f, 3.0f, 1.0f}));
    EXPECT_TRUE(input->notes.empty());
}

TEST(InputImage, EightBitPngIsDecodedFromSrgbExceptAlpha) {
    test::ScratchDir dir;
    std::vector<uint8_t> bytes;
    for (int b = 0; b < 256; ++b) {
        for (int v : {b, 255 - b, (b * 7) % 256, b}) bytes.push_back(uint8_t(v));
    }
    const fs::path file = dir / "ramp.png";
    writePng(file, 256, 1, 4, bytes);
    const Result<InputImage> input = readInputImage(file);
    ASSERT_TRUE(input) << input.error();
    EXPECT_FALSE(input->image.highDynamicRange);
    EXPECT_EQ(input->image.bitsPerChannel, 8);
    for (int x = 0; x < 256; ++x) {
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(input->image.at(x, 0, c), decodeReference(bytes[size_t(x * 4 + c)] / 255.0), 1e-6) << x << " " << c;
        EXPECT_EQ(input->image.at(x, 0, 3), float(x) / 255.0f) << x;  // alpha: exactly byte / 255
    }
    // Spot values: byte 128 is 0.2158605 linear, byte 10 is on the linear segment.
    EXPECT_NEAR(input->image.at(128, 0, 0), 0.21586050, 1e-7);
    EXPECT_NEAR(input->image.at(10, 0, 0), 10.0 / 255.0 / 12.92, 1e-9);
    EXPECT_EQ(input->image.at(255, 0, 0), 1.0f);
    EXPECT_EQ(input->image.at(0, 0, 0), 0.0f);
    EXPECT_EQ(noteWith(*input, file, "sRGB"), file.string() + ": 8-bit sRGB: decoded to linear");
    EXPECT_EQ(input->notes.size(), 1u);
}

TEST(InputImage, SixteenBitPngIsDecodedFromSrgb) {
    test::ScratchDir dir;
    const std::vector<uint16_t> samples = {0, 1000, 32768, 65535, 40000, 12345};
    const fs::path file = dir / "deep.png";
    writePng(file, 2, 1, 3, samples);
    const Result<InputImage> input = readInputImage(file);
    ASSERT_TRUE(input) << input.error();
    EXPECT_EQ(input->image.bitsPerChannel, 16);
    for (size_t i = 0; i < samples.size(); ++i)
        EXPECT_NEAR(input->image.pixels[i + i / 3], decodeReference(samples[i] / 65535.0), 1e-6) << i;
    EXPECT_EQ(input->image.at(0, 0, 3), 1.0f);
    EXPECT_FALSE(noteWith(*input, file, "16-bit sRGB: decoded to linear").empty());
}

TEST(InputImage, OneChannelIsGreyWithOpaqueAlpha) {
    test::ScratchDir dir;
    const fs::path file = dir / "grey.png";
    writePng<uint8_t>(file, 3, 1, 1, {0, 128, 255});
    const Result<InputImage> input = readInputImage(file);
    ASSERT_TRUE(input) << input.error();
    const float mid = float(decodeReference(128 / 255.0));
    EXPECT_NEAR(input->image.at(1, 0, 0), mid, 1e-6);
    EXPECT_EQ(rgba(*input, 1, 0), (std::vector<float>{input->image.at(1, 0, 0), input->image.at(1, 0, 0),
                                                      input->image.at(1, 0, 0), 1.0f}));
    EXPECT_EQ(rgba(*input, 2, 0), (std::vector<float>{1.0f, 1.0f, 1.0f, 1.0f}));
    EXPECT_EQ(noteWith(*input, file, "1 channel"), file.string() + ": 1 channel (Y): read as grey, alpha 1");
    EXPECT_FALSE(noteWith(*input, file, "8-bit sRGB").empty());

    // A float file's single channel is grey too, and linear already.
    writeExr(dir / "z.exr", 2, 1, {{"", {"Z"}, {12.5f, -1.0f}}});
    const Result<InputImage> depth = readInputImage(dir / "z.exr");
    ASSERT_TRUE(depth) << depth.error();
    EXPECT_EQ(rgba(*depth, 0, 0), (std::vector<float>{12.5f, 12.5f, 12.5f, 1.0f}));
    EXPECT_TRUE(noteWith(*depth, dir / "z.exr", "sRGB").empty());
}

TEST(InputImage, TwoChannelsAreGreyAndAlpha) {
    test::ScratchDir dir;
    const fs::path file = dir / "ya.png";
    writePng<uint8_t>(file, 2, 1, 2, {200, 51, 0, 255});
    const Result<InputImage> input = readInputImage(file);
    ASSERT_TRUE(input) << input.error();
    const float grey = input->image.at(0, 0, 0);
    EXPECT_NEAR(grey, decodeReference(200 / 255.0), 1e-6);
    EXPECT_EQ(rgba(*input, 0, 0), (std::vector<float>{grey, grey, grey, 51 / 255.0f}));  // alpha not decoded
    EXPECT_EQ(rgba(*input, 1, 0), (std::vector<float>{0.0f, 0.0f, 0.0f, 1.0f}));
    EXPECT_EQ(noteWith(*input, file, "2 channels"), file.string() + ": 2 channels (Y, A): read as grey and alpha");
}

TEST(InputImage, ChannelsBeyondRgbaAreIgnored) {
    test::ScratchDir dir;
    writeExr(dir / "extra.exr", 1, 1, {{"", {"R", "G", "B", "A", "Z", "mask"}, {1, 2, 3, 0.5f, 99, 98}}});
    const Result<InputImage> input = readInputImage(dir / "extra.exr");
    ASSERT_TRUE(input) << input.error();
    EXPECT_EQ(rgba(*input, 0, 0), (std::vector<float>{1, 2, 3, 0.5f}));
    EXPECT_TRUE(input->notes.empty());
}

// Part "beauty" (RGBA half) and part "depth" (Z float), 2x1.
void writeTwoParts(const fs::path& file) {
    writeExr(file, 2, 1,
             {{"beauty", {"R", "G", "B", "A"}, {0.5f, 0.25f, 2.0f, 1.0f, 4.0f, 8.0f, 16.0f, 0.5f}, OIIO::TypeDesc::HALF},
              {"depth", {"Z"}, {10.0f, 20.0f}}});
}

TEST(InputImageLayers, MultiPartReadsFirstPlainPartOrTheNamedOne) {
    test::ScratchDir dir;
    const fs::path file = dir / "parts.exr";
    writeTwoParts(file);
    const Result<InputImage> beauty = readInputImage(file);
    ASSERT_TRUE(beauty) << beauty.error();
    EXPECT_EQ(beauty->layer, "beauty");
    EXPECT_EQ(rgba(*beauty, 1, 0), (std::vector<float>{4.0f, 8.0f, 16.0f, 0.5f}));
    EXPECT_EQ(noteWith(*beauty, file, "also has"),
              file.string() + ": read layer 'beauty'; the file also has depth (choose one with FILE:layer)");

    const Result<InputImage> depth = readInputImage(file, "depth");
    ASSERT_TRUE(depth) << depth.error();
    EXPECT_EQ(depth->layer, "depth");
    EXPECT_EQ(rgba(*depth, 0, 0), (std::vector<float>{10.0f, 10.0f, 10.0f, 1.0f}));
    EXPECT_EQ(rgba(*depth, 1, 0), (std::vector<float>{20.0f, 20.0f, 20.0f, 1.0f}));
    EXPECT_TRUE(noteWith(*depth, file, "also has").empty());  // the user chose

    // The FILE.exr:layer form gives the same choice.
    const auto [path, layer] = splitLayerSuffix(file.string() + ":depth");
    EXPECT_EQ(path, file);
    EXPECT_EQ(layer, "depth");
    EXPECT_EQ(readInputImage(path, layer)->image.pixels, depth->image.pixels);
}

TEST(InputImageLayers, DefaultSkipsPartsWithoutPlainRgb) {
    test::ScratchDir dir;
    const fs::path file = dir / "depthfirst.exr";
    writeExr(file, 1, 1, {{"depth", {"Z"}, {5.0f}}, {"rgb", {"R", "G", "B"}, {0.1f, 0.2f, 0.3f}}});
    const Result<InputImage> input = readInputImage(file);
    ASSERT_TRUE(input) << input.error();
    EXPECT_EQ(input->layer, "rgb");
    EXPECT_EQ(rgba(*input, 0, 0), (std::vector<float>{0.1f, 0.2f, 0.3f, 1.0f}));
}

// A renderer's single-part file: ViewLayer.Combined.{R,G,B,A} and ViewLayer.Depth.Z, 2x1.
void writeRenderLayers(const fs::path& file) {
    writeExr(file, 2, 1,
             {{"",
               {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B", "ViewLayer.Combined.A",
                "ViewLayer.Depth.Z"},
               {0.1f, 0.2f, 0.3f, 1.0f, 7.0f, 1.5f, 2.5f, 3.5f, 0.0f, 9.0f}}});
}

TEST(InputImageLayers, RenderLayersDefaultToCombined) {
    test::ScratchDir dir;
    const fs::path file = dir / "render.exr";
    writeRenderLayers(file);
    const Result<InputImage> input = readInputImage(file);
    ASSERT_TRUE(input) << input.error();
    EXPECT_EQ(input->layer, "ViewLayer.Combined");
    EXPECT_EQ(rgba(*input, 0, 0), (std::vector<float>{0.1f, 0.2f, 0.3f, 1.0f}));
    EXPECT_EQ(rgba(*input, 1, 0), (std::vector<float>{1.5f, 2.5f, 3.5f, 0.0f}));
    EXPECT_FALSE(noteWith(*input, file, "also has ViewLayer.Depth").empty());
}

TEST(InputImageLayers, LayersAreChosenByFullNameOrLastComponents) {
    test::ScratchDir dir;
    const fs::path file = dir / "render.exr";
    writeRenderLayers(file);
    for (const std::string name : {"ViewLayer.Depth", "Depth"}) {
        const Result<InputImage> depth = readInputImage(file, name);
        ASSERT_TRUE(depth) << depth.error();
        EXPECT_EQ(depth->layer, "ViewLayer.Depth") << name;
        EXPECT_EQ(rgba(*depth, 0, 0), (std::vector<float>{7.0f, 7.0f, 7.0f, 1.0f})) << name;
        EXPECT_EQ(rgba(*depth, 1, 0), (std::vector<float>{9.0f, 9.0f, 9.0f, 1.0f})) << name;
        EXPECT_FALSE(noteWith(*depth, file, "1 channel (Z)").empty()) << name;
    }
    const Result<InputImage> combined = readInputImage(file, "Combined");
    ASSERT_TRUE(combined) << combined.error();
    EXPECT_EQ(rgba(*combined, 1, 0), (std::vector<float>{1.5f, 2.5f, 3.5f, 0.0f}));
}

TEST(InputImageLayers, SeveralLayersWithoutPlainOrCombinedIsAnErrorListingThem) {
    test::ScratchDir dir;
    const fs::path file = dir / "passes.exr";
    writeExr(file, 1, 1,
             {{"", {"diffuse.R", "diffuse.G", "diffuse.B", "specular.R", "specular.G", "specular.B"}, {1, 2, 3, 4, 5, 6}}});
    const Result<InputImage> input = readInputImage(file);
    ASSERT_FALSE(input);
    EXPECT_TRUE(contains(input.error(), file.string() + ": ")) << input.error();
    EXPECT_TRUE(contains(input.error(), "none is plain R,G,B or named Combined")) << input.error();
    EXPECT_TRUE(contains(input.error(), "layers: diffuse (R,G,B), specular (R,G,B)")) << input.error();

    const Result<InputImage> specular = readInputImage(file, "specular");
    ASSERT_TRUE(specular) << specular.error();
    EXPECT_EQ(rgba(*specular, 0, 0), (std::vector<float>{4, 5, 6, 1}));

    // One layer alone is read without being named.
    writeExr(dir / "one.exr", 1, 1, {{"", {"diffuse.R", "diffuse.G", "diffuse.B"}, {1, 2, 3}}});
    const Result<InputImage> only = readInputImage(dir / "one.exr");
    ASSERT_TRUE(only) << only.error();
    EXPECT_EQ(only->layer, "diffuse");
    EXPECT_EQ(rgba(*only, 0, 0), (std::vector<float>{1, 2, 3, 1}));
}

TEST(InputImageLayers, UnknownLayerIsAnErrorListingLayersAndParts) {
    test::ScratchDir dir;
    const fs::path file = dir / "parts.exr";
    writeTwoParts(file);
    const Result<InputImage> input = readInputImage(file, "normal");
    ASSERT_FALSE(input);
    EXPECT_EQ(input.error(), file.string() + ": no layer or part named 'normal'; layers: beauty (R,G,B,A), "
                                             "depth (Z); parts: beauty, depth");

    writeRenderLayers(dir / "render.exr");
    const Result<InputImage> layers = readInputImage(dir / "render.exr", "Normal");
    ASSERT_FALSE(layers);
    EXPECT_TRUE(contains(layers.error(), "layers: ViewLayer.Combined (R,G,B,A), ViewLayer.Depth (Z)")) << layers.error();
    EXPECT_FALSE(contains(layers.error(), "parts:")) << layers.error();
}

TEST(InputImageLayers, AmbiguousLastComponentIsAnError) {
    test::ScratchDir dir;
    const fs::path file = dir / "two.exr";
    writeExr(file, 1, 1, {{"", {"A.Combined.R", "A.Combined.G", "A.Combined.B", "B.Combined.R", "B.Combined.G", "B.Combined.B"},
                           {1, 2, 3, 4, 5, 6}}});
    const Result<InputImage> input = readInputImage(file, "Combined");
    ASSERT_FALSE(input);
    EXPECT_TRUE(contains(input.error(), "'Combined' is ambiguous: it matches A.Combined, B.Combined")) << input.error();
    EXPECT_EQ(rgba(*readInputImage(file, "B.Combined"), 0, 0), (std::vector<float>{4, 5, 6, 1}));
}

TEST(InputImage, NanInfinityAndNegativePixelsAreKeptAndCounted) {
    test::ScratchDir dir;
    const fs::path file = dir / "bad.exr";
    writeExr(file, 5, 1,
             {{"", {"R", "G", "B", "A"},
               {kNaN, 0, 0, 1,  kInf, kNaN, 0, 1,  -kInf, 0, 0, 1,  -0.5f, -2.0f, 0, 1,  0.5f, 0.5f, 0.5f, 1}}});
    const Result<InputImage> input = readInputImage(file);
    ASSERT_TRUE(input) << input.error();
    EXPECT_TRUE(std::isnan(input->image.at(0, 0, 0)));
    EXPECT_EQ(input->image.at(1, 0, 0), kInf);
    EXPECT_EQ(input->image.at(2, 0, 0), -kInf);
    EXPECT_EQ(input->image.at(3, 0, 1), -2.0f);
    EXPECT_EQ(input->notes.size(), 1u);
    EXPECT_EQ(noteWith(*input, file, "NaN"),
              file.string() + ": 2 pixels hold NaN, 2 pixels hold infinite values, 1 pixel holds a negative value "
                              "(kept as they are; effects sanitise their inputs)");
}

TEST(InputImage, OversizedImageIsRefusedFromItsHeader) {
    test::ScratchDir dir;
    const fs::path file = dir / "wide.exr";
    writeExr(file, 64, 8, {{"", {"R", "G", "B"}, std::vector<float>(64 * 8 * 3, 0.5f)}});
    // Cut the pixel data off: the limit must be applied before any pixel is read.
    fs::resize_file(file, fs::file_size(file) * 2 / 3);
    const Result<InputImage> refused = readInputImage(file, "", 32);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error(), file.string() + ": image is 64x8, larger than the limit of 32 pixels a side");
    const Result<InputImage> truncated = readInputImage(file, "", 64);
    ASSERT_FALSE(truncated);
    EXPECT_TRUE(contains(truncated.error(), file.string() + ": cannot read pixels")) << truncated.error();

    // The default limit is 16384 a side.
    const fs::path huge = dir / "huge.exr";
    writeExr(huge, 20000, 1, {{"", {"R", "G", "B"}, std::vector<float>(20000 * 3, 0.0f), OIIO::TypeDesc::HALF}});
    const Result<InputImage> tooWide = readInputImage(huge);
    ASSERT_FALSE(tooWide);
    EXPECT_EQ(tooWide.error(), huge.string() + ": image is 20000x1, larger than the limit of 16384 pixels a side");
}

TEST(InputImage, DataWindowIsPlacedInTheDisplayWindow) {
    test::ScratchDir dir;
    const fs::path file = dir / "crop.exr";
    OIIO::ImageSpec spec(2, 1, 3, OIIO::TypeDesc::FLOAT);
    spec.x = 1;
    spec.y = 2;
    spec.full_x = 0;
    spec.full_y = 0;
    spec.full_width = 4;
    spec.full_height = 3;
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(file.string(), spec));
    const std::vector<float> pixels = {1, 2, 3, 4, 5, 6};
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    ASSERT_TRUE(out->close());

    const Result<InputImage> input = readInputImage(file);
    ASSERT_TRUE(input) << input.error();
    EXPECT_EQ(input->image.width, 4);
    EXPECT_EQ(input->image.height, 3);
    EXPECT_EQ(rgba(*input, 1, 2), (std::vector<float>{1, 2, 3, 1}));
    EXPECT_EQ(rgba(*input, 2, 2), (std::vector<float>{4, 5, 6, 1}));
    EXPECT_EQ(rgba(*input, 0, 2), (std::vector<float>{0, 0, 0, 0}));
    EXPECT_EQ(rgba(*input, 1, 0), (std::vector<float>{0, 0, 0, 0}));
    EXPECT_FALSE(noteWith(*input, file, "data window 2x1 at (1, 2) differs from display window 4x3").empty());
}

TEST(InputImage, MissingOrUnreadableFilesAreErrorsNamingThem) {
    test::ScratchDir dir;
    const Result<InputImage> missing = readInputImage(dir / "nope.exr");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error(), (dir / "nope.exr").string() + ": no such file");
    const Result<InputImage> folder = readInputImage(dir.path());
    ASSERT_FALSE(folder);
    EXPECT_EQ(folder.error(), dir.path().string() + ": not a regular file");
    const fs::path text = dir.write("notes.png", "not an image");
    const Result<InputImage> garbage = readInputImage(text);
    ASSERT_FALSE(garbage);
    EXPECT_TRUE(contains(garbage.error(), text.string() + ": cannot read image")) << garbage.error();
}

TEST(InputImage, SplitLayerSuffixSplitsOnlyAfterAnImageFile) {
    test::ScratchDir dir;
    const fs::path png = dir.write("photo.png", "x");
    EXPECT_EQ(splitLayerSuffix("shot.exr:diffuse"), std::make_pair(fs::path("shot.exr"), std::string("diffuse")));
    EXPECT_EQ(splitLayerSuffix("dir/SHOT.EXR:ViewLayer.Combined"),
              std::make_pair(fs::path("dir/SHOT.EXR"), std::string("ViewLayer.Combined")));
    EXPECT_EQ(splitLayerSuffix(png.string() + ":left"), std::make_pair(png, std::string("left")));
    EXPECT_EQ(splitLayerSuffix("C:\\shots\\a.png"), std::make_pair(fs::path("C:\\shots\\a.png"), std::string()));
    EXPECT_EQ(splitLayerSuffix("C:\\shots\\a.exr:depth"), std::make_pair(fs::path("C:\\shots\\a.exr"), std::string("depth")));
    EXPECT_EQ(splitLayerSuffix("scene:name"), std::make_pair(fs::path("scene:name"), std::string()));
    EXPECT_EQ(splitLayerSuffix("plain.exr"), std::make_pair(fs::path("plain.exr"), std::string()));
    // A file whose own name holds the colon is taken whole.
    const fs::path colon = dir.write("odd.exr:name", "x");
    EXPECT_EQ(splitLayerSuffix(colon.string()), std::make_pair(colon, std::string()));
}

TEST(InputImageResample, ConstantStaysConstantAtOddSizes) {
    const Image image = constantImage(7, 5, 4, 0.375f);
    for (auto [w, h] : {std::pair{3, 11}, std::pair{13, 2}, std::pair{1, 1}, std::pair{29, 17}}) {
        const Result<Image> resized = resampleImage(image, w, h);
        ASSERT_TRUE(resized) << resized.error();
        EXPECT_EQ(resized->width, w);
        EXPECT_EQ(resized->height, h);
        EXPECT_EQ(resized->channels, 4);
        ASSERT_EQ(resized->pixels.size(), size_t(w * h * 4));
        for (float v : resized->pixels) EXPECT_NEAR(v, 0.375f, 1e-6) << w << "x" << h;
    }
}

TEST(InputImageResample, BrightPixelKeepsItsEnergyAndRingsIntoNoNegativeValue) {
    Image image = constantImage(64, 64, 1, 0.0f);
    image.at(31, 30, 0) = 1000.0f;
    const double area = 64.0 * 64.0;
    for (auto [w, h] : {std::pair{16, 16}, std::pair{21, 13}, std::pair{128, 96}}) {
        const Result<Image> resized = resampleImage(image, w, h);
        ASSERT_TRUE(resized) << resized.error();
        EXPECT_NEAR(sum(*resized), 1000.0 * (w * h) / area, 0.05 * 1000.0 * (w * h) / area) << w << "x" << h;
        for (float v : resized->pixels) EXPECT_GE(v, 0.0f) << w << "x" << h;
    }
    // What the triangle avoids: OpenImageIO's Lanczos filter rings below zero around the same pixel.
    OIIO::ImageBuf source(OIIO::ImageSpec(64, 64, 1, OIIO::TypeDesc::FLOAT), image.pixels.data());
    OIIO::ImageBuf lanczos(OIIO::ImageSpec(16, 16, 1, OIIO::TypeDesc::FLOAT));
    ASSERT_TRUE(OIIO::ImageBufAlgo::resize(lanczos, source, "lanczos3"));
    EXPECT_LT(OIIO::ImageBufAlgo::computePixelStats(lanczos).min[0], -1.0f);
}

TEST(InputImageResample, KeepsHorizontalGradientOrderAndRefusesBadSizes) {
    Image image = constantImage(9, 3, 3, 0.0f);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 9; ++x)
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = float(x) * float(c + 1);
    const Result<Image> resized = resampleImage(image, 5, 3);
    ASSERT_TRUE(resized) << resized.error();
    for (int x = 1; x < 5; ++x) EXPECT_GT(resized->at(x, 1, 2), resized->at(x - 1, 1, 2)) << x;
    EXPECT_NEAR(resized->at(2, 1, 0), 4.0f, 1e-5);  // the centre column maps to the centre column

    EXPECT_EQ(resampleImage(image, 9, 3)->pixels, image.pixels);
    EXPECT_FALSE(resampleImage(image, 0, 3));
    EXPECT_FALSE(resampleImage(image, 4, -1));
    EXPECT_FALSE(resampleImage(Image{}, 4, 4));
}

}  // namespace
}  // namespace rmfx
