// Hard cases of the bloom and streak stage workspaces (effects/variants/bloom.xml, streak.xml):
// black input, a 1e6 pixel, values beyond half float's range, NaN / ±Inf / negative texels, and
// image sizes whose reduction chains end in partial blocks. Each asserts finite output within a
// stated bound, for every variant (and every target format where a render is cheap).

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "effects/Test/GlareStageRun.h"

namespace rmfx::test {
namespace {

class GlareHardCasesGLTest : public GlTest {};

constexpr int kSize = 32;

struct Variant {
    std::string file;    // bloom.xml or streak.xml
    std::string effect;  // the blur kind or pass count
};

std::vector<Variant> allVariants() {
    std::vector<Variant> all;
    for (BloomBlur blur : allBloomBlurs()) all.push_back({"bloom.xml", bloomBlurName(blur)});
    for (int p : {2, 3, 4}) all.push_back({"streak.xml", "streak_" + std::to_string(p) + "pass"});
    return all;
}

// Every variant in the default rgba16f, and the default variants (tent13, streak_3pass) in every
// format: each format compiles every shader anew on llvmpipe (about a second each).
std::vector<std::pair<Variant, int>> variantsAndFormats() {
    std::vector<std::pair<Variant, int>> all;
    for (const Variant& v : allVariants()) all.push_back({v, 1});
    for (int format : {0, 2, 3, 4, 5}) {
        all.push_back({{"bloom.xml", "tent13"}, format});
        all.push_back({{"streak.xml", "streak_3pass"}, format});
    }
    return all;
}

std::string label(const Variant& v, int format) { return v.effect + " Target_Format " + std::to_string(format); }

RefImage black(int width, int height) { return RefImage(width, height, glm::dvec4(0.0, 0.0, 0.0, 1.0)); }

// Every intermediate and the result of a run are finite.
void expectAllTargetsFinite(const GlRun& run, const Variant& v) {
    std::vector<std::string> targets{"down", "result"};
    if (v.file == "bloom.xml") targets.push_back("blurred");
    else
        for (int d = 1; d <= 4; ++d) targets.push_back("streak_" + std::to_string(d));
    for (const std::string& t : targets) EXPECT_TRUE(allFinite(readRef(run, t))) << t << " has NaN or Inf";
}

TEST_F(GlareHardCasesGLTest, AllBlackInputGivesExactlyZero) {
    for (const auto& [v, format] : variantsAndFormats()) {
        SCOPED_TRACE(label(v, format));
        GlRun run = renderStage(v.file, black(kSize, kSize), v.effect, {{"Target_Format", std::to_string(format)}});
        ASSERT_TRUE(run.exec);
        EXPECT_EQ(maxColorChannel(readRef(run, "result")), 0.0);
        EXPECT_EQ(maxColorChannel(readRef(run, "down")), 0.0);
    }
}

// One pixel of 1e6 on black: B = 1e6 - 1 there, sum B = 3 (1e6 - 1). Every pass averages with
// weights summing to at most 1 and the upsample spreads a reduced texel over n^2 pixels, so the
// added light, sum (result - S), is at most Bloom_Strength * sum B (plus 1e-4 of it for float32
// sums, and for the encoded formats 10 writes' worth of their quantisation, which may round up);
// formats that saturate (RGBA8x64 at 65) add less.
TEST_F(GlareHardCasesGLTest, OnePixelAtAMillionStaysFiniteAndAddsNoMoreLightThanItHas) {
    RefImage input = black(kSize, kSize);
    input.at(kSize / 2 + 1, kSize / 2 - 3) = glm::dvec4(1e6, 1e6, 1e6, 1.0);
    const double strength = 0.5, sumB = 3.0 * (1e6 - 1.0);
    for (const auto& [v, format] : variantsAndFormats()) {
        SCOPED_TRACE(label(v, format));
        GlRun run = renderStage(v.file, input, v.effect, {{"Target_Format", std::to_string(format)}});
        ASSERT_TRUE(run.exec);
        expectAllTargetsFinite(run, v);
        double added = rgbSum(readRef(run, "result")) - rgbSum(sanitised(input));
        EXPECT_GT(added, 0.0);
        EXPECT_LE(added, strength * sumB * (1.0 + 1e-4 + 10.0 * quantisation(format, 1.0)));
    }
}

// A 4x4 block of 1e6 averages to 1e6 - 1 in its reduced texel: rgba16f and r11g11b10f targets keep
// their largest finite value (65504; 65024 in r11g11b10f's red, 64512 in its 10-bit blue) instead
// of Inf, and the result stays finite.
TEST_F(GlareHardCasesGLTest, ValuesAboveHalfMaxSaturateInFloat16AndR11G11B10Targets) {
    RefImage input = black(kSize, kSize);
    for (int y = 8; y < 12; ++y)
        for (int x = 12; x < 16; ++x) input.at(x, y) = glm::dvec4(1e6, 1e6, 1e6, 1.0);
    for (const Variant& v : {Variant{"bloom.xml", "tent13"}, Variant{"streak.xml", "streak_3pass"}})
        for (auto [format, largest] : {std::pair{1, 65504.0}, std::pair{2, 65024.0}}) {
            SCOPED_TRACE(label(v, format));
            GlRun run = renderStage(v.file, input, v.effect, {{"Target_Format", std::to_string(format)}});
            ASSERT_TRUE(run.exec);
            expectAllTargetsFinite(run, v);
            EXPECT_EQ(readRef(run, "down").at(3, 2).r, largest);
            EXPECT_EQ(readRef(run, "down").at(3, 2).b, format == 2 ? 64512.0 : largest);
            // The added light is at most Strength * largest on each of the 16 pixels' worth of each channel.
            double added = rgbSum(readRef(run, "result")) - rgbSum(input);
            EXPECT_LE(added, 0.5 * 3.0 * 16.0 * largest * (1.0 + 1e-4));
        }
}

// NaN, +Inf, -Inf and negative channels (negatives as lossy EXR compression leaves them) are
// sanitised to 0 where the input is read: the render equals, bit for bit, the render of the input
// with those channels set to 0, and nothing is NaN.
TEST_F(GlareHardCasesGLTest, NanInfAndNegativeTexelsRenderAsZeros) {
    RefImage clean = syntheticInput(kSize, kSize);
    RefImage dirty = clean;
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    auto spoil = [&](int x, int y, glm::dvec3 bad) {
        dirty.at(x, y) = glm::dvec4(bad, 1.0);
        for (int c = 0; c < 3; ++c) clean.at(x, y)[c] = std::isfinite(bad[c]) && bad[c] > 0.0 ? bad[c] : 0.0;
    };
    spoil(kSize / 2, kSize / 2 + 1, {nan, 5.0, nan});  // beside the central light
    spoil(3, 4, {inf, inf, inf});
    spoil(kSize - 1, kSize - 1, {-inf, 2.0, -inf});
    spoil(10, 20, {-0.5, -1e3, 3.0});
    spoil(11, 20, {-1e-3, 4.0, -7.0});
    for (const Variant& v : allVariants()) {
        SCOPED_TRACE(v.effect);
        GlRun expected = renderStage(v.file, clean, v.effect);
        GlRun run = renderStage(v.file, dirty, v.effect);
        ASSERT_TRUE(run.exec && expected.exec);
        expectAllTargetsFinite(run, v);
        EXPECT_EQ(maxRgbDifference(readRef(run, "result"), readRef(expected, "result")), 0.0);
    }
}

// Sizes that leave partial blocks at every level: one bright pixel in the last row and the last
// column must still reach the result. The added light, GPU against the float64 reference of the
// default variants (with rgba32f targets), within 1e-4 plus what the context's filtering allows
// each filtering pass of the chain (filteringAllowance: tent13's five passes, the streak's three
// and the merge): an H200 added 0.18 % more light than the reference through tent13 at 1921x1081.
void expectCornerPixelContributes(glm::ivec2 size) {
    SCOPED_TRACE(std::to_string(size.x) + "x" + std::to_string(size.y));
    RefImage input = black(size.x, size.y);
    input.at(size.x - 1, size.y - 1) = glm::dvec4(101.0, 51.0, 21.0, 1.0);
    glm::ivec2 reduced = reducedSize(size, 4);
    int n = reductionFactor(size, reduced);
    RefImage bloom = bloomStage(input, BloomBlur::Tent13, {}, n).result;
    RefImage streak = streakStage(input, 3, {}, n).result;
    for (auto [file, effect, expected, passes] :
         {std::tuple{"bloom.xml", "tent13", &bloom, 5}, std::tuple{"streak.xml", "streak_3pass", &streak, 4}}) {
        SCOPED_TRACE(effect);
        GlRun run = renderStage(file, input, effect, {{"Target_Format", "0"}});
        ASSERT_TRUE(run.exec);
        RefImage result = readRef(run, "result");
        ASSERT_TRUE(allFinite(result));
        double added = rgbSum(result) - rgbSum(input), expectedAdded = rgbSum(*expected) - rgbSum(input);
        std::printf("%dx%d %-12s added light %.6g, reference %.6g\n", size.x, size.y, effect, added, expectedAdded);
        EXPECT_GT(expectedAdded, 0.0);
        expectWithin(std::string(effect) + " added light", std::abs(added - expectedAdded) / expectedAdded,
                     1e-4 + filteringAllowance(passes));
    }
}

TEST_F(GlareHardCasesGLTest, TinyAndOddSizesKeepTheLastRowAndColumn) {
    expectCornerPixelContributes({1, 1});
    expectCornerPixelContributes({3, 5});
    expectCornerPixelContributes({1921, 1081});
}

}  // namespace
}  // namespace rmfx::test
