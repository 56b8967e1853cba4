// Hard cases of the tone map stage (effects/variants/tonemap.xml), for every curve variant: one
// image holding black, a pixel at 1e6, NaN/Inf/negative texels and luminance 1e-10 beside ordinary
// values, tone mapped with the default settings, Exposure 0 and 1e4, and Scene_Luminance 0 and
// 1e-10 (the 1e-6 floor), with the HDR image stored in rgba32f (which keeps 1e-10) and rgba16f
// (which clamps 1e10 to 65504). Each asserts the stored HDR image finite and every 8-bit output within
// one code of the float64 model of the variant (tests/reference/ToneMapVariantsReference.h) on
// what was stored; Exposure 0 must give black.

#include <cmath>
#include <limits>

#include <glm/common.hpp>

#include <gtest/gtest.h>

#include "effects/Test/StageTestSupport.h"
#include "reference/StageInput.h"
#include "reference/ToneMapVariantsReference.h"

namespace rmfx::test {
namespace {

class ToneMapHardCasesGLTest : public GlTest {};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

RefImage hardImage() {
    RefImage image = syntheticHdrImage(23, 13, 8, -12.0, 8.0);
    for (int x = 0; x < 8; ++x)
        for (int y = 0; y < 4; ++y) image.at(x, y) = glm::dvec4(0.0, 0.0, 0.0, 1.0);  // a black block
    image.at(15, 6) = glm::dvec4(1e6, 1e6, 1e6, 1.0);
    image.at(16, 6) = glm::dvec4(1e6, 0.0, 0.0, 1.0);
    const glm::dvec4 poison[] = {{kNaN, 1.0, 1.0, 1.0}, {kInf, 0.5, 0.5, 1.0}, {-kInf, 2.0, kNaN, 1.0},
                                 {-0.25, 3.0, -1e-3, 1.0}, {kNaN, kNaN, kNaN, kNaN}, {1.0, -kInf, kInf, 1.0}};
    for (int i = 0; i < 6; ++i) image.at(2 + 3 * i, 10) = poison[i];
    for (int x = 0; x < 23; ++x) image.at(x, 12) = glm::dvec4(1e-10, 1e-10, 1e-10, 1.0);  // luminance 1e-10
    return image;
}

int code(double display) { return static_cast<int>(std::floor(std::clamp(display, 0.0, 1.0) * 255.0 + 0.5)); }

// The stored image (rgba32f or rgba16f) read back as it is.
RefImage stored(const GlRun& run) {
    Image hdr = readBack(*run.exec, "hdr");
    RefImage out(hdr.width, hdr.height);
    for (int y = 0; y < hdr.height; ++y)
        for (int x = 0; x < hdr.width; ++x) out.at(x, y) = glm::dvec4(atGl(hdr, x, y, 0), atGl(hdr, x, y, 1), atGl(hdr, x, y, 2), 1.0);
    return out;
}

TEST_F(ToneMapHardCasesGLTest, EveryCurveStaysFiniteAndOnItsModel) {
    RefImage input = hardImage();
    const std::pair<const char*, ToneMapCurve> curves[] = {{"analytic", ToneMapCurve::Analytic},
                                                           {"fast_gamma", ToneMapCurve::FastGamma},
                                                           {"lut256", ToneMapCurve::Lut256},
                                                           {"lut32", ToneMapCurve::Lut32}};
    struct Case {
        const char* what;
        float exposure, sceneLuminance;
    };
    const Case cases[] = {{"defaults", 1.0f, 0.18f},
                          {"Exposure 0", 0.0f, 0.18f},
                          {"Exposure 1e4", 1e4f, 0.18f},
                          {"Scene_Luminance 0", 1.0f, 0.0f},
                          {"Scene_Luminance 1e-10", 1.0f, 1e-10f}};
    for (auto [effect, curve] : curves) {
        ScratchDir dir;
        GlRun run = runStage("tonemap.xml", effect, input, dir);
        ASSERT_TRUE(run.exec);
        for (int format : {0, 1})
        for (const Case& c : cases) {
            std::string what = std::string(effect) + ", " + (format == 0 ? "rgba32f" : "rgba16f") + ", " + c.what;
            SCOPED_TRACE(what);
            setVariable(run, "Target_Format", Value::ofInt(format));
            setVariable(run, "Exposure", Value::ofFloat(c.exposure));
            setVariable(run, "Scene_Luminance", Value::ofFloat(c.sceneLuminance));
            renderAgain(run);
            RefImage hdr = stored(run);
            Image out = readBack(*run.exec, "tonemapped");
            ToneMapSettings settings{c.sceneLuminance, 0.18, 4.0};
            int worst = 0, lit = 0;
            for (int y = 0; y < hdr.height; ++y)
                for (int x = 0; x < hdr.width; ++x) {
                    glm::dvec3 h(hdr.at(x, y));
                    ASSERT_TRUE(std::isfinite(h.r) && std::isfinite(h.g) && std::isfinite(h.b)) << "hdr " << x << "," << y;
                    if (format == 1) {
                        ASSERT_LE(glm::max(h.r, glm::max(h.g, h.b)), 65504.0);
                    }
                    glm::dvec3 model = toneMapped(h, settings, curve);
                    for (int ch = 0; ch < 3; ++ch) {
                        int gpu = code(atGl(out, x, y, ch));
                        worst = std::max(worst, std::abs(gpu - code(model[ch])));
                        lit = std::max(lit, gpu);
                    }
                }
            expectWithin(what + ": codes off the model", worst, 1);
            if (c.exposure == 0.0f) {
                EXPECT_EQ(lit, 0) << "Exposure 0 must give black";
            } else {
                EXPECT_EQ(lit, 255) << "the 1e6 pixel maps to white";
            }
            // The poisoned texels are black, as zeros would be.
            for (int i = 0; i < 6; ++i)
                for (int ch = 0; ch < 3; ++ch) {
                    glm::dvec3 s = sanitisedTexel(input.at(2 + 3 * i, 10));
                    if (s[ch] == 0.0 && rec709Luminance(s) == 0.0) {
                        EXPECT_EQ(atGl(out, 2 + 3 * i, 10, ch), 0.0f);
                    }
                }
        }
    }
}

}  // namespace
}  // namespace rmfx::test
