// rmfx render --explain alone prints the compiled plan and never opens a GL context: with EGL made
// unusable (no vendor library), it still prints shader_5's schedule and exits 0, while rendering
// the same frame fails on the context. (A GL test only because the rendering half needs the rmfx
// binary with a context to fail on.)

#include <gtest/gtest.h>

#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

constexpr const char* kNoEgl = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/rmfx-no-egl-vendor.json";

TEST(CliExplainGLTest, ExplainAloneNeedsNoGlContext) {
    ScratchDir dir;
    const std::string workspace = shellQuoted(sourceDir() / "effects/shader_5.xml");
    CommandResult plan = runRmfx("render " + workspace + " --explain --effects glare --size 64x64", dir.path(), kNoEgl);
    ASSERT_EQ(plan.status, 0) << plan.err;
    EXPECT_NE(plan.out.find("passes: 10 of 21 run"), std::string::npos) << plan.out;
    EXPECT_NE(plan.out.find("peak GPU memory of the frame: 118.0 KiB (120832 bytes)"), std::string::npos) << plan.out;

    CommandResult render = runRmfx("render " + workspace + " --explain --effects glare --size 64x64 -o out.png", dir.path(), kNoEgl);
    EXPECT_EQ(render.status, 2) << "rendering needs the context the environment took away: " << render.out;
    EXPECT_NE(render.err.find("EGL"), std::string::npos) << render.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.png"));
}

}  // namespace
}  // namespace rmfx::test
