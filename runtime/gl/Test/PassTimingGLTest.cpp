// Per-pass GPU timing from timestamp queries: off by default, one entry per pass that ran, in
// schedule order, and the entries add up to the frame total.

#include <numeric>

#include <gtest/gtest.h>

#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class PassTimingGLTest : public GlTest {};

TEST_F(PassTimingGLTest, TimesEveryPassOfTheNewestCompletedFrame) {
    GlRun run = runWorkspace(effectWorkspace("shader_2.xml"), {{64, 64}, 1, 0.1f});
    ASSERT_TRUE(run.exec);
    EXPECT_TRUE(run.exec->passTimings().empty()) << "timing is off by default";

    run.exec->setTimingEnabled(true);
    for (int i = 0; i < 4; ++i) ASSERT_TRUE(run.exec->renderFrame({0.1f * i, 0.1f}).takeDiagnostics().empty());
    const std::vector<PassTiming>& timings = run.exec->passTimings();
    std::vector<std::string> expected;
    for (const Pass& p : run.ws->passes)
        if (p.enabled && p.name != "scene_from_input") expected.push_back(p.name);  // no --input: culled
    std::vector<std::string> names;
    for (const PassTiming& t : timings) names.push_back(t.pass);
    EXPECT_EQ(names, expected);
    double sum = 0.0;
    for (const PassTiming& t : timings) {
        EXPECT_GE(t.milliseconds, 0.0) << t.pass;
        EXPECT_LT(t.milliseconds, 10000.0) << t.pass;
        sum += t.milliseconds;
    }
    EXPECT_GT(run.exec->frameGpuMilliseconds(), 0.0);
    EXPECT_NEAR(sum, run.exec->frameGpuMilliseconds(), 1e-6);

    run.exec->setTimingEnabled(false);
    EXPECT_TRUE(run.exec->passTimings().empty());
    EXPECT_EQ(run.exec->frameGpuMilliseconds(), 0.0);
}

}  // namespace
}  // namespace rmfx::test
