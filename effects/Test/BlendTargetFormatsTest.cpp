// Additive blending cannot be clamped by a shader: the blend unit adds after the shader has run.
// Onto a half-float target, a sum above 65504 becomes +Inf on GPUs that round float to half (an
// NVIDIA H200 gave Inf in the output of shader_2, shader_4, shader_5 and exercise_1 at exposure
// 1e4), while Mesa's llvmpipe saturates at 65504, so the GL tests on CI cannot see it. Every pass
// of the effects that blends onto a float target therefore writes a 32-bit float one, except where
// what is added is bounded far below 65504.

#include <set>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {
namespace {

bool halfFloat(TargetFormat f) {
    return f == TargetFormat::RGBA16F || f == TargetFormat::R16F || f == TargetFormat::RG16F ||
           f == TargetFormat::R11G11B10F;
}

TEST(BlendTargetFormatsTest, NoEffectBlendsOntoAHalfFloatTarget) {
    // The 8-bit exercises: scene and glare or streaks come from rgba8 targets whose alpha holds the
    // intensity / 64, so what the composite adds is at most a few hundred.
    const std::set<std::string> bounded = {"shader_6.xml", "exercise_2.xml"};
    int blends = 0;
    for (const auto& entry : std::filesystem::directory_iterator(sourceDir() / "effects")) {
        if (entry.path().extension() != ".xml" || bounded.count(entry.path().filename().string())) continue;
        Result<Workspace> loaded = loadWorkspace(entry.path());
        ASSERT_TRUE(loaded.ok()) << formatAll(loaded.diagnostics());
        const Workspace& ws = *loaded;
        for (const Pass& pass : ws.passes) {
            if (!pass.blend.enabled) continue;
            ++blends;
            std::string target = ws.passTargetName(pass);
            std::vector<TargetFormat> formats;
            if (const RenderTarget* t = ws.findTarget(target)) {
                formats = t->formats.empty() ? std::vector<TargetFormat>{t->format} : t->formats;
            } else {
                formats = {ws.output.format};
            }
            for (TargetFormat f : formats)
                EXPECT_FALSE(halfFloat(f)) << entry.path().filename().string() << ": pass '" << pass.name
                                           << "' blends onto '" << target << "' (" << targetFormatName(f) << ")";
        }
    }
    EXPECT_GE(blends, 5);  // the glare, streak and ghost composites of the chapter's float workspaces
}

}  // namespace
}  // namespace rmfx::test
