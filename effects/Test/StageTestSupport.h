#pragma once
// For the GL tests of the stage workspaces (effects/variants/): render one effect of a stage on a
// test image written as a float EXR, at the image's size.

#include <cmath>
#include <string>

#include "model/HdrEncoding.h"
#include "reference/HdrEncodingReference.h"
#include "reference/LuminanceVariantsReference.h"
#include "reference/StageInput.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

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
    Diagnostics d = run.exec->renderFrame({0.0f, 1.0f / 60.0f}).takeDiagnostics();
    EXPECT_TRUE(d.empty()) << formatAll(d);
}

inline void setVariable(GlRun& run, const std::string& name, const Value& value) {
    std::string error = run.exec->setVariable(name, value).error();
    EXPECT_EQ(error, "") << name;
}

// The 1x1 `luminance` target of luminance.xml: (r, g) = (Lavg, the peak Y).
inline glm::dvec2 readLuminance(const GlRun& run) {
    Image lum = readBack(*run.exec, "luminance");
    if (lum.pixels.empty()) return glm::dvec2(NAN);
    return {lum.at(0, 0, 0), lum.at(0, 0, 1)};
}

inline double relativeError(double actual, double expected) { return std::abs(actual - expected) / std::abs(expected); }

// The bound on the relative error of a log-average Lavg = exp(mean log(delta + Y)) computed in float
// over `image`: each pixel's float log is within a few ulps of its value (4 · 2^-23 relative),
// which moves the mean, and so Lavg relatively, by that much of the mean |log|; the float exp and
// the sums add 2e-6. Neither llvmpipe's nor NVIDIA's log and exp are correctly rounded, and
// NVIDIA's error grows with |log| (an H200 was 2.16e-6 off on an image whose logs reach 12).
inline double logAverageTolerance(const RefImage& image, double delta) {
    double sum = 0.0;
    for (const glm::dvec4& t : image.texels) sum += std::abs(std::log(delta + rec709Luminance(sanitisedTexel(t))));
    return 2e-6 + 4.0 * 0x1p-23 * sum / static_cast<double>(image.texels.size());
}

// luminance.xml's `downsampled` image checked against the exact box average of `input` by
// `factor`: within float rounding of the sum of factor² positive terms and the division
// (factor² + 2 ulps), plus what Target_Format keeps: rgba16f and r11g11b10f clamp to their largest
// value and round within a whole step (llvmpipe converts toward zero, GPUs to nearest: both are
// allowed), the encodings within their own bound (tests/reference/HdrEncodingReference.h).
// Returns the image read back (decoded), from which the chain's Lavg follows.
inline RefImage checkedDownsampled(const GlRun& run, const RefImage& input, int factor, int format) {
    constexpr HdrEncoding encodings[] = {HdrEncoding::Float, HdrEncoding::Float, HdrEncoding::Float,
                                         HdrEncoding::Rgba8x64, HdrEncoding::Rgbe8, HdrEncoding::Rgb9e5};
    RefImage gpu = readRef(run, "downsampled");
    for (glm::dvec4& t : gpu.texels) t = glm::dvec4(glm::dvec3(decodeHdr(encodings[format], glm::vec4(t))), 1.0);
    RefImage box = boxDownsampled(input, factor);
    EXPECT_EQ(gpu.width, box.width);
    EXPECT_EQ(gpu.height, box.height);
    if (gpu.width != box.width || gpu.height != box.height) return gpu;
    double worst = 0.0;  // in units of the bound
    for (size_t i = 0; i < box.texels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double exact = box.texels[i][c], bound = (factor * factor + 2) * 0x1p-24 * exact;
            if (format == 1 || format == 2) {
                const double largest = format == 1 ? 65504.0 : c == 2 ? 64512.0 : 65024.0;
                const int mantissa = format == 1 ? 10 : c == 2 ? 5 : 6;
                exact = std::min(exact, largest);
                bound += exact < 0x1p-14 ? 0x1p-14 * std::exp2(-mantissa) : std::exp2(std::floor(std::log2(exact)) - mantissa);
            } else if (format > 2) {
                exact = referenceEncode(encodings[format], glm::dvec3(box.texels[i])).decoded[c];
                bound += referenceErrorBound(encodings[format], glm::dvec3(box.texels[i])) + 0x1p-23 * exact;
            }
            double error = std::abs(gpu.texels[i][c] - exact);
            if (error > bound) {
                ADD_FAILURE() << "downsampled texel " << i << " channel " << c << ": " << gpu.texels[i][c] << ", expected "
                              << exact << " (box average " << box.texels[i][c] << ")";
                return gpu;
            }
            if (bound > 0.0) worst = std::max(worst, error / bound);
        }
    ::testing::Test::RecordProperty("downsampled: worst error / bound", std::to_string(worst));
    return gpu;
}

}  // namespace rmfx::test
