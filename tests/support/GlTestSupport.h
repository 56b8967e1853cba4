#pragma once
// Shared by the GL tests (rmfx_gl_tests): one headless GL context per test executable, and small
// helpers to load a workspace from text, render it and read targets back.

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "gl/GlExecutor.h"
#include "model/Image.h"
#include "model/Workspace.h"
#include "reference/CpuImage.h"
#include "run/HeadlessRun.h"
#include "run/LiveWorkspace.h"

namespace rmfx::test {

// Base fixture of every GL test. The first SetUp creates the headless context (kept for the
// whole executable); when no EGL display can be opened every test FAILS with the context's
// error message: a skipped GL suite would hide breakage.
class GlTest : public ::testing::Test {
protected:
    void SetUp() override;
};

// For workspaces with profile="compatibility" (legacy GLSL, fixed-function state): a second,
// compatibility-profile context, current during the test; the core one is current again after it.
class CompatibilityGlTest : public GlTest {
protected:
    void SetUp() override;
    void TearDown() override;
};

// Parses and validates workspace XML; relative file references resolve in `folder`. Adds a test
// failure with the diagnostics and returns nullptr when the workspace has errors.
std::unique_ptr<Workspace> workspaceFromText(const std::string& xml,
                                             const std::filesystem::path& folder = std::filesystem::path("."));

// A workspace of effects/ (e.g. "shader_1.xml") with `--set`-style overrides applied. Adds a test
// failure with the diagnostics and returns nullptr when it does not load.
using Overrides = std::vector<std::pair<std::string, std::string>>;
std::unique_ptr<Workspace> effectWorkspace(const std::string& file, const Overrides& overrides = {});

// Replaces the scene of a chapter-8 effect with a single light: pass `scenePass` draws (1, 1, 1, 1)
// on the pixels [from, to) (x and y from the bottom) and 0 elsewhere, with no samplers, and every
// other pass drawing into the same target is disabled. Adds a test failure when there is no such pass.
void replaceSceneWithLight(Workspace& ws, const std::string& scenePass, glm::ivec2 from, glm::ivec2 to);

// Replaces every pass that draws into `target` by one full-screen pass running `pattern` (a
// fragment shader body writing `out vec4 fragColor` from gl_FragCoord), inserted first.
void replaceSceneWithPattern(Workspace& ws, const std::string& target, const std::string& pattern);

// A pattern for replaceSceneWithPattern: `value` in rgb at `pixel` (x, y from the bottom), black
// elsewhere, alpha 1.
std::string singlePixelPattern(glm::ivec2 pixel, double value);

// The reduction-chain sizes with a single pixel at the far edges: 1x1; 3x5 with the pixel
// in the last column, the last row and the corner; 1921x1081 once (it is slow) at `largePixel`.
struct EdgePixelCase {
    glm::ivec2 size, pixel;
    std::string name() const;
};
std::vector<EdgePixelCase> edgePixelCases(glm::ivec2 largePixel = {1920, 1080});

// A stage workspace of effects/variants/ (e.g. "luminance.xml") whose Input texture reads `input`
// (an image file anywhere) instead of samples/media/hdr_scene.exr, with overrides applied. Adds a
// test failure and returns nullptr when it does not load.
std::unique_ptr<Workspace> stageWorkspace(const std::string& file, const std::filesystem::path& input,
                                          const Overrides& overrides = {});

// Writes a float64 image (row 0 at the bottom) as a 32-bit float EXR, rgba, so that what the
// Input texture holds is exactly the image's values rounded to float (NaN and Inf included).
void writeFloatExr(const std::filesystem::path& file, const RefImage& image);

struct GlRun {
    std::unique_ptr<Workspace> ws;     // the workspace run (the executor runs its own copy)
    std::unique_ptr<GlExecutor> exec;  // null when creation or a frame failed
    Diagnostics diagnostics;
};

// Renders `settings.frames` frames (frame i at time i·dt) with runHeadless. Adds a test failure
// with the diagnostics when it fails. Default options: every target is an output (readable).
GlRun runWorkspace(std::unique_ptr<Workspace> ws, const RunSettings& settings, const ExecutorOptions& options = {});
GlRun runWorkspace(const std::string& xml, const RunSettings& settings);

// readTarget, adding a test failure (and returning an empty image) on error.
Image readBack(const GlExecutor& exec, const std::string& target);

// Polls `live` every 5 ms until a change is handled: true then; false, with a test failure, when
// none comes within 5 s (hot-reload tests wait for the file system, they time nothing).
bool waitForReload(LiveWorkspace& live);

// A float RGBA image of width x height, every value 0, to fill and write as a test's input file.
Image blankHdrImage(int width, int height);

// readBack as a float64 reference image (row 0 at the bottom).
RefImage readRef(const GlRun& run, const std::string& target);

// One step of an 8-bit normalised target, and how far a float-to-unorm conversion may land from the
// exact value: Direct3D 10 and later allow 0.6 of a step and GPUs follow it (an NVIDIA H200 wrote 144
// for 144.59), where llvmpipe rounds to nearest (half a step).
inline constexpr double kUnorm8Step = 1.0 / 255.0;
inline constexpr double kUnorm8Conversion = 0.6 * kUnorm8Step;

// How far the current context's bilinear filtering takes a weight from the exact one: the largest
// |v - f| over a float texture holding 0 and 1 in two texels, sampled at 1000 fractions f between
// their centres. A rasteriser that filters in float32 (llvmpipe) gives about 1e-7; one with 8 bits
// of subtexel precision (NVIDIA's) up to 2^-9. A filtering pass of values within [0, m] then lies
// within 2 · this · m of the exact one (one weight error in each direction); tests of filtered
// taps take their tolerance from it. Measured once per process (needs a current context).
double bilinearWeightError();
// What `passes` filtering passes of values within [0, 1] may add to an error through the context's
// filtering: 2 · passes · bilinearWeightError() (a later averaging pass does not enlarge it).
double filteringAllowance(int passes);

// EXPECT_LE(error, tolerance) that also records "error of tolerance" as the test property `what`,
// so --gtest_output=xml shows how close each comparison comes to its bound.
void expectWithin(const std::string& what, double error, double tolerance);

// Pixel (x, y) channel c of an image read back, with y counted from the BOTTOM as gl_FragCoord does.
inline float atGl(const Image& image, int x, int yFromBottom, int c) {
    return image.at(x, image.height - 1 - yFromBottom, c);
}

// Formats a float so that GLSL (and the workspace parser) read back exactly the same float.
std::string glslFloat(double value);

}  // namespace rmfx::test
