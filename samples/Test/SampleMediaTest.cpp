// The computed media of the chapter workspaces: the sky's range and the chapter's alpha encoding
// (rgb * (1 + 64 a) on 8 bits) against bounds derived from its quantisation.

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "samples/SampleMedia.h"

namespace rmfx::samples {
namespace {

Image singlePixel(glm::vec3 c) {
    Image image;
    image.width = image.height = 1;
    image.channels = 3;
    image.highDynamicRange = true;
    image.pixels = {c.r, c.g, c.b};
    return image;
}

glm::dvec3 roundTrip(glm::vec3 c) {
    Image e = encodeAlphaIntensity(singlePixel(c));
    for (float v : e.pixels) EXPECT_EQ(std::round(v * 255.0f), v * 255.0f) << "not an 8-bit value";
    return glm::dvec3(decodeAlphaIntensity(e.pixels[0], e.pixels[1], e.pixels[2], e.pixels[3]));
}

// At 128 texels per face and more the sun disc covers several texels; at 32 it falls between
// texel centres and vanishes.
TEST(ChapterMedia, SkySpansMoreThanFourDecadesWithASun) {
    Image sky = makeSkyCross(128, kChapterSunDirection, kChapterSunIntensity, 2);
    float lo = 1e30f, hi = 0.0f;
    for (int y = 0; y < sky.height; ++y)
        for (int x = 0; x < sky.width; ++x) {
            float v = std::max({sky.at(x, y, 0), sky.at(x, y, 1), sky.at(x, y, 2)});
            if (v > 0.0f) lo = std::min(lo, v);  // the cross's unused blocks are 0
            hi = std::max(hi, v);
        }
    EXPECT_GT(hi / lo, 1e4f);
    EXPECT_GT(hi, 1000.0f);
}

TEST(ChapterMedia, AlphaEncodingErrorStaysWithinItsQuantisation) {
    // Below 1 the alpha is 0 and rgb carries the value: half a step of 1/255. Above 1 the alpha is
    // the smallest step covering the peak, so the peak channel keeps rgb ≥ (m − 64/255) / m and its
    // relative error is at most 0.5/255 · m / (m − 64/255) ≤ 0.5/255 · 1.251 / 1.
    for (double v = 1e-3; v <= 65.0; v *= 1.07) {
        glm::vec3 c(float(v), float(v * 0.6), float(v * 0.2));
        glm::dvec3 d = roundTrip(c);
        double error = std::fabs(d.r - c.r);
        if (v <= 1.0)
            EXPECT_LE(error, 0.5 / 255.0 + 1e-7) << v;
        else
            EXPECT_LE(error / v, 0.5 / 255.0 * 1.251 + 1e-7) << v;
        EXPECT_LE(std::fabs(d.g - c.g), 0.5 / 255.0 * std::max(1.0, v * 1.251) + 1e-6) << v;
    }
    EXPECT_EQ(roundTrip(glm::vec3(0.0f)), glm::dvec3(0.0));
}

TEST(ChapterMedia, AlphaEncodingSaturatesAt65KeepingHue) {
    glm::dvec3 d = roundTrip(glm::vec3(2000.0f, 1000.0f, 0.0f));
    EXPECT_NEAR(d.r, 65.0, 1e-5);
    EXPECT_NEAR(d.g, 65.0 * 128.0 / 255.0, 1e-5);  // 0.5 rounds to 128/255
    EXPECT_EQ(d.b, 0.0);
    glm::dvec3 n = roundTrip(glm::vec3(std::nanf(""), 1.0f, INFINITY));
    EXPECT_EQ(n.r, 0.0);
    EXPECT_NEAR(n.b, 65.0, 1e-5);
}

TEST(ChapterMedia, GhostMaskIsOpaqueInsideAndClearAtTheBorder) {
    Image mask = makeGhostMask(64);
    ASSERT_EQ(mask.channels, 4);
    EXPECT_EQ(mask.at(32, 32, 3), 1.0f);
    EXPECT_EQ(mask.at(0, 0, 3), 0.0f);
    EXPECT_LE(mask.at(0, 32, 3), 2.0f / 255.0f);
    EXPECT_EQ(mask.at(32, 32, 0), 1.0f);
}

}  // namespace
}  // namespace rmfx::samples
