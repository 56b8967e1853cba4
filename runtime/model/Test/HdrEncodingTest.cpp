// The C++ twins of the HDR encodings (runtime/HdrEncoding.h) against float64 references written
// from the definitions (tests/reference/HdrEncodingReference.h): round-trip error over a dense log
// sweep within each format's bound, 0, tiny values, the maximum and beyond, NaN, ±Inf, negatives.
// The sweep prints the figures of docs/encodings.md:
//   rmfx_model_tests --gtest_filter='Encodings/HdrEncodingTest.RoundTripStaysWithinItsBound*'

#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "model/HdrEncoding.h"
#include "reference/HdrEncodingReference.h"

namespace rmfx::test {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kMaxFloat = std::numeric_limits<float>::max();

glm::vec3 roundTrip(HdrEncoding e, glm::vec3 c) { return decodeHdr(e, encodeHdr(e, c)); }

// The decoded value is a float: besides the format's bound it may be off by its own rounding (and,
// for RGB16 and RGBA8x64, by the float products of the decode: a few ulps).
double floatSlack(double value) { return std::ldexp(std::fabs(value), -21); }

class HdrEncodingTest : public ::testing::TestWithParam<HdrEncoding> {};
// The encodings that store integer codes (all but float, which passes values through).
class IntegerHdrEncodingTest : public HdrEncodingTest {};

TEST_P(HdrEncodingTest, RoundTripStaysWithinItsBound) {
    HdrEncoding e = GetParam();
    double maxError = 0.0;               // worst |decoded − input| / bound
    double maxRelative[2] = {0.0, 0.0};  // worst |decoded − input| / peak for peak ≥ 1e-2, ≥ 1
    double maxAbsoluteBelowOne = 0.0;
    float smallestDecoded = kInf;
    int count = 0;
    for (float v = 1e-36f; v <= hdrEncodingMax(e); v *= 1.0007f, ++count) {
        glm::vec3 c(v, 0.6f * v, 0.02f * v);
        glm::vec3 d = roundTrip(e, c);
        double bound = referenceErrorBound(e, glm::dvec3(c));
        for (int k = 0; k < 3; ++k) {
            double error = std::fabs(double(d[k]) - double(c[k]));
            ASSERT_LE(error, bound + floatSlack(c[k]) + floatSlack(d[k])) << hdrEncodingName(e) << " v=" << v << " channel " << k;
            if (bound > 0.0) maxError = std::max(maxError, error / bound);
            if (v >= 1e-2) maxRelative[0] = std::max(maxRelative[0], error / c.r);
            if (v >= 1.0) maxRelative[1] = std::max(maxRelative[1], error / c.r);
            if (v <= 1.0) maxAbsoluteBelowOne = std::max(maxAbsoluteBelowOne, error);
            if (d[k] > 0.0f) smallestDecoded = std::min(smallestDecoded, d[k]);
        }
    }
    std::printf("| %-8s | %9.3g | %9.3g | %9.3g | %9.3g | %9.3g | %5.3f | %d colours\n", hdrEncodingName(e),
                double(smallestDecoded), double(roundTrip(e, glm::vec3(hdrEncodingMax(e))).r), maxRelative[1], maxRelative[0],
                maxAbsoluteBelowOne, maxError, count);
}

TEST_P(IntegerHdrEncodingTest, CodesMatchTheDefinition) {
    HdrEncoding e = GetParam();
    for (float v = 1e-36f; std::isfinite(v) && v <= hdrEncodingMax(e) * 4.0f; v *= 1.013f) {
        glm::vec3 c(v, 0.37f * v, 0.004f * v);
        RefEncoded ref = referenceEncode(e, glm::dvec3(c));
        glm::uvec4 codes = encodeHdrCodes(e, c);
        glm::vec3 d = decodeHdrCodes(e, codes);
        if (e == HdrEncoding::Rgb9e5) {  // exact integer maths on both sides
            EXPECT_EQ(packRgb9e5(c), ref.codes[0] | ref.codes[1] << 9 | ref.codes[2] << 18 | ref.codes[3] << 27) << v;
        }
        if (e == HdrEncoding::Rgbe8 || e == HdrEncoding::Rgba8x64) {
            EXPECT_EQ(codes.w, ref.codes[3]) << v;
        }
        // Where a float product decides a half-way code (RGB16, RGB32 in double, RGBA8x64's rgb) the
        // codes may differ by one: one step of the decoded value.
        double step = 0.0;
        if (e == HdrEncoding::Rgb16) step = 100.0 / 65535.0;
        if (e == HdrEncoding::Rgb32) step = 1e4 / 4294967295.0;
        if (e == HdrEncoding::Rgba8x64) step = (1.0 + 64.0 * double(ref.codes[3]) / 255.0) / 255.0;
        for (int k = 0; k < 3; ++k) {
            if (e == HdrEncoding::Rgbe8) {
                EXPECT_EQ(codes[k], ref.codes[k]) << v;
            }
            EXPECT_LE(std::fabs(d[k] - ref.decoded[k]), step + floatSlack(ref.decoded[k]) + 1e-37)
                << hdrEncodingName(e) << " " << v;
        }
    }
}

TEST_P(HdrEncodingTest, ZeroAndTinyValuesDecodeToZeroOrWithinBound) {
    HdrEncoding e = GetParam();
    EXPECT_EQ(roundTrip(e, glm::vec3(0.0f)), glm::vec3(0.0f));
    for (float tiny : {1e-40f, std::numeric_limits<float>::denorm_min(), 1e-30f, 5e-8f, 1e-6f}) {
        glm::vec3 d = roundTrip(e, glm::vec3(tiny));
        double bound = referenceErrorBound(e, glm::dvec3(tiny));
        for (int k = 0; k < 3; ++k) {
            EXPECT_TRUE(std::isfinite(d[k])) << tiny;
            EXPECT_GE(d[k], 0.0f) << tiny;
            EXPECT_LE(std::fabs(double(d[k]) - tiny), bound + floatSlack(tiny)) << hdrEncodingName(e) << " " << tiny;
        }
    }
}

TEST_P(IntegerHdrEncodingTest, MaximumAndAboveSaturateFinite) {
    HdrEncoding e = GetParam();
    float max = hdrEncodingMax(e);
    glm::vec3 atMax = roundTrip(e, glm::vec3(max));
    EXPECT_LE(std::fabs(double(atMax.r) - max), referenceErrorBound(e, glm::dvec3(max)) + floatSlack(max));
    for (float above : {std::nextafter(max, kInf), max * 1.5f, 1e30f, kMaxFloat, kInf}) {
        glm::vec3 d = roundTrip(e, glm::vec3(above));
        if (above > max) {
            EXPECT_EQ(d, atMax) << hdrEncodingName(e) << " " << above;
        }
    }
}

TEST_P(IntegerHdrEncodingTest, NaNInfAndNegativeInputs) {
    HdrEncoding e = GetParam();
    glm::vec3 atMax = roundTrip(e, glm::vec3(hdrEncodingMax(e)));
    EXPECT_EQ(roundTrip(e, glm::vec3(kNaN)), glm::vec3(0.0f));
    EXPECT_EQ(roundTrip(e, glm::vec3(-kInf)), glm::vec3(0.0f));
    EXPECT_EQ(roundTrip(e, glm::vec3(-1.0f, -0.0f, -1e30f)), glm::vec3(0.0f));
    EXPECT_EQ(roundTrip(e, glm::vec3(kInf)), atMax);
    // One bad channel leaves the others intact (up to the shared exponent's precision).
    glm::vec3 mixed = roundTrip(e, glm::vec3(kNaN, 0.5f, -2.0f));
    double bound = referenceErrorBound(e, glm::dvec3(0.0, 0.5, 0.0)) + 1e-7;
    EXPECT_NEAR(mixed.g, 0.5, bound);
    EXPECT_NEAR(mixed.r, 0.0, bound);  // RGBE8 decodes a zero byte to half a step
    EXPECT_NEAR(mixed.b, 0.0, bound);
}

TEST(HdrEncoding, FloatPassesEveryValueThrough) {
    for (float v : {0.0f, -0.0f, 1e-40f, 1.5f, -3.0f, kMaxFloat, kInf, -kInf}) {
        glm::vec3 d = roundTrip(HdrEncoding::Float, glm::vec3(v));
        EXPECT_EQ(std::bit_cast<std::uint32_t>(d.r), std::bit_cast<std::uint32_t>(v));
    }
    EXPECT_TRUE(std::isnan(roundTrip(HdrEncoding::Float, glm::vec3(kNaN)).g));
}

TEST(HdrEncoding, Rgb16StoresOneHundredAsTheLargestCodeNotZero) {
    // The D3D10 sample multiplies by 65536, so 100 (1.0) wraps to code 0.
    EXPECT_EQ(encodeHdrCodes(HdrEncoding::Rgb16, glm::vec3(100.0f, 1e-9f, 0.0f)), glm::uvec4(65535u, 0u, 0u, 65535u));
    EXPECT_EQ(encodeHdrCodes(HdrEncoding::Rgb32, glm::vec3(10000.0f)),
              glm::uvec4(0xFFFFFFu, 0xFFFFFFu, 0xFFFFFFu, 0xFFFFFFu));  // three 32-bit 0xFFFFFFFF as four 24-bit integers
}

TEST(HdrEncoding, Rgbe8HasNoNaNAndBlackIsExponentZero) {
    // The DirectX sample's RGBE8 divides by the peak without a guard: 0 / 0.
    EXPECT_EQ(encodeHdrCodes(HdrEncoding::Rgbe8, glm::vec3(0.0f)), glm::uvec4(0u));
    EXPECT_EQ(encodeHdrCodes(HdrEncoding::Rgbe8, glm::vec3(1e-33f)), glm::uvec4(0u));
    EXPECT_EQ(decodeHdrCodes(HdrEncoding::Rgbe8, glm::uvec4(200u, 100u, 50u, 0u)), glm::vec3(0.0f));
    // Ward's worked case: 1.0 is mantissa 0.5 · 2^1 → byte 128, exponent 129; decoded (128 + 0.5) / 128.
    EXPECT_EQ(encodeHdrCodes(HdrEncoding::Rgbe8, glm::vec3(1.0f, 0.5f, 0.0f)), glm::uvec4(128u, 64u, 0u, 129u));
    EXPECT_EQ(decodeHdrCodes(HdrEncoding::Rgbe8, glm::uvec4(128u, 64u, 0u, 129u)),
              glm::vec3(128.5f / 128.0f, 64.5f / 128.0f, 0.5f / 128.0f));
}

TEST(HdrEncoding, Rgb9e5MatchesTheExtensionsWorkedValues) {
    // 1.0: floor(log2) = 0 → e = 16, mantissa 1 / 2^(16 − 24) = 256.
    EXPECT_EQ(packRgb9e5(glm::vec3(1.0f, 0.0f, 0.0f)), 256u | (16u << 27));
    // 65408 is 511 · 2^7 (e = 31); a mantissa rounding up to 512 moves to the next exponent.
    EXPECT_EQ(packRgb9e5(glm::vec3(65408.0f)), 511u | (511u << 9) | (511u << 18) | (31u << 27));
    EXPECT_EQ(packRgb9e5(glm::vec3(0.99999f, 0.0f, 0.0f)), 256u | (16u << 27));
    EXPECT_EQ(unpackRgb9e5(packRgb9e5(glm::vec3(std::ldexp(1.0f, -24)))), glm::vec3(std::ldexp(1.0f, -24)));
}

TEST(HdrEncoding, FormatsAndIndices) {
    EXPECT_EQ(hdrEncodingFormat(HdrEncoding::Rgb16), TargetFormat::RGBA16);
    EXPECT_EQ(hdrEncodingFormat(HdrEncoding::Rgb32), TargetFormat::RGBA32F);
    EXPECT_EQ(hdrEncodingFormat(HdrEncoding::Rgb9e5), TargetFormat::RGBA8);
    EXPECT_EQ(hdrEncodingFromIndex(5), HdrEncoding::Rgba8x64);
    EXPECT_EQ(hdrEncodingFromIndex(6), std::nullopt);
    EXPECT_EQ(hdrEncodingFromIndex(-1), std::nullopt);
}

INSTANTIATE_TEST_SUITE_P(IntegerEncodings, IntegerHdrEncodingTest,
                         ::testing::Values(HdrEncoding::Rgb16, HdrEncoding::Rgb32, HdrEncoding::Rgb9e5, HdrEncoding::Rgbe8,
                                           HdrEncoding::Rgba8x64),
                         [](const auto& info) { return std::string(hdrEncodingName(info.param)); });

INSTANTIATE_TEST_SUITE_P(Encodings, HdrEncodingTest,
                         ::testing::Values(HdrEncoding::Float, HdrEncoding::Rgb16, HdrEncoding::Rgb32, HdrEncoding::Rgb9e5,
                                           HdrEncoding::Rgbe8, HdrEncoding::Rgba8x64),
                         [](const auto& info) { return std::string(hdrEncodingName(info.param)); });

}  // namespace
}  // namespace rmfx::test
