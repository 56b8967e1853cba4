// The test .rfx files (tests/rfx/, written for these tests) imported through loadWorkspace and
// rendered headless, end to end: importer, media resolution, contexts, dialects, streams, states
// and HLSL. Each expectation is the effect's maths worked out here from the values in the file.

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>
#include <gtest/gtest.h>

#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

constexpr int kSize = 16;

std::unique_ptr<Workspace> loadRfx(const std::string& name, GlProfile expectedProfile) {
    Result<Workspace> loaded = loadWorkspace(sourceDir() / "tests" / "rfx" / name);
    if (!loaded.ok()) {
        ADD_FAILURE() << formatAll(loaded.diagnostics());
        return nullptr;
    }
    EXPECT_EQ(loaded->profile, expectedProfile) << name;
    return std::make_unique<Workspace>(std::move(*loaded));
}

constexpr double kOutputRounding = 0.5 / 255.0;

// Every pixel of the output equals `expected` (rgb) with alpha 1, within `tolerance` (by default
// the 8-bit output's rounding); the top row may instead hold `topRowTie` (rgb), where a pass
// samples exactly on the edge of its texture (see Direct3DHlslPassesRunThroughGlslang).
void expectUniformOutput(const GlRun& run, std::array<double, 3> expected, double tolerance = kOutputRounding,
                         std::optional<std::array<double, 3>> topRowTie = std::nullopt) {
    ASSERT_TRUE(run.exec);
    Image image = readBack(*run.exec, run.ws->outputTargetName());
    ASSERT_EQ(image.width, kSize);
    ASSERT_EQ(image.height, kSize);
    double worst = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (y == 0 && topRowTie) {
                double tie = 0.0;
                for (int c = 0; c < 3; ++c) tie = std::max(tie, std::abs(image.at(x, y, c) - (*topRowTie)[c]));
                if (tie <= tolerance + 1e-6) continue;
            }
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(image.at(x, y, c) - expected[c]));
            worst = std::max(worst, std::abs(image.at(x, y, 3) - 1.0));
        }
    expectWithin("max abs error against the effect's maths", worst, tolerance + 1e-6);
}

class RfxLegacyRenderGLTest : public CompatibilityGlTest {};
class RfxCoreRenderGLTest : public GlTest {};

TEST_F(RfxLegacyRenderGLTest, TwoLegacyPassesInPassIndexOrderThroughARenderableTexture) {
    auto ws = loadRfx("gl_legacy.rfx", GlProfile::Compatibility);
    ASSERT_TRUE(ws);
    // Pass "Tint" (PASS_INDEX 0): Tint.rgb × Scale, with the group's Scale (0.5) shadowing the
    // workspace's (0.75). Pass "Show" (PASS_INDEX 1): Scene × 2 + Offset.xyz.
    const std::array<double, 3> tint{0.2, 0.4, 0.6}, offset{0.25, 0.125, 0.0};
    const double scale = 0.5;
    std::array<double, 3> expected{};
    for (int c = 0; c < 3; ++c) expected[c] = tint[c] * scale * 2.0 + offset[c];
    expectUniformOutput(runWorkspace(std::move(ws), RunSettings{{kSize, kSize}}), expected);
}

TEST_F(RfxLegacyRenderGLTest, RenderStatesCarryOverToThePassesAfterThem) {
    auto ws = loadRfx("shells.rfx", GlProfile::Compatibility);
    ASSERT_TRUE(ws);
    // "Base" writes Base; "Shell 1" adds Layer with the ONE, ONE blending of its block; the
    // disabled "Reset" changes nothing; "Shell 2" and "Shell 3" add Layer with Shell 1's state.
    const std::array<double, 3> base{0.1, 0.2, 0.3}, layer{0.2, 0.1, 0.05};
    std::array<double, 3> expected{};
    for (int c = 0; c < 3; ++c) expected[c] = std::min(1.0, base[c] + 3.0 * layer[c]);
    // Each of the four passes leaves its result in the 8-bit output, rounded by up to half a step.
    expectUniformOutput(runWorkspace(std::move(ws), RunSettings{{kSize, kSize}}), expected, 4 * kOutputRounding);
}

TEST_F(RfxCoreRenderGLTest, GlslEsPassWithStreamedAttributesBlendsOntoItsClearColour) {
    auto ws = loadRfx("gles.rfx", GlProfile::Core);
    ASSERT_TRUE(ws);
    // Base × Gain added (ONE, ONE) onto the clear colour 0xFF202020 (0x20 / 255 per channel).
    const std::array<double, 3> base{0.5, 0.25, 1.0};
    const double gain = 0.5, clear = 0x20 / 255.0;
    std::array<double, 3> expected{};
    for (int c = 0; c < 3; ++c) expected[c] = std::min(1.0, base[c] * gain + clear);
    expectUniformOutput(runWorkspace(std::move(ws), RunSettings{{kSize, kSize}}), expected);
}

TEST_F(RfxCoreRenderGLTest, Direct3DHlslPassesRunThroughGlslang) {
    auto ws = loadRfx("d3d_hlsl.rfx", GlProfile::Core);
    ASSERT_TRUE(ws);
    // Pass "Fill": Color.rgb × Gain into a float texture; pass "Double" samples it × 2.
    const std::array<double, 3> color{0.8, 0.4, 0.2};
    const double gain = 0.5;
    std::array<double, 3> expected{};
    for (int c = 0; c < 3; ++c) expected[c] = color[c] * gain * 2.0;
    // Direct3D 9 shades the top row at v = 1 exactly (quad.obj's v runs up from 0 at its bottom
    // edge; D3D9's pixel centres lie on whole numbers), on the far edge of Buffer: point sampling
    // with BORDER addressing there reads its last row or, rounded the other way, the border colour
    // (red), × 2 and held at 1 by the 8-bit output; float interpolation may round either way.
    expectUniformOutput(runWorkspace(std::move(ws), RunSettings{{kSize, kSize}}), expected, kOutputRounding,
                        std::array<double, 3>{1.0, 0.0, 0.0});
}

// Direct3D binds textures by sampler stage and keeps them from pass to pass: "Show" reads, through
// samplers named after no texture object, the target "Bind" left at stage 0 (not the one the
// disabled "Off" would have bound) and the one its own object "Other" binds at stage 1.
TEST_F(RfxCoreRenderGLTest, Direct3DSamplersReadWhatTheirStageHolds) {
    auto ws = loadRfx("d3d_sampler_stages.rfx", GlProfile::Core);
    ASSERT_TRUE(ws);
    // The colours pass through 8-bit targets (D3DFMT_A8R8G8B8) before they are read.
    const auto stored = [](double v) { return std::round(v * 255.0) / 255.0; };
    const std::array<double, 3> a{0.2, 0.4, 0.6}, c{0.3, 0.7, 0.5};
    expectUniformOutput(runWorkspace(std::move(ws), RunSettings{{kSize, kSize}}), {stored(a[0]), stored(a[1]), stored(c[2])});
}

// d3d_color_clamp.rfx: a vs_2_0 shader's COLOR0 output is clamped to 0…1 (Direct3D 9's colour
// register), its TEXCOORD0 output is not; with vs_3_0 (the same file, targets changed) neither is.
TEST_F(RfxCoreRenderGLTest, ColourOutputsBelowShaderModel3AreClampedAsDirect3DsColourRegisters) {
    const std::array<double, 4> value{-0.6, 1.4, 0.25, 1.0};
    const auto shown = [&](bool clamped) {
        std::array<double, 3> out{};
        for (int c = 0; c < 3; ++c) {
            const double colour = clamped ? std::clamp(value[c], 0.0, 1.0) : value[c];
            out[c] = 0.25 * (colour - value[c]) + 0.5;
        }
        return out;
    };
    expectUniformOutput(runWorkspace(loadRfx("d3d_color_clamp.rfx", GlProfile::Core), RunSettings{{kSize, kSize}}), shown(true));

    std::string text = readText(sourceDir() / "tests" / "rfx" / "d3d_color_clamp.rfx");
    for (const std::string from : {"TARGET=\"vs_2_0\"", "TARGET=\"ps_2_0\""}) {
        ASSERT_NE(text.find(from), std::string::npos) << from;
        text.replace(text.find(from) + 11, 3, "3_0");
    }
    ScratchDir dir;
    Result<Workspace> model3 = loadWorkspace(dir.write("clamp3.rfx", text));
    ASSERT_TRUE(model3.ok()) << formatAll(model3.diagnostics());
    expectUniformOutput(runWorkspace(std::make_unique<Workspace>(std::move(*model3)), RunSettings{{kSize, kSize}}), shown(false));
}

// d3d_pow.rfx: Direct3D 9's pow raises the absolute value of its base; GLSL's is undefined below 0.
TEST_F(RfxCoreRenderGLTest, PowRaisesTheAbsoluteValueOfItsBaseAsDirect3D9s) {
    const std::array<double, 3> base{-0.5, 0.5, -0.25};
    std::array<double, 3> expected{};
    for (int c = 0; c < 3; ++c) expected[c] = std::pow(std::abs(base[c]), 3.0);
    expectUniformOutput(runWorkspace(loadRfx("d3d_pow.rfx", GlProfile::Core), RunSettings{{kSize, kSize}}), expected);

    // 0^0 is 1 in Direct3D 9 (undefined in GLSL, NaN on Mesa); any other base to the 0th too.
    std::string text = readText(sourceDir() / "tests" / "rfx" / "d3d_pow.rfx");
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"VALUE_0=\"-0.5\"", "VALUE_0=\"0.0\""},
                                   {"VALUE=\"3.0\"", "VALUE=\"0.0\""}}) {
        ASSERT_NE(text.find(from), std::string::npos) << from;
        text.replace(text.find(from), from.size(), to);
    }
    ScratchDir dir;
    Result<Workspace> zeroth = loadWorkspace(dir.write("pow0.rfx", text));
    ASSERT_TRUE(zeroth.ok()) << formatAll(zeroth.diagnostics());
    expectUniformOutput(runWorkspace(std::make_unique<Workspace>(std::move(*zeroth)), RunSettings{{kSize, kSize}}), {1.0, 1.0, 1.0});
}

// d3d_stored_matrix.rfx: a matrix RenderMonkey keeps as its editor shows it (translation in
// VALUE_3 and VALUE_7) translates the point under mul(v, M) in a 1.71 file and under mul(M, v) in
// a 1.5 one (the same file, its version and multiplication turned round).
TEST_F(RfxCoreRenderGLTest, AStoredMatrixTranslatesUnderEitherMultiplicationOrder) {
    const glm::dvec4 point(0.25, 0.5, 0.0, 1.0), translation(0.25, 0.125, 0.0, 0.0);
    const glm::dvec4 moved = point + translation * point.w;
    const auto stored = [](double v) { return std::round(v * 255.0) / 255.0; };  // the 8-bit output
    const std::array<double, 3> expected{stored(moved.x), stored(moved.y), stored(moved.z)};
    expectUniformOutput(runWorkspace(loadRfx("d3d_stored_matrix.rfx", GlProfile::Core), RunSettings{{kSize, kSize}}), expected);

    std::string text = readText(sourceDir() / "tests" / "rfx" / "d3d_stored_matrix.rfx");
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"XML_VERSION=\"RenderMonkey 1.71\"", "XML_VERSION=\"RenderMonkey 1.5\""},
                                   {"mul(float4(0.25, 0.5, 0.0, 1.0), Offset)", "mul(Offset, float4(0.25, 0.5, 0.0, 1.0))"}}) {
        ASSERT_NE(text.find(from), std::string::npos) << from;
        text.replace(text.find(from), from.size(), to);
    }
    ScratchDir dir;
    Result<Workspace> older = loadWorkspace(dir.write("stored15.rfx", text));
    ASSERT_TRUE(older.ok()) << formatAll(older.diagnostics());
    expectUniformOutput(runWorkspace(std::make_unique<Workspace>(std::move(*older)), RunSettings{{kSize, kSize}}), expected);
}

// A 1.71 file whose HLSL multiplies mul(g_matViewProj, v) (written for OpenGL-layout matrices, as
// gaxlin's LensFlare_10): imported on its own it renders bit for bit as with --rfx-matrices
// column-vector, and the billboard lands elsewhere with the order its version implies.
TEST_F(RfxCoreRenderGLTest, TheMatrixOrderTheCodeMultipliesIsTheOrderItRendersWith) {
    auto render = [](std::optional<HlslMatrixOrder> asked) {
        WorkspaceLoadOptions load;
        load.rfxMatrices = asked;
        Result<Workspace> loaded = loadWorkspace(sourceDir() / "tests" / "rfx" / "d3d_matrix_order.rfx", {}, load);
        EXPECT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
        if (!loaded.ok()) return Image{};
        GlRun run = runWorkspace(std::make_unique<Workspace>(std::move(*loaded)), RunSettings{{64, 64}});
        return run.exec ? readBack(*run.exec, run.ws->outputTargetName()) : Image{};
    };
    const Image fromCode = render(std::nullopt);
    const Image columnVector = render(HlslMatrixOrder::ColumnVector);
    const Image rowVector = render(HlslMatrixOrder::RowVector);
    ASSERT_EQ(fromCode.width, 64);
    ASSERT_EQ(columnVector.width, 64);
    ASSERT_EQ(rowVector.width, 64);
    int lit = 0, differing = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            for (int c = 0; c < 4; ++c) EXPECT_EQ(fromCode.at(x, y, c), columnVector.at(x, y, c)) << x << "," << y << " channel " << c;
            lit += fromCode.at(x, y, 2) > 0.5 ? 1 : 0;
            differing += std::abs(fromCode.at(x, y, 2) - rowVector.at(x, y, 2)) > 0.5 ? 1 : 0;
        }
    EXPECT_GT(lit, 64) << "the billboard is on screen";
    EXPECT_LT(lit, 64 * 64 / 2) << "and does not fill it";
    EXPECT_GT(differing, lit / 4) << "the other order puts it elsewhere";
}

// RenderMonkey 1.0's form: the code in CODE attributes, the constants in DECLARATION_BLOCK, the
// active effect named alone (the first effect, "Decoy", would write red).
TEST_F(RfxCoreRenderGLTest, RenderMonkey10CodeAttributesAndItsActiveEffectRun) {
    auto ws = loadRfx("rm10_attribute_code.rfx", GlProfile::Core);
    ASSERT_TRUE(ws);
    expectUniformOutput(runWorkspace(std::move(ws), RunSettings{{kSize, kSize}}), {0.4, 0.2, 0.1});
}

TEST_F(RfxCoreRenderGLTest, Direct3DStreamsInitialValuesAndCbuffersReachTheShaders) {
    auto ws = loadRfx("d3d_streams.rfx", GlProfile::Core);
    ASSERT_TRUE(ws);
    GlRun run = runWorkspace(std::move(ws), RunSettings{{kSize, kSize}});
    ASSERT_TRUE(run.exec);
    Image image = readBack(*run.exec, run.ws->outputTargetName());
    ASSERT_EQ(image.width, kSize);
    // |tangent| (1, 0, 0) × Scale (the variable's 0.25, not the HLSL 2.0) × 0.5, plus Bias (its
    // HLSL initial value: no constant binds it) and Offset (a cbuffer member) (0.5, 0.125, 0);
    // TEXCOORD1 (the quad's coordinates, 0…1 across the screen): v/2 into blue, u into alpha.
    // Direct3D 9 shades pixel (x, y) (y from the bottom) at whole-number window coordinates:
    // x from the left edge and kSize − 1 − y from the top, so u = x / kSize, v = (y + 1) / kSize.
    double worst = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double u = double(x) / kSize, v = (y + 1.0) / kSize;
            const double expected[4] = {0.25 * 0.5 + 0.125 + 0.5, 0.25 + 0.125, 0.5 * v, u};
            for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(atGl(image, x, y, c) - expected[c]));
        }
    expectWithin("max abs error against the effect's maths", worst, kOutputRounding + 1e-6);
}

}  // namespace
}  // namespace rmfx::test

namespace rmfx::test {
namespace {

// A legacy pass drawing to TARGET (empty: the screen) whose fragment shader is `body`, reading
// the renderable textures `reads` through samplers of their names.
std::string feedbackPass(const std::string& name, int index, const std::string& target, const std::vector<std::string>& reads,
                         const std::string& body) {
    std::string uniforms, objects;
    for (const std::string& r : reads) {
        uniforms += "uniform sampler2D " + r + ";\n";
        objects += "<RmTextureObject NAME=\"" + r + "\" API=\"OpenGL\" STATE_INDEX=\"0\"><RmTextureReference NAME=\"" + r +
                   "\" API=\"\"/></RmTextureObject>\n<RmSampler NAME=\"" + r + "\" API=\"\" REGISTER=\"-1\"/>\n";
    }
    return "<RmGLPass NAME=\"" + name + "\" API=\"OpenGL\" PASS_INDEX=\"" + std::to_string(index) + "\" ENABLED=\"TRUE\">\n" +
           "<RmRenderTarget NAME=\"" + (target.empty() ? "Screen" : target) + "\" API=\"\" INDEX=\"0\" RENDER_TO_SCREEN=\"" +
           (target.empty() ? "TRUE" : "FALSE") +
           "\" COLOR_CLEAR=\"FALSE\" DEPTH_CLEAR=\"FALSE\" CLEAR_COLOR_VALUE=\"0\" DEPTH_CLEAR_VALUE=\"1.0\"/>\n" +
           "<RmGLShader NAME=\"F\" API=\"OpenGL\" PIXEL_SHADER=\"TRUE\"><RmShaderCode TYPE=\"TEXT\"><![CDATA[" + uniforms +
           "void main(void) { " + body + " }]]></RmShaderCode></RmGLShader>\n" + objects + "</RmGLPass>\n";
}

class RfxFeedbackRenderGLTest : public CompatibilityGlTest {};

// RenderMonkey's feedback pattern: "Combine" reads Sum, which only the later "Copy back" writes,
// so it reads what the last frame left there; Sum grows by 0.25 a frame. rmfx reads such a
// target as frame="previous" (it would otherwise be a cycle between the two passes).
TEST_F(RfxFeedbackRenderGLTest, APassReadingATargetOnlyALaterPassWritesReadsTheLastFrames) {
    auto target = [](const std::string& name) {
        return "<RmRenderableTexture NAME=\"" + name + "\" API=\"\" FILE_NAME=\"\" WIDTH=\"4\" HEIGHT=\"4\" FORMAT=\"116\" "
               "USE_VIEWPORT_DIMENSIONS=\"FALSE\" GENERATE_MIPMAPS=\"FALSE\"/>\n";
    };
    const std::string rfx = "<RENDER_MONKEY>\n<RmEffectWorkspace NAME=\"W\" ACTIVE_EFFECT=\"W.E\">\n"
                            "<RmOpenGLEffect NAME=\"E\" API=\"OpenGL\">\n" +
                            target("Sum") + target("Temp") +
                            feedbackPass("Combine", 0, "Temp", {"Sum"}, "gl_FragColor = texture2D(Sum, vec2(0.5)) + vec4(0.25);") +
                            feedbackPass("Copy back", 1, "Sum", {"Temp"}, "gl_FragColor = texture2D(Temp, vec2(0.5));") +
                            feedbackPass("Show", 2, "", {"Temp"}, "gl_FragColor = vec4(texture2D(Temp, vec2(0.5)).rgb * 0.25, 1.0);") +
                            "</RmOpenGLEffect>\n</RmEffectWorkspace>\n</RENDER_MONKEY>\n";
    ScratchDir dir;
    Result<Workspace> imported = loadWorkspace(dir.write("feedback.rfx", rfx));
    ASSERT_TRUE(imported.ok()) << formatAll(imported.diagnostics());
    ASSERT_EQ(imported->passes.size(), 3u);
    EXPECT_TRUE(imported->passes[0].samplers.at(0).previousFrame);   // Sum: written later
    EXPECT_FALSE(imported->passes[1].samplers.at(0).previousFrame);  // Temp: written this frame
    EXPECT_FALSE(imported->passes[2].samplers.at(0).previousFrame);
    for (int frames : {1, 3}) {
        GlRun run = runWorkspace(std::make_unique<Workspace>(*imported), RunSettings{{kSize, kSize}, frames});
        ASSERT_TRUE(run.exec);
        // Temp after n frames: 0.25 n (Sum starts at 0); the output shows a quarter of it.
        expectUniformOutput(run, {0.0625 * frames, 0.0625 * frames, 0.0625 * frames});
    }
}

}  // namespace
}  // namespace rmfx::test
