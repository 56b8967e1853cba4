#pragma once
// For the GL tests of the stage workspaces (effects/variants/): render one effect of a stage on a
// test image written as a float EXR, at the image's size.

#include <cmath>
#include <string>

#include "tests/GlTestSupport.h"
#include "tests/TestSupport.h"
#include "tests/reference/LuminanceVariantsReference.h"

namespace rmfx::test {

// Writes `input` to DIR/input.exr and renders one frame of `effect` of `workspace` (e.g.
// "luminance.xml") on it; every target stays readable. The executor can render again after
// setVariable (or reloadTexture("Input") after the file is rewritten).
inline GlRun runStage(const std::string& workspace, const std::string& effect, const RefImage& input,
                      const ScratchDir& dir, const Overrides& overrides = {}) {
    std::filesystem::path file = dir / "input.exr";
    writeFloatExr(file, input);
    ExecutorOptions options;
    options.effects = std::vector<std::string>{effect};
    return runWorkspace(stageWorkspace(workspace, file, overrides), {{input.width, input.height}, 1}, options);
}

// Renders one more frame (after setVariable or a texture reload); a test failure on error.
inline void renderAgain(GlRun& run) {
    Diagnostics d = run.exec->renderFrame({0.0f, 1.0f / 60.0f});
    EXPECT_TRUE(d.empty()) << formatAll(d);
}

inline void setVariable(GlRun& run, const std::string& name, const Value& value) {
    std::string error = run.exec->setVariable(name, value);
    EXPECT_EQ(error, "") << name;
}

// The 1x1 `luminance` target of luminance.xml: (r, g) = (Lavg, the peak Y).
inline glm::dvec2 readLuminance(const GlRun& run) {
    Image lum = readBack(*run.exec, "luminance");
    if (lum.pixels.empty()) return glm::dvec2(NAN);
    return {lum.at(0, 0, 0), lum.at(0, 0, 1)};
}

inline double relativeError(double actual, double expected) { return std::abs(actual - expected) / std::abs(expected); }

// luminance.xml's `downsampled` image (Target_Format 0 rgba32f or 1 rgba16f) checked against the
// exact box average of `input` by `factor`: within float rounding of the sum of factor² positive
// terms and the division (factor² + 2 ulps), plus for
// rgba16f the clamp at 65504 and one step of half (llvmpipe converts to half toward zero, GPUs to
// nearest: both are allowed). Returns the image read back, from which the chain's Lavg follows.
inline RefImage checkedDownsampled(const GlRun& run, const RefImage& input, int factor, int format) {
    RefImage gpu = readRef(run, "downsampled");
    RefImage box = boxDownsampled(input, factor);
    EXPECT_EQ(gpu.width, box.width);
    EXPECT_EQ(gpu.height, box.height);
    if (gpu.width != box.width || gpu.height != box.height) return gpu;
    double worst = 0.0;  // in units of the bound
    for (size_t i = 0; i < box.texels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double exact = box.texels[i][c], bound = (factor * factor + 2) * 0x1p-24 * exact;
            if (format == 1) {
                exact = std::min(exact, 65504.0);
                bound += exact < 0x1p-14 ? 0x1p-24 : std::exp2(std::floor(std::log2(exact)) - 10.0);
            }
            double error = std::abs(gpu.texels[i][c] - exact);
            if (error > bound) {
                ADD_FAILURE() << "downsampled texel " << i << " channel " << c << ": " << gpu.texels[i][c] << ", box average "
                              << box.texels[i][c];
                return gpu;
            }
            if (bound > 0.0) worst = std::max(worst, error / bound);
        }
    ::testing::Test::RecordProperty("downsampled: worst error / bound", std::to_string(worst));
    return gpu;
}

}  // namespace rmfx::test
