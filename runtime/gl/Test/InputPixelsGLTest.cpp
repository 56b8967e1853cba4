// GlExecutor::writeInputPixels: an input's next image written into its texture in place from the
// caller's memory (rows top first, apart or packed, float or half), which must give what
// replaceInputImage gives with the same image; and nothing done where the texture cannot take them.

#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>

#include "gl/GlExecutor.h"
#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"
#include "validation/ImageInputs.h"

namespace rmfx::test {
namespace {

class InputPixelsGLTest : public GlTest {};

// The input copied to an rgba32f output, texel for texel.
const char* kCopy = R"(<workspace version="1" name="copy" size="5x3">
  <target name="out" format="rgba32f"/>
  <input name="scene"/>
  <pass name="copy" target="out">
    <sampler name="Scene" texture="scene" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
uniform sampler2D Scene;
out vec4 c;
void main() { c = texelFetch(Scene, ivec2(gl_FragCoord.xy), 0); }
]]></shader>
  </pass>
  <output target="out" transform="none"/>
</workspace>
)";

// Pixel (x, y) (row 0 the top) holds seed + x / 8 + y / 64 + channel / 512: every row and column differs.
Image pattern(int w, int h, float seed) {
    Image image = blankHdrImage(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c) image.at(x, y, c) = seed + x / 8.0f + y / 64.0f + c / 512.0f;
    return image;
}

std::uint16_t half(float f) {  // exact for the pattern's values (multiples of 1/512 below 4)
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    const int exponent = int((bits >> 23) & 0xff) - 127 + 15;
    if ((bits & 0x7fffffff) == 0) return 0;
    return std::uint16_t(((bits >> 16) & 0x8000) | (exponent << 10) | ((bits >> 13) & 0x3ff));
}

struct Started {
    std::unique_ptr<Workspace> ws;
    std::unique_ptr<GlExecutor> executor;
};

Started start(const ScratchDir& dir) {
    Started run;
    run.ws = workspaceFromText(kCopy, dir.path() / "copy.xml");
    EXPECT_TRUE(writeImage(dir / "first.exr", pattern(5, 3, 0.0f)));
    Result<SuppliedInputs> supplied = supplyInputs(*run.ws, {parseInputArgument((dir / "first.exr").string())}, std::nullopt);
    EXPECT_TRUE(supplied) << formatAll(supplied.diagnostics());
    ExecutorOptions options;
    options.givenInputs = supplied->given;
    auto created = GlExecutor::create(std::make_shared<const Workspace>(*run.ws), {5, 3}, options);
    EXPECT_TRUE(created) << formatAll(created.diagnostics());
    if (created) run.executor = std::move(*created);
    return run;
}

Image frame(GlExecutor& executor) {
    EXPECT_TRUE(executor.renderFrame({0.0f, 0.0f}));
    Result<Image> out = executor.readTarget("out");
    EXPECT_TRUE(out) << out.error();
    return out ? std::move(*out) : Image{};
}

TEST_F(InputPixelsGLTest, FloatsAndHalvesWrittenInPlaceGiveTheImageTopRowFirst) {
    ScratchDir dir;
    Started run = start(dir);
    ASSERT_TRUE(run.executor);
    const Image next = pattern(5, 3, 1.0f);
    ASSERT_TRUE(run.executor->writeInputPixels("scene", {next.pixels.data(), 5, 3, false, 5 * 16}));
    Image out = frame(*run.executor);
    EXPECT_EQ(out.pixels, next.pixels);
    EXPECT_FLOAT_EQ(out.at(0, 0, 0), 1.0f);                 // the top left
    EXPECT_FLOAT_EQ(out.at(4, 2, 3), 1.5f + 2 / 64.0f + 3 / 512.0f);  // the bottom right

    // Halves, each row 8 pixels apart (a crop of a wider image).
    const Image third = pattern(5, 3, 2.0f);
    std::vector<std::uint16_t> halves(8 * 3 * 4, 0xffff);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            for (int c = 0; c < 4; ++c) halves[size_t((y * 8 + x) * 4 + c)] = half(third.at(x, y, c));
    ASSERT_TRUE(run.executor->writeInputPixels("scene", {halves.data(), 5, 3, true, 8 * 4 * 2}));
    EXPECT_EQ(frame(*run.executor).pixels, third.pixels);

    // replaceInputImage with the same image gives the same.
    ASSERT_TRUE(run.executor->replaceInputImage("scene", std::make_shared<const Image>(next)));
    EXPECT_EQ(frame(*run.executor).pixels, next.pixels);
}

TEST_F(InputPixelsGLTest, NothingIsDoneWhereTheTextureCannotTakeThePixels) {
    ScratchDir dir;
    Started run = start(dir);
    ASSERT_TRUE(run.executor);
    const Image other = pattern(4, 3, 3.0f);
    EXPECT_FALSE(run.executor->writeInputPixels("scene", {other.pixels.data(), 4, 3, false, 4 * 16}));  // another size
    EXPECT_FALSE(run.executor->writeInputPixels("nope", {other.pixels.data(), 5, 3, false, 5 * 16}));
    EXPECT_FALSE(run.executor->writeInputPixels("scene", {nullptr, 5, 3, false, 5 * 16}));
    EXPECT_EQ(frame(*run.executor).pixels, pattern(5, 3, 0.0f).pixels);  // the first image still
}

}  // namespace
}  // namespace rmfx::test
