// effects/hdr_lighting.xml with its colour targets (scene, quarter, bright pass, bloom and star
// images) in each HDR encoding (HDR_Encoding, docs/encodings.md), against the same pipeline with
// those targets in rgba32f: float32 arithmetic and no rounding, so every difference is the
// encoding's. The real scene is rendered at 96x96 over 8 frames of 0.25 s (adaptation on).
//
// (a) The encoded scene target, decoded with the C++ twin (runtime/HdrEncoding.h), is within the
//     encoding's round-trip bound (tests/reference/HdrEncodingReference.h) of the float scene
//     saturated as the encoding saturates: RGB16 clamps each channel at 100 and RGBA8x64 scales a
//     colour down to a peak of 65, so the 1000 and 300 lights saturate there; those pixels are
//     checked to decode to the saturated value, not compared with the float scene.
// (b) The measured log-average is within a bound derived per quarter texel from the round-trip
//     bounds (see logAverageTolerance) of the float64 log-average of that saturated scene, and the
//     final output within kFinalTolerance (below) of the float pipeline's. RGB16 and RGBA8x64 run
//     (b) with every radiance scaled by 1/20 as well, so that nothing saturates and the whole output
//     can be compared; at the default radiances their saturated lights make a weaker bloom and star.
// (c) No NaN or Inf in the output or any decoded colour target, in any encoding.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "model/HdrEncoding.h"
#include "reference/CpuImage.h"
#include "reference/HdrEncodingReference.h"
#include "reference/HdrLightingReference.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

const RunSettings kRun{{96, 96}, 8, 0.25f};

// The targets that follow HDR_Encoding, in pipeline order.
const char* const kColourTargets[] = {"scene",       "quarter",     "bright",      "star_source", "bloom_source",
                                      "bloom_blur",  "bloom_h",     "bloom",       "star_work_a", "star_work_b",
                                      "star_line0",  "star_line1",  "star_line2",  "star_line3",  "star_line4",
                                      "star_line5",  "star_line6",  "star_line7",  "star"};

// Every radiance scaled by 1/20: the brightest pixel (light 0, 1000 → 50) stays under RGBA8x64's 65.
const Overrides kDimmed = {{"Light0_Radiance", "50"}, {"Light1_Radiance", "15"}, {"Panel_Radiance", "0.5"},
                           {"Ambient_Radiance", "0.001"}};

Overrides withEncoding(Overrides overrides, HdrEncoding e) {
    overrides.push_back({"HDR_Encoding", std::to_string(static_cast<int>(e))});
    return overrides;
}

// The workspace with its encoding targets in rgba32f (HDR_Encoding 0 passes colour through).
std::unique_ptr<Workspace> float32Pipeline(const Overrides& overrides) {
    auto ws = effectWorkspace("hdr_lighting.xml", withEncoding(overrides, HdrEncoding::Float));
    if (!ws) return nullptr;
    for (RenderTarget& t : ws->targets)
        if (t.formatVariable == "HDR_Encoding") t.format = t.formats[0] = TargetFormat::RGBA32F;
    return ws;
}

// One float32 run per set of overrides, shared by the encodings' tests.
const GlRun& float32Run(const Overrides& overrides) {
    static std::map<Overrides, GlRun> runs;
    auto it = runs.find(overrides);
    if (it == runs.end()) it = runs.emplace(overrides, runWorkspace(float32Pipeline(overrides), kRun)).first;
    return it->second;
}

double peak(glm::dvec3 c) { return std::max({c.r, c.g, c.b}); }

// A target of the encoding's format decoded with the C++ twin.
RefImage decoded(const GlRun& run, const std::string& target, HdrEncoding e) {
    RefImage image = readRef(run, target);
    for (glm::dvec4& t : image.texels) t = glm::dvec4(glm::dvec3(decodeHdr(e, glm::vec4(t))), 1.0);
    return image;
}

// What the encoding keeps of a colour above its maximum (docs/encodings.md).
glm::dvec3 saturatedAs(HdrEncoding e, glm::dvec3 c) {
    double max = hdrEncodingMax(e);
    if (e == HdrEncoding::Rgba8x64) return peak(c) > max ? c * (max / peak(c)) : c;
    return glm::min(c, glm::dvec3(max));
}

RefImage saturatedAs(HdrEncoding e, RefImage image) {
    for (glm::dvec4& t : image.texels) t = glm::dvec4(saturatedAs(e, glm::dvec3(t)), 1.0);
    return image;
}

// One encoding round trip of a colour in range: the format's bound, plus float32 rounding of the
// decoded value (RGB32 above ~19.5, docs/encodings.md). Float (the shipped rgba16f): one half
// step, 2^-10 of each channel (llvmpipe truncates).
double roundTripBound(HdrEncoding e, glm::dvec3 c) {
    if (e == HdrEncoding::Float) return std::ldexp(peak(c), -10);
    return referenceErrorBound(e, c) + std::ldexp(peak(c), -21);
}

// Bound on |log Lavg_encoded − log Lavg_float64|: each quarter texel q holds the box average of
// decoded scene pixels (error at most the mean of their bounds), encoded once more (its own
// bound), so its luminance is off by at most E_q = that sum (the weights sum to 1) and its
// log(δ + Y) by at most E_q / (δ + Y_q − E_q); the log-average is off by at most the mean of that.
// Plus the float32 budget of the reduction, 2e-5 (HdrLightingGLTest).
double logAverageTolerance(HdrEncoding e, const RefImage& scene, const RefImage& quarter) {
    double sum = 0.0;
    for (int y = 0; y < quarter.height; ++y)
        for (int x = 0; x < quarter.width; ++x) {
            double sceneError = 0.0;
            int n = 0;
            for (int j = 4 * y; j < std::min(4 * y + 4, scene.height); ++j)
                for (int i = 4 * x; i < std::min(4 * x + 4, scene.width); ++i, ++n)
                    sceneError += roundTripBound(e, glm::dvec3(scene.at(i, j)));
            glm::dvec3 q(quarter.at(x, y));
            double error = sceneError / n + roundTripBound(e, q);
            sum += error / (hdr::kLogDelta + std::max(hdr::luminance(q) - error, 0.0));
        }
    return sum / double(quarter.texels.size()) + 2e-5;
}

// The final output's tolerance, from the error ε of one round trip of a value of 1 (bright-pass,
// bloom and star values are in 0..1, and so is the tone-mapped scene): the scene read once (the
// tone map's slope is at most 1 after exposure), and each glare path re-encoded 7 times from the
// quarter image on (quarter, bright, star source, then bloom source, 5x5, H, V or three line
// passes and the merge), added with scales 1 and 0.5, each rounding carried at slope at most 1:
// 1 + 7 · 1.5 = 11.5, so 12 ε. RGB16's and RGB32's ε are absolute: scaled by the exposure
// k = key / (adapted + 0.001) where it exceeds 1. The adapted luminance's relative error ρ (which
// the log-average's, checked against its own bound, drives) moves the tone map by at most ρ/4
// (x / (1 + x)² ≤ 1/4) and the blue shift's coefficient by Δadapted / 4.1, under ρ/4 here: ρ/2.
// The output target is rgba16f in both pipelines: one half step, 2^-10 of the largest value.
double finalTolerance(HdrEncoding e, double exposureScale, double adaptedError, double largestOutput) {
    double epsilon = roundTripBound(e, glm::dvec3(1.0));
    if (e == HdrEncoding::Rgb16 || e == HdrEncoding::Rgb32) epsilon *= std::max(1.0, exposureScale);
    return 12.0 * epsilon + 0.5 * adaptedError + std::ldexp(largestOutput, -10);
}

bool allFinite(const RefImage& image) {
    return std::all_of(image.texels.begin(), image.texels.end(), [](const glm::dvec4& t) {
        return std::isfinite(t.r) && std::isfinite(t.g) && std::isfinite(t.b);
    });
}

struct Comparison {
    double sceneWorst = 0.0;  // largest error / bound over unsaturated pixels
    int saturated = 0;        // pixels whose float colour exceeds the encoding's maximum
    double lavgError = 0.0, lavgTolerance = 0.0;  // |log(Lavg / reference)|
    double finalError = 0.0, finalTolerance = 0.0;
};

// Runs the pipeline in encoding e and compares it with the float32 one; (c) is checked here.
Comparison compareWithFloat(HdrEncoding e, const Overrides& overrides) {
    Comparison out;
    const GlRun& reference = float32Run(overrides);
    GlRun run = runWorkspace(effectWorkspace("hdr_lighting.xml", withEncoding(overrides, e)), kRun);
    if (!reference.exec || !run.exec) {
        ADD_FAILURE() << "no run";
        return out;
    }
    for (const char* target : kColourTargets)
        EXPECT_TRUE(allFinite(decoded(run, target, e))) << target << " decodes to NaN or Inf";
    RefImage output = readRef(run, "output");
    EXPECT_TRUE(allFinite(output)) << "NaN or Inf in the output";

    // (a) The scene, below and above saturation.
    RefImage floatScene = readRef(reference, "scene"), scene = decoded(run, "scene", e);
    RefImage saturatedScene = saturatedAs(e, floatScene);
    for (size_t i = 0; i < scene.texels.size(); ++i) {
        glm::dvec3 expected(saturatedScene.texels[i]), got(scene.texels[i]);
        double bound = roundTripBound(e, expected);
        double error = peak(glm::abs(got - expected));
        if (peak(glm::dvec3(floatScene.texels[i])) > hdrEncodingMax(e)) {
            ++out.saturated;
            EXPECT_LE(error, bound) << "pixel " << i << " saturates to " << peak(got) << ", not " << peak(expected);
            EXPECT_GE(peak(got), hdrEncodingMax(e) - bound) << "pixel " << i << " does not wrap or fall to 0";
        } else {
            out.sceneWorst = std::max(out.sceneWorst, error / bound);
        }
    }
    EXPECT_LE(out.sceneWorst, 1.0) << hdrEncodingName(e) << ": scene beyond the round-trip bound";

    // (b) The log-average of the saturated float scene, in float64.
    RefImage quarter = hdr::boxDownscale(saturatedScene, 4);
    double reference64 = hdr::logAverage(quarter, saturatedScene).average;
    out.lavgError = std::fabs(std::log(readRef(run, "measured").at(0, 0).r / reference64));
    out.lavgTolerance = logAverageTolerance(e, saturatedScene, quarter);
    EXPECT_LE(out.lavgError, out.lavgTolerance) << hdrEncodingName(e) << ": log-average";

    double adapted = readRef(reference, "adapted").at(0, 0).r;
    double adaptedError = std::fabs(std::log(readRef(run, "adapted").at(0, 0).r / adapted));
    if (out.saturated == 0) {  // else the float scene's Lavg is not the saturated one's
        EXPECT_LE(adaptedError, out.lavgTolerance + 2e-5) << "the adaptation follows the log-average";
    }
    RefImage referenceOutput = readRef(reference, "output");
    out.finalError = maxAbsDifference(output, referenceOutput, 3);
    out.finalTolerance = finalTolerance(e, 0.18 / (adapted + 0.001), adaptedError, maxColorChannel(referenceOutput));
    return out;
}

void report(HdrEncoding e, const char* radiance, const Comparison& c) {
    std::printf("%-9s %-16s scene error/bound %.3f (%d saturated)  |log Lavg ratio| %.2e of %.2e  final max |diff| %.2e of %.2e\n",
                hdrEncodingName(e), radiance, c.sceneWorst, c.saturated, c.lavgError, c.lavgTolerance, c.finalError,
                c.finalTolerance);
}

bool saturatesTheLights(HdrEncoding e) { return e == HdrEncoding::Rgb16 || e == HdrEncoding::Rgba8x64; }

class HdrLightingEncodingGLTest : public GlTest, public ::testing::WithParamInterface<HdrEncoding> {};

TEST_P(HdrLightingEncodingGLTest, MatchesTheFloatPipelineWithinTheEncodingsBound) {
    HdrEncoding e = GetParam();
    Comparison atDefault = compareWithFloat(e, {});
    report(e, "default radiance", atDefault);
    if (saturatesTheLights(e)) {
        EXPECT_GT(atDefault.saturated, 10) << "the lights saturate " << hdrEncodingName(e);
        // The output is finite (checked above) but its glare is weaker: compare the dimmed scene.
        Comparison dimmed = compareWithFloat(e, kDimmed);
        report(e, "1/20 radiance", dimmed);
        EXPECT_EQ(dimmed.saturated, 0);
        EXPECT_LE(dimmed.finalError, dimmed.finalTolerance) << hdrEncodingName(e) << ": final output";
    } else {
        EXPECT_EQ(atDefault.saturated, 0);
        EXPECT_LE(atDefault.finalError, atDefault.finalTolerance) << hdrEncodingName(e) << ": final output";
    }
}

INSTANTIATE_TEST_SUITE_P(Encodings, HdrLightingEncodingGLTest,
                         ::testing::Values(HdrEncoding::Float, HdrEncoding::Rgb16, HdrEncoding::Rgb32, HdrEncoding::Rgb9e5,
                                           HdrEncoding::Rgbe8, HdrEncoding::Rgba8x64),
                         [](const auto& info) { return std::string(hdrEncodingName(info.param)); });

// GlExecutor::setVariable between frames reallocates the colour targets in the new encoding's
// format; the next frame renders exactly what a fresh run in that encoding renders. Adaptation off,
// so that a frame depends on nothing from the frames before it.
TEST_F(HdrLightingEncodingGLTest, SwitchingTheEncodingBetweenFramesRendersAsAFreshRun) {
    const Overrides still = {{"Light_Adaptation", "false"}};
    const RunSettings oneFrame{kRun.size, 1, kRun.deltaTime};
    GlRun run = runWorkspace(effectWorkspace("hdr_lighting.xml", withEncoding(still, HdrEncoding::Float)), oneFrame);
    ASSERT_TRUE(run.exec);
    for (HdrEncoding e : {HdrEncoding::Rgb9e5, HdrEncoding::Rgba8x64, HdrEncoding::Rgb32, HdrEncoding::Float}) {
        SCOPED_TRACE(hdrEncodingName(e));
        ASSERT_EQ(run.exec->setVariable("HDR_Encoding", Value::ofInt(static_cast<int>(e))).error(), "");
        Diagnostics d = run.exec->renderFrame({}).takeDiagnostics();
        ASSERT_TRUE(d.empty()) << formatAll(d);
        GlRun fresh = runWorkspace(effectWorkspace("hdr_lighting.xml", withEncoding(still, e)), oneFrame);
        ASSERT_TRUE(fresh.exec);
        for (const char* target : {"scene", "bloom", "star", "measured", "output"})
            EXPECT_EQ(maxAbsDifference(readRef(run, target), readRef(fresh, target), 3), 0.0) << target;
    }
}

}  // namespace
}  // namespace rmfx::test
