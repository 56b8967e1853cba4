// effects/variants/tonemap.xml: the stored HDR image against S · Exposure within the quantisation
// of each Target_Format, and each curve variant's 8-bit output against a float64 model of its own
// maths (tests/reference/ToneMapVariantsReference.h) applied to the stored image, within one code.

#include <cmath>

#include <gtest/gtest.h>

#include "effects/Test/StageTestSupport.h"
#include "model/HdrEncoding.h"
#include "reference/StageInput.h"
#include "reference/ToneMapVariantsReference.h"

namespace rmfx::test {
namespace {

class ToneMapVariantsGLTest : public GlTest {};

const char* const kFormats[] = {"rgba32f", "rgba16f", "r11g11b10f", "rgba8 alpha x64", "RGBE8", "RGB9E5"};
constexpr HdrEncoding kEncodings[] = {HdrEncoding::Float, HdrEncoding::Float, HdrEncoding::Float,
                                      HdrEncoding::Rgba8x64, HdrEncoding::Rgbe8, HdrEncoding::Rgb9e5};

// The stored image decoded, row 0 at the bottom.
RefImage storedHdr(const GlRun& run, int format) {
    Image hdr = readBack(*run.exec, "hdr");
    RefImage out(hdr.width, hdr.height);
    for (int y = 0; y < hdr.height; ++y)
        for (int x = 0; x < hdr.width; ++x) {
            glm::vec4 texel(atGl(hdr, x, y, 0), atGl(hdr, x, y, 1), atGl(hdr, x, y, 2), hdr.channels > 3 ? atGl(hdr, x, y, 3) : 1.0f);
            out.at(x, y) = glm::dvec4(glm::dvec3(decodeHdr(kEncodings[format], texel)), 1.0);
        }
    return out;
}

// What the store pass must leave of S · Exposure (`written`, a float product as the shader's), and
// how far from it: rgba32f keeps it; rgba16f and r11g11b10f clamp it to their largest finite value
// and round within a whole step (relative 2^-10 for half, 2^-24 below its normal range; 2^-6 and,
// blue, 2^-5 for the small floats), since the rounding direction is the driver's (llvmpipe
// converts toward zero, GPUs to nearest); the encodings give exactly the codes of their C++ twins
// (runtime/HdrEncoding, tested against independent references in HdrEncodingTest).
struct Expected {
    double value, bound;
};
Expected expectedStored(int format, glm::vec3 written, int channel) {
    double v = written[channel];
    switch (format) {
        case 0: return {v, 0.0};
        case 1: v = std::min(v, 65504.0); return {v, std::max(v * 0x1p-10, 0x1p-24)};
        case 2: v = std::min(v, channel == 2 ? 64512.0 : 65024.0); return {v, std::max(v * (channel == 2 ? 0x1p-5 : 0x1p-6), 0x1p-20)};
        default: return {decodeHdr(kEncodings[format], encodeHdr(kEncodings[format], written))[channel], 0.0};
    }
}

int code(double display) { return static_cast<int>(std::floor(std::clamp(display, 0.0, 1.0) * 255.0 + 0.5)); }

// The largest difference, in codes, between the output and the curve's model of the stored image.
int largestCodeDifference(const GlRun& run, const RefImage& stored, const ToneMapSettings& settings, ToneMapCurve curve) {
    Image out = readBack(*run.exec, "tonemapped");
    int worst = 0;
    for (int y = 0; y < stored.height; ++y)
        for (int x = 0; x < stored.width; ++x) {
            glm::dvec3 model = toneMapped(glm::dvec3(stored.at(x, y)), settings, curve);
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(code(atGl(out, x, y, c)) - code(model[c])));
            EXPECT_EQ(atGl(out, x, y, 3), 1.0f);
        }
    return worst;
}

const ToneMapSettings kSettings{0.25, 0.18, 4.0};
constexpr float kExposure = 1.5f;
const Overrides kOverrides{{"Scene_Luminance", "0.25"}, {"Exposure", "1.5"}};

TEST_F(ToneMapVariantsGLTest, StoredImageIsTheExposedInputWithinEachFormatsQuantisation) {
    ScratchDir dir;
    RefImage input = syntheticHdrImage(41, 29, 3, -14.0, 15.0, 0.05);
    GlRun run = runStage("tonemap.xml", "analytic", input, dir, kOverrides);
    ASSERT_TRUE(run.exec);
    for (int format = 0; format < 6; ++format) {
        SCOPED_TRACE(std::string("Target_Format ") + kFormats[format]);
        setVariable(run, "Target_Format", Value::ofInt(format));
        renderAgain(run);
        RefImage stored = storedHdr(run, format);
        double worst = 0.0;  // in units of the bound
        for (int y = 0; y < input.height; ++y)
            for (int x = 0; x < input.width; ++x) {
                glm::vec3 written = glm::vec3(sanitisedTexel(input.at(x, y))) * kExposure;
                for (int c = 0; c < 3; ++c) {
                    Expected e = expectedStored(format, written, c);
                    double error = std::abs(stored.at(x, y)[c] - e.value);
                    ASSERT_LE(error, e.bound) << "texel " << x << "," << y << " channel " << c << ": stored " << stored.at(x, y)[c]
                                              << ", S · Exposure " << written[c];
                    if (e.bound > 0.0) worst = std::max(worst, error / e.bound);
                }
            }
        ::testing::Test::RecordProperty(std::string("worst error / bound, ") + kFormats[format], std::to_string(worst));
        // The tone map of what was stored, by the analytic curve, within one code.
        expectWithin(std::string("analytic, codes off, ") + kFormats[format],
                     largestCodeDifference(run, stored, kSettings, ToneMapCurve::Analytic), 1);
    }
}

TEST_F(ToneMapVariantsGLTest, EachCurveIsItsOwnMathsWithinOneCode) {
    ScratchDir dir;
    RefImage input = syntheticHdrImage(41, 29, 4, -16.0, 16.0, 0.05);
    const std::pair<const char*, ToneMapCurve> curves[] = {{"analytic", ToneMapCurve::Analytic},
                                                           {"fast_gamma", ToneMapCurve::FastGamma},
                                                           {"lut256", ToneMapCurve::Lut256},
                                                           {"lut32", ToneMapCurve::Lut32}};
    for (auto [effect, curve] : curves) {
        SCOPED_TRACE(effect);
        GlRun run = runStage("tonemap.xml", effect, input, dir, kOverrides);
        ASSERT_TRUE(run.exec);
        RefImage stored = storedHdr(run, 1);
        expectWithin(std::string(effect) + ", codes off its model", largestCodeDifference(run, stored, kSettings, curve), 1);
        // fast_gamma and lut32 are told apart from the ideal by more than the tolerance on this
        // image; lut256 stays within a code of it, so its table is checked entry by entry.
        int apart = 0;
        for (const glm::dvec4& t : stored.texels) {
            glm::dvec3 a = toneMapped(glm::dvec3(t), kSettings, curve), b = toneMapped(glm::dvec3(t), kSettings, ToneMapCurve::Analytic);
            for (int c = 0; c < 3; ++c) apart = std::max(apart, std::abs(code(a[c]) - code(b[c])));
        }
        ::testing::Test::RecordProperty(std::string(effect) + ": codes apart from the ideal", apart);
        if (curve == ToneMapCurve::FastGamma || curve == ToneMapCurve::Lut32) {
            EXPECT_GE(apart, 2);
        }
        if (curve == ToneMapCurve::Lut256 || curve == ToneMapCurve::Lut32) {
            int entries = curve == ToneMapCurve::Lut256 ? 256 : 32;
            RefImage table = readRef(run, entries == 256 ? "curve_lut256" : "curve_lut32");
            ASSERT_EQ(table.width, entries);
            double worst = 0.0;
            for (int i = 0; i < entries; ++i) {
                double l = std::exp2(-12.0 + 24.0 * i / (entries - 1));
                worst = std::max(worst, relativeError(table.at(i, 0).r, photographicRatio(l, kSettings.whitePoint)));
            }
            expectWithin(std::string(effect) + ": table entries, relative error", worst, 1e-6);
        }
    }
}

}  // namespace
}  // namespace rmfx::test
