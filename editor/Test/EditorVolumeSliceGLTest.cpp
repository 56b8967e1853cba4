// The target browser's view of a volume texture: TextureBlit::drawSlice draws one slice, sRGB
// encoded as every thumbnail is, read back here against the texels written (a 2x2x3 volume whose
// slices differ) and the sRGB curve computed on the CPU.

#include <cmath>
#include <vector>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "editor/DisplayTexture.h"
#include "editor/TextureBlit.h"
#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {
namespace {

class EditorVolumeSliceGLTest : public GlTest {};

// Texel (x, y, z), GL's y (row 0 at the bottom): red follows x, green y, blue the slice.
float texel(int x, int y, int z, int c) { return c == 0 ? 0.1f + 0.6f * x : c == 1 ? 0.2f + 0.5f * y : c == 2 ? 0.05f + 0.4f * z : 1.0f; }

}  // namespace

TEST_F(EditorVolumeSliceGLTest, ASliceShowsThatSlicesTexelsSrgbEncoded) {
    std::vector<float> data;
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x)
                for (int c = 0; c < 4; ++c) data.push_back(texel(x, y, z, c));
    GLuint volume = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &volume);
    glTextureStorage3D(volume, 1, GL_RGBA32F, 2, 2, 3);
    glTextureSubImage3D(volume, 0, 0, 0, 0, 2, 2, 3, GL_RGBA, GL_FLOAT, data.data());
    auto blit = editor::TextureBlit::create();
    ASSERT_TRUE(blit) << blit.error();
    editor::DisplayTexture image;
    image.resize({2, 2});
    for (int z = 0; z < 3; ++z) {
        SCOPED_TRACE("slice " + std::to_string(z));
        image.bindFramebuffer();
        (*blit)->drawSlice(volume, (static_cast<float>(z) + 0.5f) / 3.0f, DisplayTransform::Srgb);
        std::vector<unsigned char> pixels(2 * 2 * 4);
        glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x)
                for (int c = 0; c < 3; ++c) {
                    const double expected = 255.0 * srgbEncode(texel(x, y, z, c));
                    EXPECT_NEAR(pixels[static_cast<size_t>((y * 2 + x) * 4 + c)], expected, 0.6) << x << "," << y << " channel " << c;
                }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteTextures(1, &volume);
}

}  // namespace rmfx::test
