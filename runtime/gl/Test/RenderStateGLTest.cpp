// The executor sets a pass's blend, depth and rasterizer state only where it differs from what the
// pass before it set, and uploads a uniform only where its value changed: what a frame draws must
// not depend on that, whatever state other code (the editor, a caller) leaves between frames.

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "gl/GlExecutor.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class RenderStateGLTest : public GlTest {};

// base writes (0.5, 0, 0, 1) over its clear; added blends (0, Gain, 0, 0) onto it; copy, cleared
// to white and not blended, samples the result. A blend left on for copy would give 1.5 in red.
const char* const kWorkspace = R"(<workspace version="1" name="state" size="16x8">
  <float name="Gain" value="0.25"/>
  <target name="sum" format="rgba32f"/>
  <target name="copy" format="rgba32f"/>
  <pass name="base" target="sum">
    <clear color="0 0 1 1"/>
    <shader stage="fragment"><![CDATA[
out vec4 c;
void main() { c = vec4(0.5, 0.0, 0.0, 1.0); }
]]></shader>
  </pass>
  <pass name="added" target="sum">
    <blend mode="add"/>
    <shader stage="fragment"><![CDATA[
uniform float Gain;
out vec4 c;
void main() { c = vec4(0.0, Gain, 0.0, 0.0); }
]]></shader>
  </pass>
  <pass name="copy" target="copy">
    <clear color="1 1 1 1"/>
    <sampler name="Sum" target="sum" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
uniform sampler2D Sum;
out vec4 c;
void main() { c = texelFetch(Sum, ivec2(gl_FragCoord.xy), 0); }
]]></shader>
  </pass>
</workspace>)";

void expectEveryPixel(const Image& image, glm::vec4 expected, const std::string& what) {
    ASSERT_EQ(image.width, 16) << what;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 4; ++c)
                ASSERT_EQ(image.at(x, y, c), expected[c]) << what << " at (" << x << ", " << y << ") channel " << c;
}

TEST_F(RenderStateGLTest, StateLeftBetweenFramesAndChangedValuesAreTakenIntoAccount) {
    GlRun run = runWorkspace(kWorkspace, RunSettings{{16, 8}});
    ASSERT_TRUE(run.exec) << formatAll(run.diagnostics);
    GlExecutor& exec = *run.exec;
    expectEveryPixel(readBack(exec, "copy"), {0.5f, 0.25f, 0.0f, 1.0f}, "first frame");

    // What an editor or a caller may leave: every state the passes set, set otherwise.
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_ZERO);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_NEVER);
    glDepthMask(GL_FALSE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT_AND_BACK);
    glFrontFace(GL_CW);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    ASSERT_TRUE(exec.renderFrame({}));
    expectEveryPixel(readBack(exec, "copy"), {0.5f, 0.25f, 0.0f, 1.0f}, "after other state");

    ASSERT_EQ(exec.setVariable("Gain", Value::ofFloat(0.125f)).error(), "");
    ASSERT_TRUE(exec.renderFrame({}));
    expectEveryPixel(readBack(exec, "copy"), {0.5f, 0.125f, 0.0f, 1.0f}, "Gain 0.125");
    ASSERT_EQ(exec.setVariable("Gain", Value::ofFloat(0.25f)).error(), "");
    ASSERT_TRUE(exec.renderFrame({}));
    expectEveryPixel(readBack(exec, "copy"), {0.5f, 0.25f, 0.0f, 1.0f}, "Gain back to 0.25");
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

}  // namespace
}  // namespace rmfx::test
