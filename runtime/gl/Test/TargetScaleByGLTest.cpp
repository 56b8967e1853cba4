// scale-by: an int variable picks a target's size from a list of viewport fractions, at creation
// and again, with new memory, when setVariable changes it.
#include <gtest/gtest.h>

#include "gl/GlExecutor.h"
#include "run/HeadlessRun.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class TargetScaleByGLTest : public GlTest {};

// A reduced copy of a gradient and the full-size output that reads it back bilinearly: the
// reduced target's size follows Downsample.
std::string scaleByWorkspace(int downsample) {
    return R"(<workspace version="1">
  <int name="Downsample" value=")" + std::to_string(downsample) + R"(" options="1/2, 1/4, 1/8"/>
  <target name="reduced" format="rgba32f" scale="1/2 1/4 1/8" scale-by="Downsample"/>
  <pass name="fill" target="reduced">
    <shader stage="fragment">
      in vec2 vTexCoord;
      out vec4 color;
      void main() { color = vec4(gl_FragCoord.xy, 0.0, 1.0); }
    </shader>
  </pass>
  <pass name="show">
    <sampler name="Reduced" target="reduced" filter="nearest"/>
    <shader stage="fragment">
      uniform sampler2D Reduced;
      in vec2 vTexCoord;
      out vec4 color;
      void main() { color = texture(Reduced, vTexCoord); }
    </shader>
  </pass>
</workspace>)";
}

TEST_F(TargetScaleByGLTest, TheVariablePicksTheSizeAndSettingItReallocates) {
    GlRun run = runWorkspace(workspaceFromText(scaleByWorkspace(1)), {{40, 27}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec) << formatAll(run.diagnostics);
    EXPECT_EQ(run.exec->targetSize("reduced"), glm::ivec2(10, 7));  // ceil(27 / 4) = 7

    for (auto [value, size] : {std::pair{2, glm::ivec2(5, 4)}, std::pair{0, glm::ivec2(20, 14)}}) {
        ASSERT_EQ(run.exec->setVariable("Downsample", Value::ofInt(value)).error(), "");
        Diagnostics d = run.exec->renderFrame({}).takeDiagnostics();
        ASSERT_TRUE(d.empty()) << formatAll(d);
        EXPECT_EQ(run.exec->targetSize("reduced"), size);
        const TargetPlan& plan = run.exec->targetPlan();
        EXPECT_EQ(plan.targets[static_cast<size_t>(plan.find("reduced"))].bytes, static_cast<size_t>(size.x * size.y) * 16u);
        // Every texel of the new size was written: its last texel holds its own centre.
        Image reduced = readBack(*run.exec, "reduced");
        ASSERT_EQ(reduced.width, size.x);
        EXPECT_EQ(reduced.at(size.x - 1, 0, 0), size.x - 0.5f);
    }
    EXPECT_EQ(run.exec->setVariable("Downsample", Value::ofInt(3)).error(),
              "variable 'Downsample' = 3 picks none of the 3 scales of target 'reduced'");
    EXPECT_EQ(run.exec->variable("Downsample")->asInt(), 0);  // unchanged
}

// A value whose targets would not fit the memory budget changes nothing: not the value, not the
// plan, not the memory (which keeps what the last frame wrote); the next frame runs as before.
TEST_F(TargetScaleByGLTest, AValueWhoseTargetsDoNotFitLeavesTheRunAsItWas) {
    auto ws = workspaceFromText(scaleByWorkspace(2));
    ASSERT_TRUE(ws);
    ExecutorOptions options;
    options.memoryBudget = 40 * 27 * 8 + 2000;  // the rgba16f output and the 1/8 or 1/4 target, not the 1/2
    GlRun run = runWorkspace(std::move(ws), {{40, 27}, 1, 1.0f / 60.0f}, options);
    ASSERT_TRUE(run.exec) << formatAll(run.diagnostics);
    const unsigned texture = run.exec->targetTexture("reduced");
    const Image before = readBack(*run.exec, "reduced");
    ASSERT_EQ(before.width, 5);

    EXPECT_EQ(run.exec->setVariable("Downsample", Value::ofInt(0)).error(),
              "the render targets need 12.8 KiB, more than the memory budget of 10.4 KiB (largest: 'output' 40x27 8.4 KiB, "
              "'reduced' 20x14 4.4 KiB); nothing was allocated (raise it with --memory-budget MiB)");
    EXPECT_EQ(run.exec->variable("Downsample")->asInt(), 2);
    EXPECT_EQ(run.exec->targetSize("reduced"), glm::ivec2(5, 4));
    EXPECT_EQ(run.exec->targetTexture("reduced"), texture) << "the memory in use stays";
    EXPECT_TRUE(readBack(*run.exec, "reduced").pixels == before.pixels);
    Diagnostics d = run.exec->renderFrame({}).takeDiagnostics();
    EXPECT_TRUE(d.empty()) << formatAll(d);
    EXPECT_TRUE(readBack(*run.exec, "reduced").pixels == before.pixels);

    ASSERT_EQ(run.exec->setVariable("Downsample", Value::ofInt(1)).error(), "") << "a value that fits still works";
    EXPECT_EQ(run.exec->targetSize("reduced"), glm::ivec2(10, 7));
}

TEST_F(TargetScaleByGLTest, AValuePickingNoScaleFailsAtCreationNamingTheTarget) {
    auto ws = workspaceFromText(scaleByWorkspace(1));
    ASSERT_TRUE(ws);
    ws->findVariable("Downsample")->value = Value::ofInt(5);  // as --set Downsample=5 does
    auto exec = runHeadless(*ws, {{40, 27}, 1, 1.0f / 60.0f});
    EXPECT_FALSE(exec);
    const Diagnostics& d = exec.diagnostics();
    ASSERT_FALSE(d.empty());
    EXPECT_EQ(d.front().element, "<target name=\"reduced\">");
    EXPECT_EQ(d.front().message, "variable 'Downsample' = 5 picks none of the 3 scales of target 'reduced'");
}

}  // namespace
}  // namespace rmfx::test
