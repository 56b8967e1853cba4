// CPU mipmap levels against a float64 reference written differently: each output texel as the
// overlap of its footprint rectangle (box) with every texel of the level above, not separably.
// Images are asymmetric (every texel differs), so a flipped or transposed level fails.

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "io/image/MipChain.h"

namespace rmfx {
namespace {

Image ramp(int width, int height, int depth, int channels) {
    Image image;
    image.width = width;
    image.height = height;
    image.depth = depth;
    image.channels = channels;
    for (int z = 0; z < depth; ++z)
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                for (int c = 0; c < channels; ++c)
                    image.pixels.push_back(static_cast<float>(0.013 * x + 0.17 * y * y + 0.5 * z + 0.031 * c + 0.002 * x * y));
    return image;
}

struct Level {
    int w, h, d;
    std::vector<double> v;  // linear values
};

double overlap(double a0, double a1, double b0, double b1) { return std::max(0.0, std::min(a1, b1) - std::max(a0, b0)); }

Level referenceReduce(const Level& above, int nw, int nh, int nd, int channels) {
    Level out{nw, nh, nd, std::vector<double>(static_cast<size_t>(nw) * nh * nd * channels, 0.0)};
    const double sx = double(above.w) / nw, sy = double(above.h) / nh, sz = double(above.d) / nd;
    for (int z = 0; z < nd; ++z)
        for (int y = 0; y < nh; ++y)
            for (int x = 0; x < nw; ++x)
                for (int c = 0; c < channels; ++c) {
                    double sum = 0.0;
                    for (int k = 0; k < above.d; ++k)
                        for (int j = 0; j < above.h; ++j)
                            for (int i = 0; i < above.w; ++i) {
                                const double area = overlap(x * sx, (x + 1) * sx, i, i + 1) *
                                                    overlap(y * sy, (y + 1) * sy, j, j + 1) *
                                                    overlap(z * sz, (z + 1) * sz, k, k + 1);
                                sum += area * above.v[((static_cast<size_t>(k) * above.h + j) * above.w + i) * channels + c];
                            }
                    out.v[((static_cast<size_t>(z) * nh + y) * nw + x) * channels + c] = sum / (sx * sy * sz);
                }
    return out;
}

void expectMatchesReference(const Image& base, int levels) {
    const std::vector<Image> below = mipLevelsBelow(base, levels, MipEncoding::Linear);
    ASSERT_EQ(below.size(), static_cast<size_t>(levels - 1));
    Level reference{base.width, base.height, std::max(base.depth, 1), {base.pixels.begin(), base.pixels.end()}};
    for (int l = 1; l < levels; ++l) {
        const int nw = std::max(1, base.width >> l), nh = std::max(1, base.height >> l);
        const int nd = base.depth > 1 ? std::max(1, base.depth >> l) : 1;
        reference = referenceReduce(reference, nw, nh, nd, base.channels);
        const Image& mip = below[static_cast<size_t>(l - 1)];
        ASSERT_EQ(mip.width, nw) << "level " << l;
        ASSERT_EQ(mip.height, nh) << "level " << l;
        ASSERT_EQ(std::max(mip.depth, 1), nd) << "level " << l;
        ASSERT_EQ(mip.pixels.size(), reference.v.size());
        for (size_t i = 0; i < reference.v.size(); ++i)
            ASSERT_NEAR(mip.pixels[i], reference.v[i], 1e-6 * std::max(1.0, std::abs(reference.v[i])))
                << "level " << l << " value " << i;
    }
}

TEST(MipChain, PowerOfTwoLevelsAreTwoByTwoAverages) {
    const Image base = ramp(8, 4, 1, 4);
    const std::vector<Image> below = mipLevelsBelow(base, 4, MipEncoding::Linear);
    ASSERT_EQ(below.size(), 3u);
    EXPECT_EQ(below[0].width, 4);
    EXPECT_EQ(below[0].height, 2);
    EXPECT_EQ(below[1].width, 2);
    EXPECT_EQ(below[1].height, 1);
    EXPECT_EQ(below[2].width, 1);
    EXPECT_EQ(below[2].height, 1);
    // Level 1 texel (3, 1): the base's 2x2 block at (6..7, 2..3); the top row differs from the bottom.
    for (int c = 0; c < 4; ++c) {
        const double block = (base.at(6, 2, c) + base.at(7, 2, c) + base.at(6, 3, c) + base.at(7, 3, c)) / 4.0;
        EXPECT_NEAR(below[0].at(3, 1, c), block, 1e-6);
    }
    EXPECT_LT(below[0].at(0, 0, 0), below[0].at(0, 1, 0));
    EXPECT_LT(below[0].at(0, 0, 0), below[0].at(1, 0, 0));
    expectMatchesReference(base, 4);
}

TEST(MipChain, OddSizesWeighTheTexelsTheirFootprintsSplit) {
    expectMatchesReference(ramp(5, 3, 1, 3), 3);
    expectMatchesReference(ramp(7, 1, 1, 1), 3);
    expectMatchesReference(ramp(1, 6, 1, 2), 3);
    // 3 -> 1: the middle texel counts whole, the outer ones whole too: a plain average of three.
    const Image row = ramp(3, 1, 1, 1);
    const std::vector<Image> below = mipLevelsBelow(row, 2, MipEncoding::Linear);
    EXPECT_NEAR(below[0].pixels[0], (row.pixels[0] + row.pixels[1] + row.pixels[2]) / 3.0, 1e-6);
}

TEST(MipChain, VolumesReduceTheirDepthToo) {
    const Image volume = ramp(4, 4, 2, 1);
    const std::vector<Image> below = mipLevelsBelow(volume, 3, MipEncoding::Linear);
    ASSERT_EQ(below.size(), 2u);
    EXPECT_EQ(below[0].depth, 1);
    // Level 1 texel (0, 0): the 2x2x2 block at the origin.
    const auto at = [&](int x, int y, int z) { return volume.pixels[(static_cast<size_t>(z) * 4 + y) * 4 + x]; };
    const double block = (at(0, 0, 0) + at(1, 0, 0) + at(0, 1, 0) + at(1, 1, 0) + at(0, 0, 1) + at(1, 0, 1) +
                          at(0, 1, 1) + at(1, 1, 1)) / 8.0;
    EXPECT_NEAR(below[0].pixels[0], block, 1e-6);
    expectMatchesReference(ramp(4, 2, 8, 2), 4);
}

TEST(MipChain, SrgbColourIsAveragedAsLightAndAlphaAsItIs) {
    Image base;
    base.width = 2;
    base.height = 1;
    base.channels = 4;
    base.pixels = {0.0f, 1.0f, 0.5f, 0.0f, 1.0f, 1.0f, 0.5f, 1.0f};
    const std::vector<Image> below = mipLevelsBelow(base, 2, MipEncoding::Srgb);
    ASSERT_EQ(below.size(), 1u);
    // Half of full light, encoded: 0.7353569…; the other channels unchanged; alpha the plain mean.
    const double halfLight = 1.055 * std::pow(0.5, 1.0 / 2.4) - 0.055;
    EXPECT_NEAR(below[0].pixels[0], halfLight, 1e-6);
    EXPECT_NEAR(below[0].pixels[1], 1.0, 1e-6);
    EXPECT_NEAR(below[0].pixels[2], 0.5, 1e-6);
    EXPECT_NEAR(below[0].pixels[3], 0.5, 1e-6);
    const std::vector<Image> linear = mipLevelsBelow(base, 2, MipEncoding::Linear);
    EXPECT_NEAR(linear[0].pixels[0], 0.5, 1e-6);
}

}  // namespace
}  // namespace rmfx
