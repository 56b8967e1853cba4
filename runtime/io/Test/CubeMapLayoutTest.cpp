#include "io/image/CubeMapLayout.h"

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <tuple>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace rmfx {
namespace {

Image blank(int width, int height, int channels) {
    Image image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.pixels.assign(size_t(width) * height * channels, 0.0f);
    return image;
}

// OpenGL's face selection and (s, t), straight from the spec's table, for checking the inverse.
struct GlLookup {
    int face;
    float s;
    float t;
};

GlLookup glCubeLookup(const glm::vec3& r) {
    const float ax = std::abs(r.x), ay = std::abs(r.y), az = std::abs(r.z);
    int face;
    float sc, tc, ma;
    if (ax >= ay && ax >= az) {
        face = r.x > 0 ? 0 : 1;
        sc = r.x > 0 ? -r.z : r.z;
        tc = -r.y;
        ma = ax;
    } else if (ay >= az) {
        face = r.y > 0 ? 2 : 3;
        sc = r.x;
        tc = r.y > 0 ? r.z : -r.z;
        ma = ay;
    } else {
        face = r.z > 0 ? 4 : 5;
        sc = r.z > 0 ? r.x : -r.x;
        tc = -r.y;
        ma = az;
    }
    return {face, (sc / ma + 1) / 2, (tc / ma + 1) / 2};
}

TEST(CubeMapLayout, TexelDirectionsInvertOpenGlFaceSelection) {
    for (int face = 0; face < 6; ++face)
        for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 16; ++i) {
                const float u = (i + 0.5f) / 16, v = (j + 0.5f) / 16;
                const glm::vec3 d = cubeFaceTexelDirection(face, u, v);
                EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
                const GlLookup gl = glCubeLookup(d);
                EXPECT_EQ(gl.face, face) << cubeFaceName(face) << " " << u << "," << v;
                EXPECT_NEAR(gl.s, u, 1e-6f);
                EXPECT_NEAR(gl.t, v, 1e-6f);
            }
    // Spot values: the top-left texel corner of +X looks toward +Y and +Z; +Y's top edge toward -Z.
    const glm::vec3 corner = cubeFaceTexelDirection(PositiveX, 0, 0) * std::sqrt(3.0f);
    EXPECT_NEAR(corner.x, 1, 1e-6f);
    EXPECT_NEAR(corner.y, 1, 1e-6f);
    EXPECT_NEAR(corner.z, 1, 1e-6f);
    const glm::vec3 top = cubeFaceTexelDirection(PositiveY, 0.5f, 0) * std::sqrt(2.0f);
    EXPECT_NEAR(top.y, 1, 1e-6f);
    EXPECT_NEAR(top.z, -1, 1e-6f);
}

TEST(CubeMapLayout, EquirectMappingRoundTrips) {
    for (int j = 1; j < 32; ++j)
        for (int i = 0; i < 64; ++i) {
            const float u = i / 64.0f, v = j / 32.0f;
            const glm::vec2 back = equirectCoordinates(equirectDirection(u, v));
            EXPECT_NEAR(back.x, u, 1e-6f);
            EXPECT_NEAR(back.y, v, 1e-6f);
        }
    const glm::vec3 centre = equirectDirection(0.5f, 0.5f);
    EXPECT_NEAR(centre.z, -1, 1e-6f);
    const glm::vec3 east = equirectDirection(0.75f, 0.5f);
    EXPECT_NEAR(east.x, 1, 1e-6f);
    EXPECT_NEAR(equirectDirection(0.3f, 0.0f).y, 1, 1e-6f);
}

// A panorama whose RGB is its own direction * 0.5 + 0.5, from longitude and latitude.
Image directionPanorama(int height) {
    Image image = blank(2 * height, height, 3);
    const double pi = std::numbers::pi;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double lon = 2 * pi * ((x + 0.5) / image.width - 0.5);
            const double lat = pi * (0.5 - (y + 0.5) / image.height);
            const double d[3] = {std::cos(lat) * std::sin(lon), std::sin(lat), -std::cos(lat) * std::cos(lon)};
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = float(d[c] * 0.5 + 0.5);
        }
    return image;
}

TEST(CubeMapLayout, EquirectFacesLookWhereOpenGlSamplesThem) {
    Image panorama = directionPanorama(256);
    panorama.highDynamicRange = true;
    const Result<CubeFaces> faces = cubeFromEquirect(panorama);
    ASSERT_TRUE(faces) << faces.error();
    float worst = 0;
    for (int f = 0; f < 6; ++f) {
        const Image& face = (*faces)[f];
        ASSERT_EQ(face.width, 128);
        ASSERT_EQ(face.height, 128);
        ASSERT_EQ(face.channels, 3);
        EXPECT_TRUE(face.highDynamicRange);
        for (int y = 0; y < face.height; ++y)
            for (int x = 0; x < face.width; ++x) {
                const glm::vec3 d = cubeFaceTexelDirection(f, (x + 0.5f) / 128, (y + 0.5f) / 128);
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::abs(face.at(x, y, c) - (d[c] * 0.5f + 0.5f)));
            }
    }
    // Bilinear interpolation of a smooth field; the largest error is next to the poles.
    EXPECT_LT(worst, 4e-3f);
}

TEST(CubeMapLayout, EquirectWrapsInLongitudeAndTakesFaceSize) {
    // Only the first and last columns are lit; they meet behind the viewer, at +Z.
    Image panorama = blank(64, 32, 1);
    for (int y = 0; y < 32; ++y) {
        panorama.at(0, y, 0) = 1;
        panorama.at(63, y, 0) = 1;
    }
    // At face size 32 the two middle texels of +Z sample across the seam between those columns.
    const Result<CubeFaces> faces = cubeFromEquirect(panorama, 32);
    ASSERT_TRUE(faces) << faces.error();
    const Image& back = (*faces)[PositiveZ];
    ASSERT_EQ(back.width, 32);
    EXPECT_FLOAT_EQ(back.at(15, 16, 0), 1.0f);
    EXPECT_FLOAT_EQ(back.at(16, 16, 0), 1.0f);
    EXPECT_EQ(back.at(0, 16, 0), 0.0f);
    EXPECT_EQ((*faces)[NegativeZ].at(16, 16, 0), 0.0f);
}

// Six distinct colours, one per face in GL order.
const float kFaceColours[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};

// Block positions (column, row in face units) of each GL face in the two crosses.
const int kHorizontalBlocks[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
const int kVerticalBlocks[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {1, 3}};

Image colourCross(int columns, int rows, int n, const int blocks[6][2]) {
    Image cross = blank(columns * n, rows * n, 3);
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                for (int c = 0; c < 3; ++c)
                    cross.at(blocks[f][0] * n + x, blocks[f][1] * n + y, c) = kFaceColours[f][c];
    return cross;
}

TEST(CubeMapLayout, CrossFacesGetTheirColours) {
    const Image horizontal = colourCross(4, 3, 16, kHorizontalBlocks);
    const Image vertical = colourCross(3, 4, 16, kVerticalBlocks);
    for (const Image* cross : {&horizontal, &vertical}) {
        const Result<CubeFaces> faces = cubeFromCross(*cross);
        ASSERT_TRUE(faces) << faces.error();
        for (int f = 0; f < 6; ++f) {
            const Image& face = (*faces)[f];
            ASSERT_EQ(face.width, 16);
            ASSERT_EQ(face.height, 16);
            ASSERT_EQ(face.channels, 3);
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x)
                    for (int c = 0; c < 3; ++c)
                        ASSERT_EQ(face.at(x, y, c), kFaceColours[f][c]) << cubeFaceName(f);
        }
    }
}

// Pixels that touch across a seam in the cross must touch on the cube: the texels they become
// share an edge, found by comparing the directions of their edge midpoints. This checks the
// orientation of every face, including the rotated -Z of the vertical cross.
void expectSeamsMeetOnTheCube(const Image& cross, const CubeFaces& faces) {
    const int n = faces[0].width;
    std::map<int, std::tuple<int, int, int>> where;  // cross pixel index -> face, x, y
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) where[int(faces[f].at(x, y, 0))] = {f, x, y};
    auto edgeMidpoints = [n](const std::tuple<int, int, int>& texel) {
        const auto [f, x, y] = texel;
        const float u0 = float(x) / n, u1 = float(x + 1) / n, v0 = float(y) / n, v1 = float(y + 1) / n;
        const float um = (u0 + u1) / 2, vm = (v0 + v1) / 2;
        return std::array<glm::vec3, 4>{cubeFaceTexelDirection(f, u0, vm), cubeFaceTexelDirection(f, u1, vm),
                                        cubeFaceTexelDirection(f, um, v0), cubeFaceTexelDirection(f, um, v1)};
    };
    int seamPairs = 0;
    for (int y = 0; y < cross.height; ++y)
        for (int x = 0; x < cross.width; ++x) {
            const auto p = where.find(y * cross.width + x);
            if (p == where.end()) continue;
            for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
                if (x + dx >= cross.width || y + dy >= cross.height) continue;
                const auto q = where.find((y + dy) * cross.width + x + dx);
                if (q == where.end() || std::get<0>(q->second) == std::get<0>(p->second)) continue;
                ++seamPairs;
                float closest = 10;
                for (const glm::vec3& a : edgeMidpoints(p->second))
                    for (const glm::vec3& b : edgeMidpoints(q->second)) closest = std::min(closest, glm::length(a - b));
                EXPECT_LT(closest, 1e-5f) << "cross pixel " << x << "," << y << " (" << cubeFaceName(std::get<0>(p->second))
                                          << ") and its neighbour (" << cubeFaceName(std::get<0>(q->second))
                                          << ") do not touch on the cube";
            }
        }
    EXPECT_EQ(seamPairs, 5 * n);  // five seams are joined in either cross
}

Image indexCross(int columns, int rows, int n) {
    Image cross = blank(columns * n, rows * n, 1);
    for (size_t i = 0; i < cross.pixels.size(); ++i) cross.pixels[i] = float(i);
    return cross;
}

TEST(CubeMapLayout, HorizontalCrossSeamsMeetOnTheCube) {
    const Image cross = indexCross(4, 3, 8);
    const Result<CubeFaces> faces = cubeFromCross(cross);
    ASSERT_TRUE(faces) << faces.error();
    expectSeamsMeetOnTheCube(cross, *faces);
}

TEST(CubeMapLayout, VerticalCrossSeamsMeetOnTheCube) {
    const Image cross = indexCross(3, 4, 8);
    const Result<CubeFaces> faces = cubeFromCross(cross);
    ASSERT_TRUE(faces) << faces.error();
    expectSeamsMeetOnTheCube(cross, *faces);
    // -Z is stored upside down: its first texel is the last pixel of the cross.
    EXPECT_EQ((*faces)[NegativeZ].at(0, 0, 0), float(cross.pixels.size() - 1 - 8));
}

TEST(CubeMapLayout, RejectsWrongAspectRatios) {
    const Result<CubeFaces> square = cubeFromCross(blank(64, 64, 3));
    ASSERT_FALSE(square);
    EXPECT_NE(square.error().find("64x64"), std::string::npos) << square.error();
    EXPECT_NE(square.error().find("4:3"), std::string::npos) << square.error();
    EXPECT_FALSE(cubeFromCross(blank(10, 7, 3)));  // not 4:3 in whole faces
    EXPECT_FALSE(cubeFromCross(Image{}));

    const Result<CubeFaces> wide = cubeFromEquirect(blank(90, 60, 3));
    ASSERT_FALSE(wide);
    EXPECT_NE(wide.error().find("90x60"), std::string::npos) << wide.error();
    EXPECT_FALSE(cubeFromEquirect(blank(64, 32, 3), -1));

    const Result<CubeFaces> strip = cubeFromImage(blank(96, 16, 3));
    ASSERT_FALSE(strip);
    EXPECT_NE(strip.error().find("96x16"), std::string::npos) << strip.error();
    EXPECT_TRUE(cubeFromImage(blank(64, 32, 3)));
    EXPECT_TRUE(cubeFromImage(blank(64, 48, 3)));
    EXPECT_TRUE(cubeFromImage(blank(48, 64, 3)));
}

TEST(CubeMapLayout, SixFacesAreChecked) {
    std::array<Image, 6> faces;
    for (Image& face : faces) face = blank(8, 8, 4);
    EXPECT_TRUE(cubeFromFaces(faces));

    std::array<Image, 6> oblong = faces;
    oblong[NegativeY] = blank(8, 4, 4);
    Result<CubeFaces> result = cubeFromFaces(oblong);
    ASSERT_FALSE(result);
    EXPECT_NE(result.error().find("-Y"), std::string::npos) << result.error();
    EXPECT_NE(result.error().find("square"), std::string::npos) << result.error();

    std::array<Image, 6> sizes = faces;
    sizes[PositiveZ] = blank(16, 16, 4);
    result = cubeFromFaces(sizes);
    ASSERT_FALSE(result);
    EXPECT_NE(result.error().find("+Z"), std::string::npos) << result.error();

    std::array<Image, 6> channels = faces;
    channels[NegativeX] = blank(8, 8, 3);
    result = cubeFromFaces(channels);
    ASSERT_FALSE(result);
    EXPECT_NE(result.error().find("-X"), std::string::npos) << result.error();

    std::array<Image, 6> missing = faces;
    missing[PositiveY] = Image{};
    EXPECT_FALSE(cubeFromFaces(missing));
}

}  // namespace
}  // namespace rmfx
