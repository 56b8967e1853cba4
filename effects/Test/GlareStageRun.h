#pragma once
// Renders the bloom and streak stage workspaces (effects/variants/) on a synthetic input for the GL
// tests: the input goes to the workspace as a float EXR in a scratch folder, in place of the
// scene the workspace names, and the render has the input's size.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "reference/GlareVariantsReference.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test {

// The stage workspace `file` ("bloom.xml", "streak.xml") rendering `effect` on `input` with
// `overrides` (--set style). Adds a test failure, and returns a run without executor, when anything fails.
inline GlRun renderStage(const std::string& file, const RefImage& input, const std::string& effect,
                         const Overrides& overrides = {}) {
    ScratchDir dir;
    std::filesystem::path exr = dir / "input.exr";
    writeFloatExr(exr, input);
    auto ws = stageWorkspace(file, exr, overrides);
    if (!ws) return {};
    ExecutorOptions options;
    options.effects = std::vector<std::string>{effect};
    return runWorkspace(std::move(ws), {{input.width, input.height}, 1, 1.0f / 60.0f}, options);
}

// A gradient below and above the threshold, a few bright texels (one on the top row and one in
// the right column, so that the edges count) and a small bright square.
inline RefImage syntheticInput(int width, int height) {
    RefImage image(width, height, glm::dvec4(0.0, 0.0, 0.0, 1.0));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = glm::dvec4(2.0 * x / width, 1.5 * y / height, 0.5 + double(x + y) / (width + height), 1.0);
    auto light = [&](int x, int y, glm::dvec3 c) { image.at(x, y) = glm::dvec4(c, 1.0); };
    light(width / 2, height / 2, {40.0, 30.0, 20.0});
    light(width / 5, height / 3, {10.0, 60.0, 5.0});
    light(width - 1, height / 4, {25.0, 25.0, 25.0});
    light(width / 3, height - 1, {5.0, 8.0, 50.0});
    for (int y = 3 * height / 4; y < 3 * height / 4 + 5; ++y)
        for (int x = 2 * width / 3; x < 2 * width / 3 + 6; ++x) light(x, y, {8.0, 4.0, 2.0});
    return image;
}

// Whether every channel of every texel is finite.
inline bool allFinite(const RefImage& image) {
    for (const auto& t : image.texels)
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(t[c])) return false;
    return true;
}

// Largest |a - b| over rgb.
inline double maxRgbDifference(const RefImage& a, const RefImage& b) { return maxAbsDifference(a, b, 3); }

// What one write into a target of format Target_Format `format` may change a value of a texel
// whose largest channel is at most `peak`: rgba16f rounds to 11 significant bits, r11g11b10f keeps
// 6 (r, g) or 5 (b) mantissa bits, RGBA8x64 steps by (1 + 64 a / 255) / 255 with the multiplier
// at most peak + 64/255 (at least 1), RGBE8 truncates to 8 bits of the peak, RGB9E5 rounds to 9.
inline double quantisation(int format, double peak) {
    switch (format) {
        case 0: return std::ldexp(peak, -24);
        case 1: return std::ldexp(peak, -11);
        case 2: return std::ldexp(peak, -5);
        case 3: return 0.5 / 255.0 * std::max(1.0, peak + 64.0 / 255.0);
        case 4: return std::ldexp(peak, -8);
        case 5: return std::ldexp(peak, -9);
    }
    return 0.0;
}

// Sum of r + g + b over an image.
inline double rgbSum(const RefImage& image) {
    double sum = 0.0;
    for (const auto& t : image.texels) sum += t.r + t.g + t.b;
    return sum;
}

// Renders `effect` of the stage workspace `file` with Target_Format 0 and then 1..5, and expects
// each result within strength * (writes * quantisation(F, peak) + filterTolerance * peak) of the
// rgba32f one, peak the largest value of `down`: every pass averages with non-negative weights
// summing to at most 1, so an error a write makes never grows later and no value exceeds the peak;
// filterTolerance covers the shader's bilinear (encoded formats) against the hardware's (float).
inline void expectFormatsWithinQuantisation(const std::string& file, const RefImage& input, const std::string& effect,
                                            Overrides overrides, int writes, double strength, double filterTolerance) {
    overrides.push_back({"Target_Format", "0"});
    GlRun reference = renderStage(file, input, effect, overrides);
    ASSERT_TRUE(reference.exec);
    RefImage expected = readRef(reference, "result");
    double peak = maxColorChannel(readRef(reference, "down"));
    std::printf("%-13s", effect.c_str());
    for (int format = 1; format <= 5; ++format) {
        SCOPED_TRACE(effect + " Target_Format " + std::to_string(format));
        overrides.back().second = std::to_string(format);
        GlRun run = renderStage(file, input, effect, overrides);
        ASSERT_TRUE(run.exec);
        RefImage result = readRef(run, "result");
        ASSERT_TRUE(allFinite(result));
        double bound = strength * (writes * quantisation(format, peak) + filterTolerance * peak);
        double error = maxRgbDifference(result, expected);
        std::printf("  %d: %.3g of %.3g", format, error, bound);
        expectWithin(effect + " format " + std::to_string(format), error, bound);
    }
    std::printf("\n");
}

}  // namespace rmfx::test
