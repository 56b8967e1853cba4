// One run preparation: validation's programs become the compiled frame's, so a run reads,
// assembles and compiles each shader once and says each warning once; glslang's messages keep
// pass order though passes compile on several threads.

#include "compile/RunPreparation.h"

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

using test::lines;
using test::ScratchDir;

// Two passes with the same legacy shader, written for lenient drivers (GLSL 1.10 refuses `5 * PI`
// and `float quarter = 1`): assembling each warns that it is compiled with GLSL 1.20's rules.
std::string lenientWorkspace() {
    const std::string shader = R"(<shader stage="fragment" dialect="glsl110"><![CDATA[
const float PI = 3.14159265;
void main() { float quarter = 1; gl_FragColor = vec4(5 * PI / 100.0, quarter / 4.0, 0.0, 1.0); }
]]></shader>)";
    return lines({
        R"(<workspace version="1" name="lenient" profile="compatibility" size="8x4">)",  // 1
        R"(  <target name="first" format="rgba16f"/>)",                                     // 2
        R"(  <effect name="tint" passes="second"/>)",                                      // 3
        R"(  <pass name="first" target="first">)" + shader + "</pass>",                     // 4-7
        R"(  <pass name="second">)" + shader + "</pass>",                                   // 8-11
        R"(</workspace>)",
    });
}

std::string warningOf(const std::filesystem::path& file, int line, const std::string& pass) {
    return file.string() + ":" + std::to_string(line) + ": warning: <pass name=\"" + pass +
           "\">: fragment shader without #version: GLSL 1.10 rejects it (";
}

// The diagnostics of a whole preparation, one per line.
std::vector<std::string> formattedEach(const Diagnostics& all) {
    std::vector<std::string> out;
    for (const Diagnostic& d : all) {
        std::string text = formatAll({d});
        if (!text.empty() && text.back() == '\n') text.pop_back();
        out.push_back(text);
    }
    return out;
}

TEST(RunPreparation, TheFrameRunsValidationsProgramsAndEachWarningIsSaidOnce) {
    ScratchDir dir;
    RunRequest request;
    request.workspace = dir.write("lenient.xml", lenientWorkspace());
    Result<PreparedRun> run = prepareRun(request);
    ASSERT_TRUE(run.ok()) << formatAll(run.diagnostics());
    const std::vector<std::string> said = formattedEach(run.diagnostics());
    ASSERT_EQ(said.size(), 2u) << formatAll(run.diagnostics());
    const std::string first = warningOf(*request.workspace, 4, "first"), second = warningOf(*request.workspace, 8, "second");
    EXPECT_EQ(said[0].substr(0, first.size()), first);
    EXPECT_EQ(said[1].substr(0, second.size()), second);
    const CompiledFrame& frame = *run->frame;
    ASSERT_EQ(frame.programs.size(), 2u);
    for (const auto& [index, program] : frame.programs) {
        ASSERT_TRUE(program.ok());
        EXPECT_TRUE(program.diagnostics().empty()) << "pass " << index << ": " << formatAll(program.diagnostics());
        EXPECT_EQ(program->stages.at(1).shader.code.rfind("#version 120\n", 0), 0u) << program->stages.at(1).shader.code;
    }
    EXPECT_EQ(frame.viewport, glm::ivec2(8, 4));
}

TEST(RunPreparation, AnotherChoiceOfEffectsAssemblesAgainWithoutSayingItsWarningsAgain) {
    ScratchDir dir;
    RunRequest request;
    request.workspace = dir.write("lenient.xml", lenientWorkspace());
    request.plan.effects = std::vector<std::string>{};  // tint left out: its macro is false
    request.size = {6, 2};
    Result<PreparedRun> run = prepareRun(request);
    ASSERT_TRUE(run.ok()) << formatAll(run.diagnostics());
    EXPECT_EQ(run.diagnostics().size(), 2u) << formatAll(run.diagnostics());
    const CompiledFrame& frame = *run->frame;
    EXPECT_EQ(frame.viewport, glm::ivec2(6, 2));
    for (const auto& [index, program] : frame.programs) {
        ASSERT_TRUE(program.ok());
        EXPECT_TRUE(program.diagnostics().empty()) << "pass " << index << ": " << formatAll(program.diagnostics());
        EXPECT_NE(program->stages.at(1).shader.code.find("#define RMFX_EFFECT_tint false"), std::string::npos)
            << program->stages.at(1).shader.code;
    }
}

TEST(RunPreparation, CompileErrorsComeInPassOrderThoughPassesCompileAtOnce) {
    ScratchDir dir;
    std::string passes;
    for (int i = 0; i < 6; ++i)
        passes += "  <pass name=\"p" + std::to_string(i) + "\"><shader stage=\"fragment\"><![CDATA[out vec4 c;\nvoid main() { c = vec4(nope" +
                  std::to_string(i) + "); }\n]]></shader></pass>\n";
    RunRequest request;
    request.workspace = dir.write("broken.xml", "<workspace version=\"1\" name=\"broken\">\n" + passes + "</workspace>\n");
    Result<PreparedRun> run = prepareRun(request);
    ASSERT_FALSE(run.ok());
    std::vector<std::string> expected;
    for (int i = 0; i < 6; ++i) {
        const std::string at = request.workspace->string() + ":" + std::to_string(3 + 3 * i) + ": error: <pass name=\"p" +
                               std::to_string(i) + "\">: ";
        expected.push_back(at + "'nope" + std::to_string(i) + "' : undeclared identifier");
        expected.push_back(at + "'' : compilation terminated");
    }
    EXPECT_EQ(formattedEach(run.diagnostics()), expected);
}

TEST(RunPreparation, AnOverrideOfAnUndeclaredVariableStopsTheRunNamingIt) {
    ScratchDir dir;
    RunRequest request;
    request.workspace = dir.write("lenient.xml", lenientWorkspace());
    request.overrides = {{"Exposure", "2"}};
    Result<LoadedRun> loaded = loadRun(request);
    ASSERT_FALSE(loaded.ok());
    const std::vector<std::string> said = formattedEach(loaded.diagnostics());
    ASSERT_EQ(said.size(), 3u) << formatAll(loaded.diagnostics());
    EXPECT_EQ(said[2], (dir / "lenient.xml").string() + ": error: --set Exposure: the workspace has no variable 'Exposure' (it declares none)");
}

}  // namespace
}  // namespace rmfx
