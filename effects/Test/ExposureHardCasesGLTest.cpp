// Exposure 0 and 1e4 on every workspace with an exposure-like variable (Exposure_Level of the
// chapter's workspaces and auto_exposure, fExposureLevel of the article, the key Middle_Gray of
// hdr_lighting): every target read back is finite with non-negative colour, 8-bit targets hold
// 0..1, half-float ones at most 65504 (the scene passes clamp what they write there), and exposure
// 0 gives a black output, as the maths says for each of them.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class ExposureHardCasesGLTest : public GlTest {};

struct ExposureCase {
    std::string file;
    std::string variable;
    Overrides extra;
    int frames = 1;
};

std::vector<ExposureCase> exposureCases() {
    std::vector<ExposureCase> cases;
    // Both skies: the float one reaches 2000 (x 1e4 = 2e7, beyond half floats), the 8-bit one 65.
    for (std::string file : {"shader_1", "shader_2", "shader_3", "shader_4", "shader_5", "exercise_1"})
        for (std::string format : {"0", "1"}) cases.push_back({file + ".xml", "Exposure_Level", {{"Environment_Format", format}}});
    cases.push_back({"shader_6.xml", "Exposure_Level", {}});
    cases.push_back({"exercise_2.xml", "Exposure_Level", {}});
    cases.push_back({"auto_exposure.xml", "Exposure_Level", {{"Environment_Format", "1"}, {"Initial_Exposure", "16"}}, 3});
    cases.push_back({"article_pipeline.xml", "fExposureLevel", {}});
    for (std::string op : {"1", "2"})
        cases.push_back({"hdr_lighting.xml", "Middle_Gray", {{"Tone_Map_Operator", op}}, 3});
    return cases;
}

struct TargetCheck {
    int nonFinite = 0, negative = 0, aboveHalf = 0, outsideUnit = 0;
    double largest = 0.0;
};

// 65504 bounds what a half-float target can hold; a 32-bit float target may hold a little more
// (a luminance weighted 0.2126 + 0.7152 + 0.0722 of three 65504s rounds above it on an H200).
TargetCheck check(const Image& image, TargetFormat format) {
    bool eightBit = format == TargetFormat::RGBA8;
    bool half = format == TargetFormat::RGBA16F || format == TargetFormat::R16F || format == TargetFormat::RG16F ||
                format == TargetFormat::R11G11B10F;
    TargetCheck c;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int ch = 0; ch < image.channels; ++ch) {
                float v = image.at(x, y, ch);
                if (!std::isfinite(v)) {
                    ++c.nonFinite;
                    continue;
                }
                if (ch < 3 && v < 0.0f) ++c.negative;
                if (half && v > 65504.0f) ++c.aboveHalf;
                if (eightBit && (v < 0.0f || v > 1.0f)) ++c.outsideUnit;
                if (ch < 3) c.largest = std::max(c.largest, double(v));
            }
    return c;
}

// Each case renders its frames at exposure 0, then the same executor renders them again at 1e4
// (setVariable: no recompile), as a user dragging the slider would.
TEST_F(ExposureHardCasesGLTest, ExposureZeroAnd1e4GiveFiniteTargetsAndABlackOutputAtZero) {
    for (const ExposureCase& kase : exposureCases()) {
        std::string label = kase.file + " " + kase.variable;
        for (const auto& [name, v] : kase.extra) label += " " + name + "=" + v;
        SCOPED_TRACE(label);
        Overrides overrides = kase.extra;
        overrides.push_back({kase.variable, "0"});
        GlRun run = runWorkspace(effectWorkspace(kase.file, overrides), {{64, 64}, 0, 1.0f / 60.0f});
        ASSERT_TRUE(run.exec);
        for (float exposure : {0.0f, 1e4f}) {
            SCOPED_TRACE(kase.variable + "=" + std::to_string(exposure));
            ASSERT_EQ(run.exec->setVariable(kase.variable, Value::ofFloat(exposure)).error(), "");
            for (int i = 0; i < kase.frames; ++i) {
                Diagnostics d = run.exec->renderFrame({static_cast<float>(run.exec->frameIndex()) / 60.0f, 1.0f / 60.0f}).takeDiagnostics();
                ASSERT_TRUE(d.empty()) << formatAll(d);
            }
            std::vector<std::string> targets = {"output"};
            for (const RenderTarget& t : run.ws->targets) targets.push_back(t.name);
            double outputLargest = 0.0;
            for (const std::string& name : targets) {
                TargetCheck c = check(readBack(*run.exec, name), run.exec->targetFormat(name));
                EXPECT_EQ(c.nonFinite, 0) << name << ": NaN or Inf";
                EXPECT_EQ(c.negative, 0) << name << ": negative colour";
                EXPECT_EQ(c.aboveHalf, 0) << name << ": above the largest half float";
                EXPECT_EQ(c.outsideUnit, 0) << name << ": outside 0..1 in an 8-bit target";
                if (name == "output") outputLargest = c.largest;
            }
            if (exposure == 0.0f) {
                EXPECT_EQ(outputLargest, 0.0) << "exposure 0: a black output";
            } else {
                EXPECT_GT(outputLargest, 0.0) << "exposure 1e4: light reaches the output";
            }
        }
    }
}

// llvmpipe clamps float -> half writes to 65504 itself (other drivers write Inf), which would hide
// a pass that does not clamp: here the half-float targets those passes write are made rgba32f, so
// what the shader writes is seen as it is. At exposure 1e4 the sky (2000 x 1e4) must arrive as
// 65504 exactly: the scene passes (sky, teapot), the streak and ghost passes and auto_exposure's
// screen (65504 x its exposure) clamp what they write; so does the article's tone map, at 1e9.
TEST_F(ExposureHardCasesGLTest, PassesWritingHalfFloatTargetsClampAt65504) {
    struct Case {
        std::string file, variable;
        Overrides extra;
        std::string target;  // the half-float target the clamp protects ("output": the screen)
        std::string exposure = "1e4";
    };
    std::vector<Case> cases = {
        {"shader_1.xml", "Exposure_Level", {{"Environment_Format", "1"}}, "scene"},
        // The streak passes gain up to 3.77, the ghost passes 4 x Glow_Factor (masked: 0.93 of 4 at 64x64).
        {"shader_3.xml", "Exposure_Level", {{"Environment_Format", "1"}}, "streak_dl_4"},
        {"shader_4.xml", "Exposure_Level", {{"Environment_Format", "1"}, {"Glow_Factor", "2"}}, "ghost_1"},
        {"auto_exposure.xml", "Exposure_Level", {{"Environment_Format", "1"}, {"Initial_Exposure", "16"}}, "output"},
        // The article's output reaches only 6000 at 1e4 (2000^0.55 x 1e4^0.55): its clamp needs 1e9.
        {"article_pipeline.xml", "fExposureLevel", {}, "output", "1e9"},
    };
    for (const Case& kase : cases) {
        SCOPED_TRACE(kase.file);
        Overrides overrides = kase.extra;
        overrides.push_back({kase.variable, kase.exposure});
        auto ws = effectWorkspace(kase.file, overrides);
        ASSERT_TRUE(ws);
        ws->output.format = TargetFormat::RGBA32F;
        for (RenderTarget& t : ws->targets)
            if (t.name == "scene" || t.name == kase.target) t.format = TargetFormat::RGBA32F;
        GlRun run = runWorkspace(std::move(ws), {{64, 64}, 1, 1.0f / 60.0f});
        ASSERT_TRUE(run.exec);
        // Held to the half-float bound although it is rgba32f here: the shader's clamp is what is tested.
        TargetCheck c = check(readBack(*run.exec, kase.target), TargetFormat::RGBA16F);
        EXPECT_EQ(c.nonFinite, 0);
        EXPECT_EQ(c.aboveHalf, 0) << kase.target << " largest " << c.largest;
        EXPECT_EQ(c.largest, 65504.0) << "saturated at the clamp";
    }
}

// hdr_lighting's per-channel operator maps any key to c / (1 + c) < 1; with no star and bloom on
// top the output stays in 0..1 at Middle_Gray 1e4 and is exactly 0 at Middle_Gray 0.
TEST_F(ExposureHardCasesGLTest, HdrLightingPerChannelToneMapStaysInZeroToOneAtAnyKey) {
    for (const char* key : {"0", "1e4"}) {
        SCOPED_TRACE(std::string("Middle_Gray=") + key);
        GlRun run = runWorkspace(effectWorkspace("hdr_lighting.xml", {{"Middle_Gray", key},
                                                                      {"Tone_Map_Operator", "1"},
                                                                      {"Bloom_Scale", "0"},
                                                                      {"Star_Scale", "0"}}),
                                 {{64, 64}, 3, 1.0f / 60.0f});
        ASSERT_TRUE(run.exec);
        Image out = readBack(*run.exec, "output");
        double largest = 0.0;
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x)
                for (int c = 0; c < 3; ++c) {
                    float v = out.at(x, y, c);
                    ASSERT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f) << x << "," << y << ": " << v;
                    largest = std::max(largest, double(v));
                }
        if (std::string(key) == "0") EXPECT_EQ(largest, 0.0);
        else EXPECT_GT(largest, 0.99) << "the lights saturate";
    }
}

}  // namespace
}  // namespace rmfx::test
