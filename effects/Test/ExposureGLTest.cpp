// effects/shader_1.xml (chapter 8, exposure control): the scene target holds the environment
// decoded as rgb * (1 + 64 a) and scaled by Exposure_Level, compared with a float64 reference that
// filters the 8-bit cube texels bilinearly (as GL does, before the shader decodes) along each
// pixel's view ray. The teapot pass is switched off so every pixel is sky.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "io/image/CubeMapLayout.h"
#include "io/image/ImageIO.h"
#include "reference/CameraRays.h"
#include "reference/CpuImage.h"
#include "reference/CubeSampling.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class ExposureGLTest : public GlTest {};

constexpr int kWidth = 96, kHeight = 64;  // not square: the reference must follow the aspect ratio

struct SkyRun {
    GlRun run;
    RefImage scene;
    OrbitCameraSettings camera;
};

SkyRun renderSky(const Overrides& overrides) {
    SkyRun out;
    std::unique_ptr<Workspace> ws = effectWorkspace("shader_1.xml", overrides);
    if (!ws) return out;
    for (Pass& pass : ws->passes)
        if (pass.name == "teapot") pass.enabled = false;
    out.camera = ws->camera;
    out.run = runWorkspace(std::move(ws), {{kWidth, kHeight}, 1, 1.0f / 60.0f});
    if (out.run.exec) out.scene = fromImage(readBack(*out.run.exec, "scene"));
    return out;
}

CubeFaces loadCube(const std::string& file) {
    Result<Image> cross = readImage(sourceDir() / "samples" / "media" / file);
    if (!cross) {
        ADD_FAILURE() << cross.error();
        return {};
    }
    Result<CubeFaces> faces = cubeFromCross(*cross);
    if (!faces) ADD_FAILURE() << faces.error();
    return faces ? *faces : CubeFaces{};
}

struct Comparison {
    int compared = 0;
    double worstExcess = -1e30;  // largest |gl − ref| − tolerance
    double brightest = 0.0;
};

// decode(texel) = rgb · (1 + 64 a) for the 8-bit cube, the texel itself for the float one.
// Tolerance per pixel: one half-float step, 2^-10 relative, because GL leaves the rounding mode of
// float -> half writes open and llvmpipe truncates (seen here: results one step low); GL may quantise the bilinear
// weights (llvmpipe: 8 bits, Mesa's spec minimum), so each interpolated channel may be off by
// 2^-8 of the spread of its four texels, which the decode multiplies by (1 + 64 a) for rgb and by
// 64 rgb for alpha. The reference skips footprints that straddle a face edge (seamless filtering).
Comparison compareSky(const SkyRun& sky, const CubeFaces& faces, bool alphaEncoded, double exposure) {
    Comparison result;
    CameraRays rays(sky.camera, kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            glm::dvec3 d = rays.ray(x, y);
            CubeSample s = sampleCubeBilinear(faces, d);
            if (s.nearEdge) continue;
            // Spread of the footprint: sample a little off in each direction of the face grid.
            glm::dvec4 lo = s.value, hi = s.value;
            for (double e : {-1.0, 1.0})
                for (int axis = 0; axis < 3; ++axis) {
                    glm::dvec3 nudged = d;
                    nudged[axis] += e * 2.0 / faces[0].width;
                    CubeSample n = sampleCubeBilinear(faces, glm::normalize(nudged));
                    if (n.nearEdge) continue;
                    lo = glm::min(lo, n.value);
                    hi = glm::max(hi, n.value);
                }
            glm::dvec4 spread = (hi - lo) / 256.0;
            for (int c = 0; c < 3; ++c) {
                double ref, weightError;
                if (alphaEncoded) {
                    ref = s.value[c] * (1.0 + 64.0 * s.value.a) * exposure;
                    weightError = (spread[c] * (1.0 + 64.0 * s.value.a) + s.value[c] * 64.0 * spread.a) * exposure;
                } else {
                    ref = s.value[c] * exposure;
                    weightError = spread[c] * exposure;
                }
                double tolerance = std::ldexp(std::fabs(ref), -10) + weightError + 1e-6;
                double gl = sky.scene.at(x, y)[c];
                result.worstExcess = std::max(result.worstExcess, std::fabs(gl - ref) - tolerance);
                result.brightest = std::max(result.brightest, ref);
            }
            ++result.compared;
        }
    return result;
}

TEST_F(ExposureGLTest, AlphaEncodedSkyMatchesTheFloat64Decode) {
    SkyRun sky = renderSky({{"Exposure_Level", "0.5"}});
    ASSERT_TRUE(sky.run.exec);
    Comparison c = compareSky(sky, loadCube("sky_cross_alpha64.png"), true, 0.5);
    EXPECT_GT(c.compared, kWidth * kHeight / 2);
    EXPECT_GT(c.brightest, 20.0) << "the sun (clipped to 65 by the encoding) should be in view";
    EXPECT_LE(c.worstExcess, 0.0);
}

TEST_F(ExposureGLTest, HalfFloatSkyMatchesTheEnvironment) {
    SkyRun sky = renderSky({{"Exposure_Level", "0.25"}, {"Environment_Format", "1"}});
    ASSERT_TRUE(sky.run.exec);
    Comparison c = compareSky(sky, loadCube("sky_cross.exr"), false, 0.25);
    EXPECT_GT(c.compared, kWidth * kHeight / 2);
    EXPECT_GT(c.brightest, 100.0) << "the unclipped sun should be in view";
    EXPECT_LE(c.worstExcess, 0.0);
}

// Independent of any reference: exposure is a plain scale, so 8× the exposure is 8× every value
// (exact in half floats apart from the rounding of each result: one step, 2^-10 relative).
TEST_F(ExposureGLTest, ExposureScalesEveryPixelLinearly) {
    SkyRun low = renderSky({{"Exposure_Level", "0.25"}});
    SkyRun high = renderSky({{"Exposure_Level", "2"}});
    ASSERT_TRUE(low.run.exec && high.run.exec);
    double worst = 0.0;
    for (size_t i = 0; i < low.scene.texels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double a = low.scene.texels[i][c] * 8.0, b = high.scene.texels[i][c];
            worst = std::max(worst, std::fabs(a - b) / std::max(b, 1e-3));
        }
    EXPECT_LE(worst, std::ldexp(1.0, -10));
}

TEST_F(ExposureGLTest, ScreenClipsWhatTheSceneHolds) {
    SkyRun sky = renderSky({{"Exposure_Level", "1"}});
    ASSERT_TRUE(sky.run.exec);
    RefImage screen = fromImage(readBack(*sky.run.exec, "output"));
    EXPECT_EQ(maxAbsDifference(screen, sky.scene, 3), 0.0) << "the screen pass copies the scene";
    ScratchDir scratch;
    ASSERT_TRUE(writeImage(scratch / "screen.png", readBack(*sky.run.exec, "output"), DisplayTransform::None));
    Result<Image> png = readImage(scratch / "screen.png");
    ASSERT_TRUE(png);
    double brightest = 0.0;
    for (float v : png->pixels) brightest = std::max<double>(brightest, v);
    EXPECT_EQ(brightest, 1.0) << "values above 1 clip on an 8-bit screen";
}

}  // namespace
}  // namespace rmfx::test
