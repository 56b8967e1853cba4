#include "editor/TargetDecoding.h"

#include <cmath>

#include <gtest/gtest.h>

namespace rmfx::editor {
namespace {

Image image(int width, int height, int channels, std::vector<float> pixels) {
    Image i;
    i.width = width;
    i.height = height;
    i.channels = channels;
    i.pixels = std::move(pixels);
    return i;
}

// IEC 61966-2-1, written out here rather than taken from the runtime.
int srgbByte(double linear) {
    double v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(v * 255.0));
}

}  // namespace

TEST(EditorTargetDecoding, NoneKeepsTheTexel) {
    glm::vec4 t(1.5f, -2.0f, 0.25f, 0.75f);
    EXPECT_EQ(decodeTexel(DecodeAs::None, t), t);
}

TEST(EditorTargetDecoding, Rgbe8DecodesWardsFormula) {
    // Bytes (128, 64, 32, 129) in an rgba8 target: (m + 0.5) · 2^(e − 136) = (m + 0.5) / 128.
    glm::vec4 texel(128 / 255.0f, 64 / 255.0f, 32 / 255.0f, 129 / 255.0f);
    glm::vec4 d = decodeTexel(DecodeAs::Rgbe8, texel);
    EXPECT_FLOAT_EQ(d.r, 128.5f / 128.0f);
    EXPECT_FLOAT_EQ(d.g, 64.5f / 128.0f);
    EXPECT_FLOAT_EQ(d.b, 32.5f / 128.0f);
    EXPECT_EQ(d.a, 1.0f);
}

TEST(EditorTargetDecoding, Alpha64DecodesRgbTimesOnePlus64A) {
    // rgb · (1 + 64 a): a = 2/255 → × (1 + 128/255).
    glm::vec4 texel(51 / 255.0f, 102 / 255.0f, 255 / 255.0f, 2 / 255.0f);
    glm::vec4 d = decodeTexel(DecodeAs::Rgba8x64, texel);
    const float k = 1.0f + 64.0f * 2.0f / 255.0f;
    EXPECT_NEAR(d.r, 51 / 255.0f * k, 1e-5f);
    EXPECT_NEAR(d.g, 102 / 255.0f * k, 1e-5f);
    EXPECT_NEAR(d.b, 1.0f * k, 1e-5f);
}

TEST(EditorTargetDecoding, Rgb9e5DecodesTheSharedExponent) {
    // Word: r mantissa 256, g 128, b 0, exponent 16 → m · 2^(16 − 15 − 9) = m / 256.
    std::uint32_t word = 256u | (128u << 9) | (16u << 27);
    glm::vec4 texel(float(word & 255u) / 255.0f, float((word >> 8) & 255u) / 255.0f, float((word >> 16) & 255u) / 255.0f,
                    float(word >> 24) / 255.0f);
    glm::vec4 d = decodeTexel(DecodeAs::Rgb9e5, texel);
    EXPECT_FLOAT_EQ(d.r, 1.0f);
    EXPECT_FLOAT_EQ(d.g, 0.5f);
    EXPECT_FLOAT_EQ(d.b, 0.0f);
}

TEST(EditorTargetDecoding, Rgb16IsAHundredOver65535PerCode) {
    glm::vec4 texel(65535 / 65535.0f, 1311 / 65535.0f, 0.0f, 1.0f);
    glm::vec4 d = decodeTexel(DecodeAs::Rgb16, texel);
    EXPECT_NEAR(d.r, 100.0f, 1e-4f);
    EXPECT_NEAR(d.g, 1311 * 100.0 / 65535.0, 1e-5f);
}

TEST(EditorTargetDecoding, OneChannelTexelsReadAsGlSamplesThem) {
    Image i = image(2, 1, 1, {0.25f, 3.0f});
    EXPECT_EQ(texelAt(i, 1, 0), glm::vec4(3.0f, 0.0f, 0.0f, 1.0f));
    Image rgba = image(1, 2, 4, {1, 2, 3, 4, 5, 6, 7, 8});
    EXPECT_EQ(texelAt(rgba, 0, 1), glm::vec4(5, 6, 7, 8));
}

TEST(EditorTargetDecoding, DisplayBytesApplyExposureThenSrgb) {
    EXPECT_EQ(displayBytes({0.5f, 0.0f, 1.0f, 0.3f}, 0.0f), (std::array<std::uint8_t, 4>{188, 0, 255, 255}));
    // One stop up doubles: 0.25 shows as 0.5 did; 0.001 is on the linear segment.
    auto b = displayBytes({0.25f, 0.001f, 4.0f, 1.0f}, 1.0f);
    EXPECT_EQ(b[0], srgbByte(0.5));
    EXPECT_EQ(b[1], srgbByte(0.002));
    EXPECT_EQ(b[2], 255);  // clipped
    auto down = displayBytes({8.0f, NAN, -1.0f, 1.0f}, -4.0f);
    EXPECT_EQ(down[0], srgbByte(0.5));
    EXPECT_EQ(down[1], 0);  // NaN shows black
    EXPECT_EQ(down[2], 0);
}

TEST(EditorTargetDecoding, TransformNoneOnlyClipsAndRounds) {
    auto b = displayBytes({0.5f, 2.0f, 0.1f, 1.0f}, 0.0f, DisplayTransform::None);
    EXPECT_EQ(b[0], 128);  // 127.5 rounds up
    EXPECT_EQ(b[1], 255);
    EXPECT_EQ(b[2], 26);  // 25.5
}

TEST(EditorTargetDecoding, DisplayPixelsDecodeEveryTexelRowsTopFirst) {
    // Two texels of RGBE8: exponent 128 → (m + 0.5) / 256; second texel 0 (exponent byte 0).
    Image i = image(1, 2, 4, {127 / 255.0f, 0, 0, 128 / 255.0f, 0, 0, 0, 0});
    std::vector<std::uint8_t> px = displayPixels(i, DecodeAs::Rgbe8, 0.0f);
    ASSERT_EQ(px.size(), 8u);
    EXPECT_EQ(px[0], srgbByte(127.5 / 256.0));
    EXPECT_EQ(px[3], 255);
    EXPECT_EQ(px[4], 0);
    EXPECT_EQ(px[7], 255);
}

}  // namespace rmfx::editor
