// The finished plan without a GL context: every runnable pass assembled once, content skip's
// second programs only where leaving an effect out changes a pass's code, and `--explain` printed
// from the plan alone.

#include "compile/CompiledFrame.h"

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

using EffectsByPass = std::map<std::string, std::set<std::string>>;

std::shared_ptr<const Workspace> parse(const std::string& xml) {
    Result<Workspace> parsed = parseWorkspaceText(xml, "compiled.xml", ".");
    EXPECT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
    if (!parsed) return nullptr;
    return std::make_shared<const Workspace>(std::move(*parsed));
}

// bright (the source) → glow (the effect) → final, whose shader reads the glow only under
// if (RMFX_EFFECT_glow) when `finalReadsTheMacro`; otherwise the macro appears only in a comment.
std::string glowWorkspace(bool finalReadsTheMacro) {
    const std::string finalBody = finalReadsTheMacro
                                      ? "    if (RMFX_EFFECT_glow) c += texelFetch(Glow, p, 0);\n"
                                      : "    // RMFX_EFFECT_glow is not read: the glow is always added\n    c += texelFetch(Glow, p, 0);\n";
    return R"(<workspace version="1" name="glow" size="8x4">
  <target name="bright" format="rgba16f"/>
  <target name="glow" format="rgba16f"/>
  <effect name="glow" passes="glow_pass" source="bright"/>
  <pass name="bright_pass" target="bright"><shader stage="fragment"><![CDATA[
out vec4 c;
void main() { c = vec4(gl_FragCoord.x > 4.0 ? 2.0 : 0.0); }
]]></shader></pass>
  <pass name="glow_pass" target="glow"><sampler name="Bright" target="bright" filter="nearest"/><shader stage="fragment"><![CDATA[
uniform sampler2D Bright;
out vec4 c;
void main() { c = texelFetch(Bright, ivec2(gl_FragCoord.xy), 0) * 0.5; }
]]></shader></pass>
  <pass name="final"><sampler name="Bright" target="bright" filter="nearest"/><sampler name="Glow" target="glow" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
uniform sampler2D Bright;
uniform sampler2D Glow;
out vec4 c;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    c = texelFetch(Bright, p, 0);
)" + finalBody + R"(}
]]></shader></pass>
  <output format="rgba16f" transform="none"/>
</workspace>
)";
}

FramePlanOptions outputOnly() {
    FramePlanOptions options;
    options.outputs = {"output"};
    return options;
}

TEST(CompiledFrame, APassWhoseCodeReadsTheEffectGetsASecondProgramWithoutIt) {
    auto ws = parse(glowWorkspace(true));
    ASSERT_TRUE(ws);
    auto frame = compileFrame(ws, outputOnly(), {8, 4});
    ASSERT_TRUE(frame) << formatAll(frame.diagnostics());
    const CompiledFrame& f = **frame;
    EXPECT_EQ(f.programs.size(), 3u);
    for (const auto& [index, program] : f.programs) EXPECT_TRUE(program.ok()) << index << ": " << formatAll(program.diagnostics());
    EXPECT_EQ(f.passesDrawnWithoutSkippedEffects({}), (EffectsByPass{{"final", {"glow"}}}));
    const ProgramWithoutEffects* without = f.programWithout({}, 2);
    ASSERT_TRUE(without);
    EXPECT_EQ(without->effects, (std::set<std::string>{"glow"}));
    ASSERT_EQ(without->source.stages.size(), 2u);
    const std::string& code = without->source.stages[1].shader.code;
    EXPECT_NE(code.find("RMFX_EFFECT_glow false"), std::string::npos) << code;
    EXPECT_EQ(f.programWithout({}, 1), nullptr) << "the effect's own pass is skipped, not drawn a second way";
}

TEST(CompiledFrame, AMacroNamedOnlyInACommentIsNotRead) {
    auto ws = parse(glowWorkspace(false));
    ASSERT_TRUE(ws);
    auto frame = compileFrame(ws, outputOnly(), {8, 4});
    ASSERT_TRUE(frame) << formatAll(frame.diagnostics());
    EXPECT_TRUE((*frame)->passesDrawnWithoutSkippedEffects({}).empty());
    EXPECT_EQ((*frame)->programWithout({}, 2), nullptr);
}

TEST(CompiledFrame, TheHealthCheckDrawsEveryPassAsCompiled) {
    auto ws = parse(glowWorkspace(true));
    ASSERT_TRUE(ws);
    FramePlanOptions options = outputOnly();
    options.checkHealth = true;
    auto frame = compileFrame(ws, options, {8, 4});
    ASSERT_TRUE(frame) << formatAll(frame.diagnostics());
    EXPECT_TRUE((*frame)->withoutEffects.empty());
}

TEST(CompiledFrame, LimitsAndAnEmptyViewportFailBeforeAnyShaderIsRead) {
    auto ws = parse(glowWorkspace(true));
    ASSERT_TRUE(ws);
    auto empty = compileFrame(ws, outputOnly(), {0, 4});
    ASSERT_FALSE(empty);
    EXPECT_EQ(formatAll(empty.diagnostics()), "compiled.xml: error: viewport size 0x4 is empty\n");
    auto tooLarge = compileFrame(ws, outputOnly(), {64, 4}, 32);
    ASSERT_FALSE(tooLarge);
    EXPECT_NE(formatAll(tooLarge.diagnostics()).find("64x4"), std::string::npos) << formatAll(tooLarge.diagnostics());
}

TEST(CompiledFrame, ExplainPrintsThePlanWithoutAFrame) {
    auto ws = parse(glowWorkspace(true));
    ASSERT_TRUE(ws);
    auto frame = compileFrame(ws, outputOnly(), {8, 4});
    ASSERT_TRUE(frame) << formatAll(frame.diagnostics());
    const std::string explained = explainFrame(explanationOf(**frame, {}));
    EXPECT_EQ(explained,
              "glow: outputs 'output'; effects asked for: glow (declared: glow); switched off: none\n"
              "\n"
              "passes: 3 of 3 run\n"
              "  # pass        writes effect status why\n"
              "  1 bright_pass bright -      run    'final' reads 'bright'\n"
              "  2 glow_pass   glow   glow   run    'final' reads 'glow'\n"
              "  3 final       output -      run    writes 'output', which is asked for\n"
              "\n"
              "targets: 3 of 3 allocated, in 3 textures\n"
              "  target size format  bytes lifetime              memory\n"
              "  bright 8x4  rgba16f 256 B bright_pass .. final  #0\n"
              "  glow   8x4  rgba16f 256 B glow_pass .. final    #1\n"
              "  output 8x4  rgba16f 256 B final .. end of frame #2\n"
              "\n"
              "peak GPU memory of the frame: 768 B (768 bytes) of 768 B (768 bytes) for all declared targets: 100%\n"
              "\n"
              "skipped by content (decided on the GPU each frame; no frame ran):\n"
              "  glow: skipped where 'bright' holds no pixel it works on\n"
              "  final: drawn compiled without glow where it is skipped (it reads what it hands on)\n");
}

// hdr_lighting.xml as `rmfx render --explain` plans it: bloom and star decided by the glare gate,
// the bright pass and star source drawn only for them, the final pass compiled without both.
TEST(CompiledFrame, HdrLightingsPlanNamesItsFeedersAndTheFinalPassWithoutTheGlare) {
    Result<Workspace> parsed = parseWorkspaceFile(test::sourceDir() / "effects" / "hdr_lighting.xml");
    ASSERT_TRUE(parsed) << formatAll(parsed.diagnostics());
    auto frame = compileFrame(std::make_shared<const Workspace>(std::move(*parsed)), outputOnly(), {64, 48});
    ASSERT_TRUE(frame) << formatAll(frame.diagnostics());
    const CompiledFrame& f = **frame;
    EXPECT_EQ(f.passesDrawnOnlyForEffects({}), (EffectsByPass{{"bright_pass", {"bloom", "star"}}, {"star_source", {"bloom", "star"}}}));
    EXPECT_EQ(f.passesDrawnWithoutSkippedEffects({}), (EffectsByPass{{"final", {"bloom", "star"}}}));
    EXPECT_EQ(f.passesDrawnWithoutSkippedEffects({"star"}), (EffectsByPass{{"final", {"bloom"}}}));
    const std::string explained = explainFrame(explanationOf(f, {}));
    for (const char* line : {"  bloom: skipped where its gate 'glare_gate' holds no non-zero pixel\n",
                             "  star: skipped where its gate 'glare_gate' holds no non-zero pixel\n",
                             "  bright_pass: drawn only where bloom, star run (only they read what it writes)\n",
                             "  final: drawn compiled without bloom, star where they are skipped (it reads what they hand on)\n"})
        EXPECT_NE(explained.find(line), std::string::npos) << line << "\nin:\n" << explained;
}

}  // namespace
}  // namespace rmfx
