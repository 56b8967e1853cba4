// NaN, +Inf, -Inf and negative texels in the float sky (samples/media/sky_cross.exr), the one float
// texture the workspaces read: a copy with such texels on a sparse grid is written to a scratch
// folder and each workspace's Sky_Float is pointed at it. The scene passes make the filtered sample
// finite and non-negative (finiteNonNegative, effects/glsl/finite.glsl, on the bits) before
// anything else sees it, so:
//   - no target holds a NaN or Inf;
//   - every texel of the scene (the first target written from the sky) that the bad texels cannot
//     reach is bit-identical to the render with those texels replaced by 0 (which texels they
//     reach is found by a third render with them replaced by +Inf: a texel that differs there is
//     reachable), and they reach at most 5 % of it (the bilinear and mip footprints of 1 texel in
//     1024), but some of it (they are in view). The marker is +Inf, not a large finite value,
//     because a texel in a filter's footprint at weight 0 still carries a NaN or an infinity on
//     some GPUs (0 * Inf is NaN; an NVIDIA H200 reached 2 colour values a 1e30 marker did not),
//     and must then count as reached;
//   - every texel of every target lies between 0 and the zero-texel render's value (+1e-6
//     relative for the order of float sums): a filtered sample that touched a bad texel becomes 0
//     (NaN, ±Inf) or smaller (a negative weight), never larger, and every pass after it is
//     monotonic (non-negative weights, thresholds that keep or drop, clamps). Downstream blurs
//     spread the markers too far for a mask, so only this bound is checked there.
// auto_exposure divides by the average, which the bad texels lower, so only its scene follows the
// rules above; its other targets must be finite.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class SkyTextureHardCasesGLTest : public GlTest {};

constexpr int kGrid = 32;  // one bad texel per 32x32 texels of the cross image

// The sky with the texels (x, y) on the grid set to what `bad` gives for the i-th of them.
template <typename Bad>
Image withGridTexels(const Image& sky, Bad bad) {
    Image out = sky;
    int i = 0;
    for (int y = kGrid / 2; y < out.height; y += kGrid)
        for (int x = kGrid / 2 + (y / kGrid) % 7; x < out.width; x += kGrid, ++i)
            for (int c = 0; c < std::min(3, out.channels); ++c) out.at(x, y, c) = bad(i, c);
    return out;
}

float badValue(int i, int c) {
    switch ((i + c) % 4) {
    case 0: return std::numeric_limits<float>::quiet_NaN();
    case 1: return std::numeric_limits<float>::infinity();
    case 2: return -std::numeric_limits<float>::infinity();
    default: return -5.0f;
    }
}

uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

struct Case {
    std::string file;
    Overrides overrides;
    int frames = 1;
    bool monotonic = true;  // false: only the scene is compared (auto_exposure)
};

GlRun render(const Case& kase, const std::filesystem::path& sky) {
    auto ws = effectWorkspace(kase.file, kase.overrides);
    if (!ws) return {};
    bool found = false;
    for (Texture& t : ws->textures)
        if (t.name == "Sky_Float") {
            t.files = {sky.string()};
            found = true;
        }
    EXPECT_TRUE(found) << kase.file << " has no Sky_Float";
    return runWorkspace(std::move(ws), {{128, 128}, kase.frames, 1.0f / 60.0f});
}

TEST_F(SkyTextureHardCasesGLTest, BadTexelsAreSanitisedInTheFirstPassThatReadsTheSky) {
    auto sky = readImage(sourceDir() / "samples" / "media" / "sky_cross.exr");
    ASSERT_TRUE(sky.ok()) << sky.error();
    ScratchDir dir;
    const auto badFile = dir / "sky_bad.exr", zeroFile = dir / "sky_zero.exr", markerFile = dir / "sky_marker.exr";
    ASSERT_TRUE(writeImage(badFile, withGridTexels(sky.value(), badValue)).ok());
    ASSERT_TRUE(writeImage(zeroFile, withGridTexels(sky.value(), [](int, int) { return 0.0f; })).ok());
    ASSERT_TRUE(writeImage(markerFile, withGridTexels(sky.value(), [](int, int) { return std::numeric_limits<float>::infinity(); })).ok());
    {  // the file keeps the bad values (float EXR)
        auto back = readImage(badFile);
        ASSERT_TRUE(back.ok());
        int nan = 0;
        for (float v : back.value().pixels) nan += std::isnan(v);
        ASSERT_GT(nan, 10);
    }

    std::vector<Case> cases;
    // shader_2, 3, 4 and exercise_1 draw their scene with the same sky and teapot passes as
    // shader_5, whose glare, streaks and ghosts are theirs combined.
    for (std::string file : {"shader_1", "shader_5"}) cases.push_back({file + ".xml", {{"Environment_Format", "1"}}});
    cases.push_back({"article_pipeline.xml", {}});
    cases.push_back({"auto_exposure.xml", {{"Environment_Format", "1"}}, 2, false});

    for (const Case& kase : cases) {
        SCOPED_TRACE(kase.file);
        GlRun bad = render(kase, badFile), zero = render(kase, zeroFile), marker = render(kase, markerFile);
        ASSERT_TRUE(bad.exec && zero.exec && marker.exec);
        std::vector<std::string> targets = {"output"};
        for (const RenderTarget& t : bad.ws->targets) targets.push_back(t.name);
        for (const std::string& name : targets) {
            Image b = readBack(*bad.exec, name), z = readBack(*zero.exec, name), m = readBack(*marker.exec, name);
            ASSERT_EQ(b.pixels.size(), z.pixels.size());
            ASSERT_EQ(b.pixels.size(), m.pixels.size());
            int nonFinite = 0, changedUnreached = 0, outOfRange = 0, reached = 0;
            const bool first = name == "scene";
            for (size_t i = 0; i < b.pixels.size(); ++i) {
                if (!std::isfinite(b.pixels[i])) ++nonFinite;
                if (!kase.monotonic && !first) continue;
                if (static_cast<int>(i % b.channels) >= 3) continue;  // colour only
                const float v = b.pixels[i], ref = z.pixels[i];
                outOfRange += !(v >= 0.0f && v <= ref + 1e-6f * std::fabs(ref));
                if (!first) continue;
                if (bits(m.pixels[i]) == bits(ref)) changedUnreached += bits(v) != bits(ref);
                else ++reached;
            }
            EXPECT_EQ(nonFinite, 0) << name << ": NaN or Inf";
            EXPECT_EQ(outOfRange, 0) << name << ": outside [0, the zero-texel render]";
            if (first) {
                const int colours = static_cast<int>(b.pixels.size() / b.channels) * 3;
                EXPECT_EQ(changedUnreached, 0) << "differs where no bad texel reaches";
                EXPECT_GT(reached, 0) << "the bad texels are in view";
                EXPECT_LE(reached, colours / 20) << "they stay local";
                std::printf("  %s: %d of %d scene colour values reached by bad texels\n", kase.file.c_str(), reached,
                            colours);
            }
        }
    }
}

}  // namespace
}  // namespace rmfx::test
