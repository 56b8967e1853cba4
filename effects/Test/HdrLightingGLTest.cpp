// effects/hdr_lighting.xml (the DirectX SDK HDRLighting sample) against the float64 references of
// tests/reference/HdrLightingReference.h. The scene passes are replaced by an analytic pattern
// (black pixels, huge peaks, negatives, NaN and Inf) so the inputs are known; each stage is compared
// with its reference computed from the stage's own input as the GPU left it, so errors do not
// accumulate across stages and every tolerance is that of one pass.
//
// Tolerances. rgba16f targets: one half-float step, 2^-10 relative (GL leaves the rounding of
// float -> half writes open; llvmpipe truncates), on top of float32 arithmetic (~1e-6 relative for
// these short sums of non-negative terms). The shaders filter in float32 after fetching texels (no
// fixed-point bilinear weights). rg32f/r32f: the error bounds are derived at each test.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "reference/CpuImage.h"
#include "reference/HdrLightingReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

class HdrLightingGLTest : public GlTest {};

std::unique_ptr<Workspace> loadHdrLighting(const Overrides& overrides = {}) {
    return effectWorkspace("hdr_lighting.xml", overrides);
}

// Disables every pass after `last` (the ones a test does not look at, for speed).
void stopAfter(Workspace& ws, const std::string& last) {
    bool after = false;
    for (Pass& pass : ws.passes) {
        if (after) pass.enabled = false;
        if (pass.name == last) after = true;
    }
}

// The target in `format`, whatever HDR_Encoding picks (its format-by list too).
void setFormat(Workspace& ws, const std::string& target, TargetFormat format) {
    for (RenderTarget& t : ws.targets)
        if (t.name == target) {
            t.format = format;
            std::fill(t.formats.begin(), t.formats.end(), format);
        }
}

RefImage targetImage(const GlRun& run, const std::string& name) { return fromImage(readBack(*run.exec, name)); }

double maxChannel(const RefImage& image) {
    double m = 0.0;
    for (const glm::dvec4& t : image.texels) m = std::max({m, t.r, t.g, t.b});
    return m;
}

const double kHalfStep = std::ldexp(1.0, -10);
// One rounding to half plus the float32 arithmetic of a pass (a few 1e-6 relative).
const double kHalfTolerance = kHalfStep + 1e-5;

// ---------------------------------------------------------------- log-average luminance

// Black rows at the bottom (whole quarter texels black: log(delta) matters), values from 2^-12 to
// 2^10, scattered black pixels, negatives, one NaN, one +Inf and peaks of `peak`.
std::string logAveragePattern(double peak) {
    return R"(void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int h = (p.x * 7 + p.y * 13) % 17;
    vec3 c = vec3(exp2(float(p.x % 23) - 12.0), exp2(float(p.y % 19) - 10.0), float(h) * 0.3);
    if (h == 3) c = vec3(-5.0, 2.0, -0.5);
    if (p.x % 16 == 5 && p.y % 16 == 9) c = vec3(1.0, 0.9, 1.1) * )" + glslFloat(peak) + R"(;
    if (h == 0 || p.y < 8) c = vec3(0.0);
    if (p == ivec2(2, 9)) c = vec3(uintBitsToFloat(0x7FC00000u));
    if (p == ivec2(7, 10)) c.g = uintBitsToFloat(0x7F800000u);
    fragColor = vec4(c, 1.0);
}
)";
}

struct LuminanceRun {
    GlRun run;
    RefImage scene, quarter;
    double average = 0.0, peak = 0.0;  // the measured target
};

LuminanceRun measure(glm::ivec2 size, double peak, bool floatScene) {
    LuminanceRun out;
    auto ws = loadHdrLighting();
    if (!ws) return out;
    replaceSceneWithPattern(*ws, "scene", logAveragePattern(peak));
    if (floatScene) {
        setFormat(*ws, "scene", TargetFormat::RGBA32F);
        setFormat(*ws, "quarter", TargetFormat::RGBA32F);
    }
    stopAfter(*ws, "luminance1");
    out.run = runWorkspace(std::move(ws), {size, 1, 1.0f / 60.0f});
    if (!out.run.exec) return out;
    out.scene = targetImage(out.run, "scene");
    out.quarter = targetImage(out.run, "quarter");
    Image measured = readBack(*out.run.exec, "measured");
    out.average = measured.at(0, 0, 0);
    out.peak = measured.at(0, 0, 1);
    return out;
}

// A 1e6 peak overflows half floats (max 65504; written as Inf or clamped, driver-dependent), so
// this test makes the scene and quarter targets rgba32f; the luminance chain is rg32f anyway.
// Float32 error budget of Lavg: the quarter's sums of 16 non-negative texels (1e-6 relative, so
// 1e-6 in log), log near 23 within 3 ulps (6e-6), the weighted means (~1e-6), exp of up to 23 within
// (3 + 2|x|) ulps (3e-6): 2e-5 relative. The peak passes one log and one exp: 2e-5 relative.
TEST_F(HdrLightingGLTest, LogAverageOfBlackPixelsNegativesNanAndMillionPeaksMatchesFloat64) {
    for (glm::ivec2 size : {glm::ivec2(98, 70), glm::ivec2(128, 128), glm::ivec2(301, 262)}) {
        SCOPED_TRACE(std::to_string(size.x) + "x" + std::to_string(size.y));
        LuminanceRun r = measure(size, 1.0e6, true);
        ASSERT_TRUE(r.run.exec);
        RefImage quarter = hdr::boxDownscale(r.scene, 4);
        ASSERT_EQ(quarter.width, (size.x + 3) / 4);
        EXPECT_LE(worstExcess(r.quarter, quarter, 2e-6, 0.0), 0.0) << "exact 4x4 box average";
        hdr::LogAverage ref = hdr::logAverage(quarter, r.scene);
        EXPECT_NEAR(ref.peak, 0.2125 * 1e6 + 0.7154 * 0.9e6 + 0.0721 * 1.1e6, 1.0) << "the peak is in the image";
        int blackTexels = 0;
        for (const glm::dvec4& t : quarter.texels) blackTexels += hdr::luminance(glm::dvec3(t)) == 0.0;
        EXPECT_GE(blackTexels, 2 * quarter.width) << "whole black quarter texels: log(delta) counts";
        EXPECT_NEAR(r.average / ref.average, 1.0, 2e-5) << "Lavg " << r.average << " vs " << ref.average;
        EXPECT_NEAR(r.peak / ref.peak, 1.0, 2e-5) << "peak " << r.peak << " vs " << ref.peak;
        // The arithmetic mean, which a careless reduction would give, is far off.
        double mean = 0.0;
        for (const glm::dvec4& t : quarter.texels) mean += hdr::luminance(glm::dvec3(t)) / quarter.texels.size();
        EXPECT_GT(mean / ref.average, 10.0);
    }
}

// The workspace as it is: rgba16f scene and quarter (peaks of 3e4, inside half range). The quarter
// is the exact average rounded once to half; Lavg from the quarter the GPU wrote is within the
// float32 budget above, and within 2^-10 (one half step of every texel, at most 2^-10 in log) of
// the average of the unrounded quarter.
TEST_F(HdrLightingGLTest, LogAverageInTheHalfFloatPipelineMatchesFloat64) {
    LuminanceRun r = measure({98, 70}, 3.0e4, false);
    ASSERT_TRUE(r.run.exec);
    RefImage quarter = hdr::boxDownscale(r.scene, 4);
    EXPECT_LE(worstExcess(r.quarter, quarter, kHalfTolerance, 1e-12), 0.0);
    hdr::LogAverage fromGpuQuarter = hdr::logAverage(r.quarter, r.scene);
    hdr::LogAverage exact = hdr::logAverage(quarter, r.scene);
    EXPECT_NEAR(r.average / fromGpuQuarter.average, 1.0, 2e-5);
    EXPECT_NEAR(r.average / exact.average, 1.0, kHalfStep + 2e-5);
    EXPECT_NEAR(r.peak / exact.peak, 1.0, 2e-5);
    EXPECT_GT(exact.peak, 2.0e4);
}

// ---------------------------------------------------------------- light adaptation

// A uniform grey scene of luminance y (rgb equal: Y = y, as the weights sum to 1).
std::string uniformPattern(double y) {
    return "void main() { fragColor = vec4(vec3(" + glslFloat(y) + "), 1.0); }\n";
}

struct AdaptationRun {
    GlRun run;
    double adapted = 0.0, measured = 0.0;
};

AdaptationRun adapt(int frames, float dt, double initial, TargetFormat format = TargetFormat::R32F) {
    AdaptationRun out;
    auto ws = loadHdrLighting();
    if (!ws) return out;
    replaceSceneWithPattern(*ws, "scene", uniformPattern(0.05));
    stopAfter(*ws, "adaptation");
    for (RenderTarget& t : ws->targets)
        if (t.name == "adapted") {
            t.format = format;
            t.initial = glm::vec4(float(initial), 0, 0, 0);
        }
    out.run = runWorkspace(std::move(ws), {{16, 16}, frames, dt});
    if (!out.run.exec) return out;
    out.adapted = readBack(*out.run.exec, "adapted").at(0, 0, 0);
    out.measured = readBack(*out.run.exec, "measured").at(0, 0, 0);
    return out;
}

// From 1.0 towards the measured ~0.05 at 10 frames per second: after 1 s the closed form
// current + (initial - current) 0.98^(30 t), after 30 s the measured luminance itself. Error: GLSL's
// pow is exp2(y log2 x) with log2 within 2^-21 near 1, so k = 1 - 0.98^(30 dt) is off by ~1e-6
// and (1 - k)^n by n·1e-6 relative of the remaining difference; each frame's float rounding adds
// an ulp or two of the value: 2e-5 of |initial - current| covers both.
TEST_F(HdrLightingGLTest, AdaptationConvergesToTheMeasuredLuminance) {
    const float dt = 0.1f;
    AdaptationRun early = adapt(10, dt, 1.0);
    ASSERT_TRUE(early.run.exec);
    EXPECT_NEAR(early.measured, 0.05 + hdr::kLogDelta, 1e-4) << "Lavg of a uniform image is Y + delta";
    double expected = hdr::adaptedAfter(1.0, early.measured, 10 * double(dt));
    EXPECT_NEAR(early.adapted, expected, 2e-5 * (1.0 - early.measured));
    EXPECT_GT(early.adapted, 2.0 * early.measured) << "after 1 s it is still on its way";

    AdaptationRun late = adapt(300, dt, 1.0);
    ASSERT_TRUE(late.run.exec);
    // 0.98^900 = 1.2e-8 of the initial difference is left; r32f resolves 0.05 to 4e-9.
    EXPECT_NEAR(late.adapted / late.measured, 1.0, 1e-5);
}

// 30 and 120 frames per second over the same 2 s agree with each other and with the closed form:
// (0.98^(30/30))^60 = (0.98^(30/120))^240. The tolerance (1e-4 of the initial difference) covers
// the pow error per frame (~1e-7 relative on k, times 240 frames) and per-frame rounding; a
// per-frame rate that ignored dt would differ by 0.98^60 - 0.98^240 = 0.29 of it.
TEST_F(HdrLightingGLTest, AdaptationIsIndependentOfTheFrameRate) {
    AdaptationRun at30 = adapt(60, 1.0f / 30.0f, 1.0);
    AdaptationRun at120 = adapt(240, 1.0f / 120.0f, 1.0);
    ASSERT_TRUE(at30.run.exec && at120.run.exec);
    double difference = 1.0 - at30.measured;
    double expected = hdr::adaptedAfter(1.0, at30.measured, 2.0);
    EXPECT_NEAR(at30.adapted, expected, 1e-4 * difference);
    EXPECT_NEAR(at120.adapted, expected, 1e-4 * difference);
    EXPECT_NEAR(at30.adapted, at120.adapted, 1e-4 * difference);
    EXPECT_GT(std::pow(0.98, 60) - std::pow(0.98, 240), 0.25) << "the check can tell the two rates apart";
}

// At 120 frames per second each step is 0.5% of the remaining difference. Approaching 0.05 from
// 0.04, r16f (steps of 2^-15 = 3.05e-5 there) stops once 0.5% of the difference is under half a
// step, about 6% short (round to nearest), or under a whole step, about 12% short (truncation,
// llvmpipe's rounding). r32f gets to 0.01 · 0.98^240 = 8e-5 of it after 8 s. This test would fail if
// the workspace's adapted target were r16f.
TEST_F(HdrLightingGLTest, AdaptationStallsInR16fAndConvergesInR32f) {
    AdaptationRun full = adapt(960, 1.0f / 120.0f, 0.04, TargetFormat::R32F);
    AdaptationRun half = adapt(960, 1.0f / 120.0f, 0.04, TargetFormat::R16F);
    ASSERT_TRUE(full.run.exec && half.run.exec);
    EXPECT_NEAR(full.adapted / full.measured, 1.0, 0.003);
    EXPECT_LT(half.adapted / half.measured, 0.98) << "r16f stalls short of the target";
    EXPECT_GT(half.adapted, 0.04) << "it did move";
    auto ws = loadHdrLighting();
    ASSERT_TRUE(ws);
    EXPECT_EQ(ws->findTarget("adapted")->format, TargetFormat::R32F) << "the workspace keeps the adapted luminance in r32f";
}

// ---------------------------------------------------------------- glare and final pass

// A dim gradient, a 4x4 block of 2000 aligned with a quarter texel, a grey single-pixel peak of
// 30000 and a patch of 3.
const char* kGlarePattern = R"(void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = vec3(0.02 + 0.002 * float(p.x), 0.03 + 0.001 * float(p.y), 0.05);
    if (p.x >= 40 && p.x < 44 && p.y >= 44 && p.y < 48) c = vec3(2000.0, 1500.0, 1000.0);
    if (p == ivec2(90, 21)) c = vec3(30000.0);
    if (p.x >= 100 && p.x < 110 && p.y >= 70 && p.y < 80) c = vec3(3.0, 2.0, 1.0);
    fragColor = vec4(c, 1.0);
}
)";

GlRun renderGlare(const Overrides& overrides, glm::ivec2 size = {128, 96}) {
    auto ws = loadHdrLighting(overrides);
    if (!ws) return {};
    replaceSceneWithPattern(*ws, "scene", kGlarePattern);
    return runWorkspace(std::move(ws), {size, 1, 1.0f / 60.0f});
}

double adaptedOf(const GlRun& run) { return readBack(*run.exec, "adapted").at(0, 0, 0); }

TEST_F(HdrLightingGLTest, BrightPassBloomAndStarSourcesMatchFloat64) {
    GlRun run = renderGlare({{"Light_Adaptation", "false"}, {"Middle_Gray", "0.3"}});
    ASSERT_TRUE(run.exec);
    double adapted = adaptedOf(run);
    RefImage quarter = targetImage(run, "quarter"), bright = targetImage(run, "bright");
    RefImage starSource = targetImage(run, "star_source"), bloomSource = targetImage(run, "bloom_source");
    RefImage bloomBlur = targetImage(run, "bloom_blur"), bloomH = targetImage(run, "bloom_h");
    RefImage bloom = targetImage(run, "bloom");

    EXPECT_LE(worstExcess(bright, hdr::brightPass(quarter, adapted, 0.3), kHalfTolerance, 1e-6), 0.0);
    EXPECT_GT(maxChannel(bright), 0.5) << "the bright block passes";
    EXPECT_LE(worstExcess(starSource, hdr::convolve(bright, hdr::gauss5x5Kernel()), kHalfTolerance, 1e-6), 0.0);
    EXPECT_LE(worstExcess(bloomSource, hdr::boxDownscale(starSource, 2), kHalfTolerance, 1e-6), 0.0);
    EXPECT_LE(worstExcess(bloomBlur, hdr::convolve(bloomSource, hdr::gauss5x5Kernel()), kHalfTolerance, 1e-6), 0.0);
    EXPECT_LE(worstExcess(bloomH, hdr::bloomPass(bloomBlur, true), kHalfTolerance, 1e-6), 0.0);
    EXPECT_LE(worstExcess(bloom, hdr::bloomPass(bloomH, false), kHalfTolerance, 1e-6), 0.0);
    EXPECT_GT(maxChannel(bloom), 1e-3);

    // Independent of the references: a normalised kernel moves energy, it does not make or lose
    // it (the bright texels are more than 2 texels from the quarter image's borders, so the 5x5
    // blur spills nothing; the 1/8 bloom image is too small for the same check).
    auto total = [](const RefImage& image) {
        double sum = 0.0;
        for (const glm::dvec4& t : image.texels) sum += t.r + t.g + t.b;
        return sum;
    };
    EXPECT_NEAR(total(starSource) / total(bright), 1.0, 2 * kHalfStep);
}

// The star source replaced by a single white texel: pass 0 of line 0 of the Vertical star (step one
// texel, straight down in the sample's terms, so the line grows upwards) gathers the texel into the
// 8 texels above it with exactly the 8 tap weights, and nothing anywhere else. Lines 1..7 are
// switched off so that the work targets keep line 0's passes 0 and 1; only the targets read here
// are asked for, as the star merge would read the lines switched off.
TEST_F(HdrLightingGLTest, StarLineResponseToASingleTexelIsItsTapWeights) {
    auto ws = loadHdrLighting({{"Star_Type", "3"}, {"Chromatic_Aberration", "1"}});
    ASSERT_TRUE(ws);
    replaceSceneWithPattern(*ws, "scene", uniformPattern(0.1));
    for (Pass& pass : ws->passes) {
        if (pass.name == "star_source") {
            pass.shaders = {ShaderSource{}};
            pass.shaders[0].stage = ShaderStage::Fragment;
            pass.shaders[0].code = "#version 450 core\nout vec4 fragColor;\nvoid main() { fragColor = "
                                   "ivec2(gl_FragCoord.xy) == ivec2(16, 12) ? vec4(1.0) : vec4(0.0, 0.0, 0.0, 1.0); }\n";
            pass.samplers.clear();
        }
        if (pass.name.starts_with("star") && pass.name.size() == 7 && pass.name[4] != '0') pass.enabled = false;
    }
    ExecutorOptions outputs;
    outputs.outputs = {"star_source", "star_work_a", "star_work_b", "star_line0"};
    GlRun run = runWorkspace(std::move(ws), {{128, 96}, 1, 1.0f / 60.0f}, outputs);
    ASSERT_TRUE(run.exec);
    RefImage source = targetImage(run, "star_source"), pass0 = targetImage(run, "star_work_a");
    RefImage pass1 = targetImage(run, "star_work_b"), line = targetImage(run, "star_line0");
    ASSERT_EQ(source.at(16, 12).r, 1.0);

    hdr::StarLine vertical = hdr::starLines(3)[0];
    std::array<hdr::StarTap, 8> taps = hdr::starTaps(vertical, 0, {32, 24}, 1.0);
    double outside = 0.0;
    for (int y = 0; y < pass0.height; ++y)
        for (int x = 0; x < pass0.width; ++x) {
            int i = y - 12;
            glm::dvec3 gl(pass0.at(x, y));
            if (x == 16 && i >= 0 && i < 8) {
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(gl[c], taps[size_t(i)].weight[c], kHalfTolerance * taps[size_t(i)].weight[c]) << "tap " << i;
            } else {
                outside = std::max({outside, gl.r, gl.g, gl.b});
            }
        }
    EXPECT_EQ(outside, 0.0);
    EXPECT_GT(taps[7].weight.r, 0.0) << "the eighth tap still carries light";
    EXPECT_LT(taps[7].weight.r, taps[0].weight.r) << "and is attenuated";

    // Passes 1 and 2 (steps of 8 and 64 texels, chromatic weights) against float64.
    EXPECT_LE(worstExcess(pass1, hdr::starLinePass(pass0, vertical, 1, 1.0), kHalfTolerance, 1e-7), 0.0);
    EXPECT_LE(worstExcess(line, hdr::starLinePass(pass1, vertical, 2, 1.0), kHalfTolerance, 1e-7), 0.0);
    glm::dvec3 tip(line.at(16, 12 + 9));
    EXPECT_NE(tip.r, tip.b) << "the chromatic table colours the line";
}

// Each star type: every line from the star source through its three passes in float64 (three half
// roundings of non-negative sums: 3 · 2^-10), lines beyond the type's count black, and the merge.
TEST_F(HdrLightingGLTest, StarTypesMatchFloat64) {
    for (int type : {0, 2, 4}) {
        SCOPED_TRACE("Star_Type " + std::to_string(type));
        GlRun run = renderGlare({{"Star_Type", std::to_string(type)}, {"Light_Adaptation", "false"}});
        ASSERT_TRUE(run.exec);
        RefImage source = targetImage(run, "star_source");
        std::vector<hdr::StarLine> lines = hdr::starLines(type);
        std::vector<RefImage> gpuLines;
        for (int d = 0; d < 8; ++d) {
            RefImage gl = targetImage(run, "star_line" + std::to_string(d));
            if (d >= int(lines.size())) {
                EXPECT_EQ(maxChannel(gl), 0.0) << "line " << d << " is not part of this star";
                continue;
            }
            RefImage ref = source;
            for (int p = 0; p < 3; ++p) ref = hdr::starLinePass(ref, lines[size_t(d)], p, 0.5);
            EXPECT_LE(worstExcess(gl, ref, 3 * kHalfTolerance, 1e-6), 0.0) << "line " << d;
            EXPECT_GT(maxChannel(gl), 0.02) << "line " << d;
            gpuLines.push_back(gl);
        }
        EXPECT_LE(worstExcess(targetImage(run, "star"), hdr::starMerge(gpuLines), kHalfTolerance, 1e-6), 0.0);
    }
}

struct FinalInputs {
    RefImage scene, bloom, star;
    double adapted = 0.0, peak = 0.0;
};

FinalInputs finalInputs(const GlRun& run) {
    FinalInputs in;
    in.scene = targetImage(run, "scene");
    in.bloom = targetImage(run, "bloom");
    in.star = targetImage(run, "star");
    in.adapted = adaptedOf(run);
    in.peak = readBack(*run.exec, "measured").at(0, 0, 1);
    return in;
}

// Both operators (and the photographic one with a fixed white point), with blue shift, star and
// bloom, per pixel against float64 from the final pass's inputs. Output rgba16f: one half step.
TEST_F(HdrLightingGLTest, FinalCompositionWithBothToneMapOperatorsMatchesFloat64) {
    struct Case {
        int op;
        double white;
        bool blueShift;
    };
    for (Case c : {Case{1, 0.0, true}, Case{2, 0.0, true}, Case{2, 3.0, false}, Case{0, 0.0, true}}) {
        SCOPED_TRACE("operator " + std::to_string(c.op) + " white " + std::to_string(c.white));
        GlRun run = renderGlare({{"Tone_Map_Operator", std::to_string(c.op)},
                                 {"White_Point", std::to_string(c.white)},
                                 {"Blue_Shift", c.blueShift ? "true" : "false"},
                                 {"Light_Adaptation", "false"}});
        ASSERT_TRUE(run.exec);
        FinalInputs in = finalInputs(run);
        hdr::FinalSettings settings;
        settings.toneMapOperator = c.op;
        settings.whitePoint = c.white;
        settings.blueShift = c.blueShift;
        RefImage ref = hdr::finalComposite(in.scene, in.bloom, in.star, in.adapted, in.peak, settings);
        RefImage gl = targetImage(run, "output");
        EXPECT_LE(worstExcess(gl, ref, kHalfTolerance, 1e-6), 0.0);
        EXPECT_GT(maxChannel(gl), 0.5);
        double coefficient = hdr::blueShiftCoefficient(in.adapted);
        EXPECT_GT(coefficient, 0.1) << "the scene is dim enough for blue shift to show";
        EXPECT_LT(coefficient, 0.9);
    }
}

// Independent of the reference: with Lwhite the image's largest scaled luminance, the photographic
// operator maps the brightest pixel (a grey 30000) to 1 and no pixel's luminance above it; the
// per-channel operator never exceeds 1.
TEST_F(HdrLightingGLTest, PhotographicOperatorMapsThePeakToWhite) {
    Overrides noGlare = {{"Bloom_Scale", "0"}, {"Star_Scale", "0"}, {"Blue_Shift", "false"}, {"Light_Adaptation", "false"}};
    Overrides photographic = noGlare, perChannel = noGlare;
    photographic.push_back({"Tone_Map_Operator", "2"});
    perChannel.push_back({"Tone_Map_Operator", "1"});
    GlRun run = renderGlare(photographic);
    ASSERT_TRUE(run.exec);
    // The peak travels as log(1 + Y / delta) and back: within 2e-5 (see the log-average tests).
    EXPECT_NEAR(readBack(*run.exec, "measured").at(0, 0, 1), 30000.0, 30000.0 * 2e-5) << "the single bright pixel";
    RefImage out = targetImage(run, "output");
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(out.at(90, 21)[c], 1.0, kHalfStep);
    double brightest = 0.0;
    for (const glm::dvec4& t : out.texels) brightest = std::max(brightest, hdr::luminance(glm::dvec3(t)));
    EXPECT_LT(brightest, 1.0 + kHalfStep) << "no luminance above the white point's";
    GlRun sample = renderGlare(perChannel);
    ASSERT_TRUE(sample.exec);
    EXPECT_LE(maxChannel(targetImage(sample, "output")), 1.0);
}

// ---------------------------------------------------------------- the workspace as shipped

// The real scene, several frames at a fixed step: at its default and at an odd size, every image
// finite, the lights far above 1, the adaptation settled on the measured luminance.
TEST_F(HdrLightingGLTest, SceneRendersOverManyFramesAtOddSizes) {
    for (glm::ivec2 size : {glm::ivec2(97, 61), glm::ivec2(128, 128)}) {
        SCOPED_TRACE(std::to_string(size.x) + "x" + std::to_string(size.y));
        GlRun run = runWorkspace(loadHdrLighting(), {size, 30, 0.5f});
        ASSERT_TRUE(run.exec);
        RefImage scene = targetImage(run, "scene"), output = targetImage(run, "output");
        EXPECT_GT(maxChannel(scene), 300.0) << "emissive lights far above 1";
        for (const glm::dvec4& t : output.texels)
            ASSERT_TRUE(std::isfinite(t.r) && std::isfinite(t.g) && std::isfinite(t.b));
        EXPECT_GT(maxChannel(output), 0.9);
        double measured = readBack(*run.exec, "measured").at(0, 0, 0);
        // 30 frames of 0.5 s: 0.98^450 = 1.1e-4 of the initial difference is left.
        EXPECT_NEAR(adaptedOf(run) / measured, 1.0, 2e-4 * std::fabs(1.0 - measured) / measured + 1e-5);
        EXPECT_GT(maxChannel(targetImage(run, "star")), 0.05) << "the lights make a star";
    }
}

}  // namespace
}  // namespace rmfx::test
