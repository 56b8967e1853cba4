// The benchmark's hand-written shader_5 (bench/HandWrittenShader5) issues the work GlExecutor
// issues for shader_5 with all effects: the same shaders, states, inputs and formats on the same
// context, so its screen is the executor's bit for bit, and the effects' passes show in it (it
// differs from the screen without them).

#include <cmath>
#include <vector>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "bench/HandWrittenShader5.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class HandWrittenShader5GLTest : public GlTest {};

// The distance between adjacent half floats at magnitude |v|.
double halfStep(double v) {
    v = std::fabs(v);
    if (v < std::ldexp(1.0, -14)) return std::ldexp(1.0, -24);  // subnormal halves
    return std::ldexp(1.0, static_cast<int>(std::floor(std::log2(v))) - 10);
}

// Largest difference in half-float steps between the hand loop's screen (GL rows, bottom first)
// and an image the executor read back (top first).
double largestStepDifference(const std::vector<float>& hand, const Image& executor) {
    double largest = 0.0;
    for (int y = 0; y < executor.height; ++y)
        for (int x = 0; x < executor.width; ++x)
            for (int c = 0; c < 4; ++c) {
                double a = hand[(static_cast<size_t>(y) * executor.width + x) * 4 + c];
                double b = atGl(executor, x, y, c);
                largest = std::max(largest, std::fabs(a - b) / halfStep(std::max(std::fabs(a), std::fabs(b))));
            }
    return largest;
}

TEST_F(HandWrittenShader5GLTest, RendersTheExecutorsScreen) {
    const glm::ivec2 size{64, 64};
    ExecutorOptions options;
    options.outputs = {"output"};
    GlRun run = runWorkspace(effectWorkspace("shader_5.xml"), {size, 2, 1.0f / 60.0f}, options);
    ASSERT_TRUE(run.exec);
    ExecutorOptions withoutEffects = options;
    withoutEffects.effects = std::vector<std::string>{};
    GlRun bare = runWorkspace(effectWorkspace("shader_5.xml"), {size, 1, 1.0f / 60.0f}, withoutEffects);
    ASSERT_TRUE(bare.exec);

    auto hand = bench::HandWrittenShader5::create(*run.ws, size);
    ASSERT_TRUE(hand) << hand.error();
    EXPECT_EQ((*hand)->passCount(), static_cast<int>(run.exec->passesRun().size()));
    EXPECT_EQ((*hand)->passCount(), 20);
    for (int frame = 0; frame < 2; ++frame) (*hand)->renderFrame();
    std::vector<float> screen(static_cast<size_t>(size.x) * size.y * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage((*hand)->outputTexture(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(screen.size() * sizeof(float)),
                      screen.data());
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

    Image expected = readBack(*run.exec, "output");
    ASSERT_EQ(expected.width, size.x);
    ASSERT_EQ(expected.height, size.y);
    int differing = 0;
    for (int y = 0; y < expected.height; ++y)
        for (int x = 0; x < expected.width; ++x)
            for (int c = 0; c < 4; ++c)
                differing += screen[(static_cast<size_t>(y) * expected.width + x) * 4 + c] != atGl(expected, x, y, c);
    EXPECT_EQ(differing, 0) << "values unlike the executor's screen; largest difference "
                            << largestStepDifference(screen, expected) << " half-float steps";
    // The comparison sees the effects: without them the executor's screen is many steps away.
    Image plain = readBack(*bare.exec, "output");
    EXPECT_GT(largestStepDifference(screen, plain), 100.0);
}

}  // namespace
}  // namespace rmfx::test
