// RMFX_GL_DEBUG: a headless context made with it set writes the driver's account of a GL error to
// stderr, in the call that raised it; one made without it writes nothing.

#include <cstdlib>
#include <string>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "gl/GlContext.h"
#include "gl/GlDebugOutput.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class GlDebugOutputGLTest : public GlTest {
protected:
    void TearDown() override {
        unsetenv("RMFX_GL_DEBUG");
        GlTest::SetUp();  // the shared context current again
    }

    // stderr while a fresh headless context, made with RMFX_GL_DEBUG as `value` (null: unset),
    // is asked to enable a capability that does not exist.
    std::string stderrOfABadCall(const char* value) {
        if (value) setenv("RMFX_GL_DEBUG", value, 1);
        else unsetenv("RMFX_GL_DEBUG");
        auto context = GlContext::createHeadless();
        EXPECT_TRUE(context) << (context ? "" : context.error());
        if (!context) return "";
        ::testing::internal::CaptureStderr();
        glEnable(0x7fff);  // GL_INVALID_ENUM
        const GLenum error = glGetError();
        std::string written = ::testing::internal::GetCapturedStderr();
        EXPECT_EQ(error, static_cast<GLenum>(GL_INVALID_ENUM));
        return written;
    }
};

TEST_F(GlDebugOutputGLTest, ASetVariableMakesTheDriverSayWhatWentWrong) {
    EXPECT_FALSE(glDebugOutputAsked());
    const std::string written = stderrOfABadCall("1");
    EXPECT_NE(written.find("rmfx: GL debug"), std::string::npos) << written;
    EXPECT_NE(written.find("GL_INVALID_ENUM"), std::string::npos) << written;
}

TEST_F(GlDebugOutputGLTest, UnsetOrZeroWritesNothing) {
    EXPECT_EQ(stderrOfABadCall(nullptr), "");
    EXPECT_EQ(stderrOfABadCall("0"), "");
}

}  // namespace
}  // namespace rmfx::test
