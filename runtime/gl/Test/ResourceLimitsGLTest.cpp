// Limits before allocation: a target larger than the GL allows, a frame over the memory budget or
// a huge viewport fails with an error naming what asked for it, and no texture storage is made.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include "gl/GlExecutor.h"
#include "run/HeadlessRun.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

// Counts glTextureStorage2D calls while alive, by swapping libepoxy's function pointer.
class TextureStorageCounter {
public:
    TextureStorageCounter() {
        // Resolve the real entry point first: epoxy's initial stub replaces the pointer when called.
        GLuint t = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &t);
        glTextureStorage2D(t, 1, GL_RGBA8, 1, 1);
        glDeleteTextures(1, &t);
        real_ = epoxy_glTextureStorage2D;
        epoxy_glTextureStorage2D = &counting;
        calls_ = 0;
    }
    ~TextureStorageCounter() { epoxy_glTextureStorage2D = real_; }
    int calls() const { return calls_; }

private:
    static void EPOXY_CALLSPEC counting(GLuint texture, GLsizei levels, GLenum format, GLsizei w, GLsizei h) {
        ++calls_;
        real_(texture, levels, format, w, h);
    }
    static inline decltype(epoxy_glTextureStorage2D) real_ = nullptr;
    static inline int calls_ = 0;
};

std::string workspaceWithTarget(const std::string& target) {
    return R"(<workspace version="1">
  <target name="small" format="rgba8" size="8x8"/>
  )" + target + R"(
  <pass name="fill_small" target="small">
    <shader stage="fragment">out vec4 color; void main() { color = vec4(1.0); }</shader>
  </pass>
  <pass name="fill" target="big">
    <sampler name="Small" target="small"/>
    <shader stage="fragment">uniform sampler2D Small; out vec4 color; void main() { color = texture(Small, vec2(0.5)); }</shader>
  </pass>
  <output target="big"/>
</workspace>)";
}

class ResourceLimitsGLTest : public GlTest {};

// Creating an executor for `target`'s workspace at `viewport` fails without any texture storage;
// returns its diagnostics.
Diagnostics failsWithoutStorage(const std::string& target, glm::ivec2 viewport, const ExecutorOptions& options = {}) {
    auto ws = workspaceFromText(workspaceWithTarget(target));
    if (!ws) return {};
    TextureStorageCounter storage;
    auto exec = runHeadless(*ws, {viewport, 1, 1.0f / 60.0f}, options);
    EXPECT_FALSE(exec);
    EXPECT_EQ(storage.calls(), 0);
    return exec.diagnostics();
}

TEST_F(ResourceLimitsGLTest, ATargetOfOneHundredThousandSquaredFailsAndAllocatesNothing) {
    Diagnostics d = failsWithoutStorage(R"(<target name="big" format="rgba32f" size="100000x100000"/>)", {64, 64});
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_EQ(d[0].where.line, 3);
    EXPECT_EQ(d[0].element, "<target name=\"big\">");
    GLint max = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
    EXPECT_EQ(d[0].message, "target 'big' would be 100000x100000, larger than this GL allows (" + std::to_string(max) +
                                " per side); nothing was allocated");
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ResourceLimitsGLTest, AFrameOverTheMemoryBudgetFailsNamingTheLargestTargets) {
    // 1024x1024 rgba32f is 16 MiB; the small target 256 bytes.
    const std::string big = R"(<target name="big" format="rgba32f" size="1024x1024"/>)";
    ExecutorOptions tight;
    tight.memoryBudget = 8u << 20;
    Diagnostics d = failsWithoutStorage(big, {64, 64}, tight);
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_EQ(d[0].message,
              "the render targets need 16.0 MiB, more than the memory budget of 8.0 MiB (largest: 'big' 1024x1024 "
              "16.0 MiB, 'small' 8x8 256 B); nothing was allocated (raise it with --memory-budget MiB)");
    ExecutorOptions roomy;
    roomy.memoryBudget = 17u << 20;
    GlRun run = runWorkspace(workspaceFromText(workspaceWithTarget(big)), {{64, 64}, 1, 1.0f / 60.0f}, roomy);
    EXPECT_TRUE(run.exec) << formatAll(run.diagnostics);
}

TEST_F(ResourceLimitsGLTest, AViewportBeyondTheLimitFailsBeforeAnything) {
    Diagnostics d = failsWithoutStorage(R"(<target name="big" format="rgba8" scale="1"/>)", {100000, 100000});
    ASSERT_EQ(d.size(), 1u) << formatAll(d);
    EXPECT_NE(d[0].message.find("viewport size 100000x100000 is larger than this GL allows"), std::string::npos)
        << d[0].message;
}

}  // namespace
}  // namespace rmfx::test
