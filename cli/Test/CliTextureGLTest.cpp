// rmfx render --texture NAME=FILE: your own environment behind the chapter's teapot. A 2:1
// longitude/latitude EXR of a known, asymmetric function of direction replaces shader_1's float
// sky; the sky pixels of the scene must be that function of each pixel's view ray (float64,
// from the camera and the documented longitude/latitude convention, not from rmfx's code).

#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class CliTextureGLTest : public GlTest {};

constexpr double kPi = 3.14159265358979323846;

// Different in every channel and along every axis, so that a mirrored or rotated sky fails.
glm::dvec3 skyOf(glm::dvec3 d) { return {1.2 + d.x, 1.5 + 0.8 * d.y, 2.0 - 0.6 * d.z}; }

// docs (CubeMapLayout.h): u, v in [0, 1], v = 0 at the top; longitude 2 pi (u - 0.5), latitude
// pi (0.5 - v), looking along (cos lat sin lon, sin lat, -cos lat cos lon).
glm::dvec3 equirectRay(double u, double v) {
    double lon = 2.0 * kPi * (u - 0.5), lat = kPi * (0.5 - v);
    return {std::cos(lat) * std::sin(lon), std::sin(lat), -std::cos(lat) * std::cos(lon)};
}

Image equirectSky(int width) {
    Image image = blankHdrImage(width, width / 2);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            glm::dvec3 c = skyOf(equirectRay((x + 0.5) / image.width, (y + 0.5) / image.height));
            for (int ch = 0; ch < 3; ++ch) image.at(x, y, ch) = static_cast<float>(c[ch]);
            image.at(x, y, 3) = 1.0f;
        }
    return image;
}

TEST_F(CliTextureGLTest, YourEnvironmentIsTheSkyBehindTheTeapot) {
    ScratchDir dir;
    ASSERT_TRUE(writeImage(dir / "env.exr", equirectSky(512)).ok());
    std::filesystem::path out = dir / "scene.exr";
    CommandResult cli = runRmfx("render " + shellQuoted(sourceDir() / "effects/shader_1.xml") +
                                    " --set Environment_Format=1 --set Exposure_Level=1 --texture Sky_Float=env.exr"
                                    " --size 64x64 --target scene -o " + shellQuoted(out),
                                dir.path());
    ASSERT_EQ(cli.status, 0) << cli.err;
    Result<Image> scene = readImage(out);
    ASSERT_TRUE(scene.ok()) << scene.error();
    ASSERT_EQ(scene->width, 64);

    // shader_1's <camera target="0 0.1 0" distance="3.4" yaw="35" pitch="6" fov="50"/>.
    const double yaw = 35 * kPi / 180, pitch = 6 * kPi / 180;
    glm::dvec3 target(0, 0.1, 0);
    glm::dvec3 eye = target + 3.4 * glm::dvec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                                               std::cos(yaw) * std::cos(pitch));
    glm::dmat4 inverse = glm::inverse(glm::perspective(50 * kPi / 180, 1.0, 0.05, 100.0) *
                                      glm::lookAt(eye, target, glm::dvec3(0, 1, 0)));
    int checked = 0;
    // The top rows of the image see only sky; the teapot lies lower.
    for (int row = 0; row < 8; ++row)
        for (int x = 0; x < 64; ++x) {
            glm::dvec2 ndc((x + 0.5) / 32.0 - 1.0, 1.0 - (row + 0.5) / 32.0);
            glm::dvec4 far = inverse * glm::dvec4(ndc, 1.0, 1.0);
            glm::dvec3 want = skyOf(glm::normalize(glm::dvec3(far) / far.w - eye));
            for (int c = 0; c < 3; ++c)
                // Two bilinear resamplings (longitude/latitude to 128-texel faces, then the GPU's) of a
                // function linear in the direction, then rgba16f storage: well under 0.5 %.
                EXPECT_NEAR(scene->at(x, row, c), want[c], 5e-3 * want[c]) << "pixel " << x << "," << row << " channel " << c;
            ++checked;
        }
    EXPECT_EQ(checked, 512);
}

TEST_F(CliTextureGLTest, AnImageOfNoCubeShapeIsAnErrorNamingTheTexture) {
    ScratchDir dir;
    Image odd = equirectSky(64);
    odd.height = 24;  // 64x24: neither 2:1 nor a cross
    odd.pixels.resize(static_cast<size_t>(odd.width) * odd.height * 4);
    ASSERT_TRUE(writeImage(dir / "odd.exr", odd).ok());
    CommandResult cli = runRmfx("render " + shellQuoted(sourceDir() / "effects/shader_1.xml") +
                                    " --set Environment_Format=1 --texture Sky_Float=odd.exr --size 16x16 -o out.exr",
                                dir.path());
    EXPECT_NE(cli.status, 0);
    EXPECT_NE(cli.err.find("Sky_Float"), std::string::npos) << cli.err;
    EXPECT_NE(cli.err.find("64x24"), std::string::npos) << cli.err;
    EXPECT_NE(cli.err.find("expected a 2:1 longitude/latitude image, a 4:3 horizontal cross or a 3:4 vertical cross"),
              std::string::npos)
        << cli.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

// An old .rfx whose texture file is missing (RenderMonkey's own media) loads with --texture in
// its place: lit_teapot's band = texture(Ramp, …) scales Paint (0.9, 0.6, 0.3) x the default
// material and light diffuse (0.8 x 1), so two constant ramps differ, on every teapot pixel, by
// (rampA - rampB) x Paint x 0.8, and nowhere else.
TEST_F(CliTextureGLTest, AnRfxTextureWhoseFileIsMissingTakesYours) {
    ScratchDir dir;
    auto ramp = [&](const std::string& name, glm::vec3 c) {
        Image image = blankHdrImage(8, 2);
        for (int i = 0; i < 16; ++i) {
            for (int ch = 0; ch < 3; ++ch) image.pixels[i * 4 + ch] = c[ch];
            image.pixels[i * 4 + 3] = 1.0f;
        }
        ASSERT_TRUE(writeImage(dir / name, image).ok());
    };
    ramp("white.exr", {1.0f, 1.0f, 1.0f});
    ramp("warm.exr", {0.5f, 0.25f, 0.0f});
    const std::string rfx = shellQuoted(sourceDir() / "tests/rfx/lit_teapot.rfx");
    CommandResult without = runRmfx("render " + rfx + " --size 64x64 -o none.exr", dir.path());
    EXPECT_EQ(without.status, 1);
    EXPECT_NE(without.err.find("RAMP.PNG' not found"), std::string::npos) << without.err;
    for (const char* name : {"white", "warm"}) {
        CommandResult cli = runRmfx("render " + rfx + " --size 64x64 --texture Ramp=" + name + ".exr -o " + name + "-out.exr",
                                    dir.path());
        ASSERT_EQ(cli.status, 0) << cli.err;
    }
    Result<Image> white = readImage(dir / "white-out.exr"), warm = readImage(dir / "warm-out.exr");
    ASSERT_TRUE(white.ok() && warm.ok());
    const glm::dvec3 want = glm::dvec3(0.5, 0.75, 1.0) * glm::dvec3(0.9, 0.6, 0.3) * 0.8;
    int teapot = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            glm::dvec3 d(white->at(x, y, 0) - warm->at(x, y, 0), white->at(x, y, 1) - warm->at(x, y, 1),
                         white->at(x, y, 2) - warm->at(x, y, 2));
            if (d == glm::dvec3(0.0)) continue;  // the background: the same in both
            ++teapot;
            // An imported effect's output is 8-bit, as RenderMonkey's back buffer was: each image rounds
            // to 1/255, so their difference is within one step.
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(d[c], want[c], 1.0 / 255 + 1e-4) << "pixel " << x << "," << y << " channel " << c;
        }
    EXPECT_GT(teapot, 200);
}

}  // namespace
}  // namespace rmfx::test
