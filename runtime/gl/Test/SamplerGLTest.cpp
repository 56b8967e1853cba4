// Texture sampling against CPU references: nearest and bilinear filtering, the four wrap modes
// outside [0, 1], mipmap levels of a render target, sRGB decoding of 8-bit PNGs, and image
// orientation (row 0 of a file is the top, uv (0, 1)).

#include <cmath>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

class SamplerGLTest : public GlTest {};

// A 4x4 RGBA float image with a distinct value in every texel and channel.
Image testImage() {
    Image image;
    image.width = image.height = 4;
    image.channels = 4;
    image.highDynamicRange = true;
    image.pixels.resize(64);
    for (int y = 0; y < 4; ++y)      // file row, 0 = top
        for (int x = 0; x < 4; ++x) {
            image.at(x, y, 0) = static_cast<float>(x + 4 * y + 1) / 16.0f;
            image.at(x, y, 1) = static_cast<float>(x * x) * 0.75f - static_cast<float>(y);
            image.at(x, y, 2) = 100.0f + static_cast<float>(10 * y + x);
            image.at(x, y, 3) = 1.0f / static_cast<float>(1 + x + y);
        }
    return image;
}

// A texel of `image` addressed the GL way: (i, j) with j = 0 the BOTTOM row (the file's last row).
glm::dvec4 texelGl(const Image& image, int i, int j) {
    int row = image.height - 1 - j;
    return {image.at(i, row, 0), image.at(i, row, 1), image.at(i, row, 2), image.at(i, row, 3)};
}

enum class WrapRule { Repeat, Clamp, Mirror, Border };

// GL 4.5 §8.14.2: wrap applied to integer texel coordinates; -1 means "the border colour".
int wrapIndex(int i, int size, WrapRule rule) {
    switch (rule) {
        case WrapRule::Repeat: return ((i % size) + size) % size;
        case WrapRule::Clamp: return std::clamp(i, 0, size - 1);
        case WrapRule::Mirror: {
            int m = ((i % (2 * size)) + 2 * size) % (2 * size) - size;
            int mirrored = m >= 0 ? m : -(1 + m);
            return size - 1 - mirrored;
        }
        case WrapRule::Border: return i < 0 || i >= size ? -1 : i;
    }
    return i;
}

glm::dvec4 fetch(const Image& image, int i, int j, WrapRule rule, glm::dvec4 border) {
    int wi = wrapIndex(i, image.width, rule), wj = wrapIndex(j, image.height, rule);
    if (wi < 0 || wj < 0) return border;
    return texelGl(image, wi, wj);
}

glm::dvec4 sampleNearest(const Image& image, glm::dvec2 uv, WrapRule rule, glm::dvec4 border = {}) {
    return fetch(image, static_cast<int>(std::floor(uv.x * image.width)),
                 static_cast<int>(std::floor(uv.y * image.height)), rule, border);
}

glm::dvec4 sampleLinear(const Image& image, glm::dvec2 uv, WrapRule rule, glm::dvec4 border = {}) {
    double u = uv.x * image.width - 0.5, v = uv.y * image.height - 0.5;
    int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
    double a = u - i0, b = v - j0;
    return (1 - a) * (1 - b) * fetch(image, i0, j0, rule, border) + a * (1 - b) * fetch(image, i0 + 1, j0, rule, border) +
           (1 - a) * b * fetch(image, i0, j0 + 1, rule, border) + a * b * fetch(image, i0 + 1, j0 + 1, rule, border);
}

// A workspace whose single pass samples `samplerElement` (uniform "tex") at the given
// coordinates, one per pixel of an rgba32f target "out" of size N x 1.
std::string samplingWorkspace(const std::string& textureElement, const std::string& samplerElement,
                              const std::vector<glm::dvec2>& uvs) {
    std::ostringstream uvList;
    for (size_t i = 0; i < uvs.size(); ++i)
        uvList << (i ? ", " : "") << "vec2(" << glslFloat(uvs[i].x) << ", " << glslFloat(uvs[i].y) << ")";
    std::ostringstream xml;
    xml << R"(<workspace version="1" name="sampling" size="8x8">
  )" << textureElement << R"(
  <target name="out" format="rgba32f" size=")" << uvs.size() << R"(x1"/>
  <pass name="sample" target="out">
    )" << samplerElement << R"(
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D tex;
out vec4 fragColor;
const vec2 uvs[)" << uvs.size() << "] = vec2[](" << uvList.str() << R"();
void main() { fragColor = texture(tex, uvs[int(gl_FragCoord.x)]); }
]]></shader>
  </pass>
</workspace>)";
    return xml.str();
}

// Coordinates on a 1/32 grid: bilinear weights are multiples of 1/8 (exact with the 8 bits of
// sub-texel precision GPUs use) and no coordinate sits on a texel edge of a 4-texel axis.
std::vector<glm::dvec2> coordinates(double lo, double hi) {
    std::vector<glm::dvec2> uvs;
    int k = 0;
    for (double u = lo; u <= hi; u += 5.0 / 32.0, ++k) {
        glm::dvec2 uv(u, lo + std::fmod(k * 7.0 / 32.0, hi - lo));
        for (int c = 0; c < 2; ++c)
            if (uv[c] * 4.0 == std::floor(uv[c] * 4.0)) uv[c] += 1.0 / 32.0;  // off the texel edge
        uvs.push_back(uv);
    }
    return uvs;
}

Image renderSamples(const std::string& xml, const std::filesystem::path& folder, size_t count) {
    auto ws = workspaceFromText(xml, folder);
    if (!ws) return {};
    GlRun run = runWorkspace(std::move(ws), {{8, 8}, 1, 1.0f / 60.0f});
    if (!run.exec) return {};
    Image out = readBack(*run.exec, "out");
    EXPECT_EQ(out.width, static_cast<int>(count));
    return out;
}

// rgba32f results of float texture sampling. Nearest: exact. Linear: the weights are exact
// (see coordinates()); the tolerance covers float arithmetic on values up to ~115.
constexpr double linearTolerance = 2e-5;

struct Case {
    const char* name;
    const char* samplerAttributes;
    bool linear;
    WrapRule rule;
    glm::dvec4 border{0.0};
};

void checkCase(const Case& c, const std::filesystem::path& folder, const Image& image, double lo, double hi) {
    SCOPED_TRACE(c.name);
    std::vector<glm::dvec2> uvs = coordinates(lo, hi);
    std::string sampler = std::string(R"(<sampler name="tex" texture="pattern" )") + c.samplerAttributes + "/>";
    Image out = renderSamples(samplingWorkspace(R"(<texture name="pattern" file="pattern.exr" mipmaps="false"/>)",
                                                sampler, uvs),
                              folder, uvs.size());
    ASSERT_EQ(out.width, static_cast<int>(uvs.size()));
    for (size_t i = 0; i < uvs.size(); ++i) {
        glm::dvec4 expected = c.linear ? sampleLinear(image, uvs[i], c.rule, c.border)
                                       : sampleNearest(image, uvs[i], c.rule, c.border);
        for (int ch = 0; ch < 4; ++ch)
            EXPECT_NEAR(out.at(static_cast<int>(i), 0, ch), expected[ch], c.linear ? linearTolerance : 0.0)
                << "uv (" << uvs[i].x << ", " << uvs[i].y << ") channel " << ch;
    }
}

class SamplerFileGLTest : public SamplerGLTest {
protected:
    void SetUp() override {
        SamplerGLTest::SetUp();
        if (HasFatalFailure()) return;
        auto written = writeImage(dir / "pattern.exr", image);
        ASSERT_TRUE(written) << written.error();
    }
    ScratchDir dir;
    Image image = testImage();
};

TEST_F(SamplerFileGLTest, NearestAndLinearFilteringInsideTheImage) {
    checkCase({"nearest", R"(filter="nearest")", false, WrapRule::Clamp}, dir.path(), image, 0.0, 1.0);
    checkCase({"linear", R"(filter="linear")", true, WrapRule::Clamp}, dir.path(), image, 0.0, 1.0);
}

TEST_F(SamplerFileGLTest, WrapModesOutsideTheUnitSquare) {
    const double lo = -1.75, hi = 2.5;
    for (bool linear : {false, true}) {
        std::string filter = linear ? R"(filter="linear" )" : R"(filter="nearest" )";
        std::string repeat = filter + R"(wrap="repeat")", clamp = filter + R"(wrap="clamp")",
                    mirror = filter + R"(wrap="mirror")",
                    border = filter + R"(wrap="border" border="0.25 -2 1000 0.5")";
        checkCase({"repeat", repeat.c_str(), linear, WrapRule::Repeat}, dir.path(), image, lo, hi);
        checkCase({"clamp", clamp.c_str(), linear, WrapRule::Clamp}, dir.path(), image, lo, hi);
        checkCase({"mirror", mirror.c_str(), linear, WrapRule::Mirror}, dir.path(), image, lo, hi);
        checkCase({"border", border.c_str(), linear, WrapRule::Border, {0.25, -2, 1000, 0.5}}, dir.path(), image, lo, hi);
    }
}

TEST_F(SamplerFileGLTest, SeparateWrapModesPerAxis) {
    // wrap-s repeat, wrap-t clamp: the reference wraps each axis with its own rule.
    std::vector<glm::dvec2> uvs = {{-0.40625, 1.59375}, {1.28125, -0.65625}, {2.15625, 0.40625}};
    Image out = renderSamples(
        samplingWorkspace(R"(<texture name="pattern" file="pattern.exr" mipmaps="false"/>)",
                          R"(<sampler name="tex" texture="pattern" filter="nearest" wrap-s="repeat" wrap-t="clamp"/>)",
                          uvs),
        dir.path(), uvs.size());
    ASSERT_EQ(out.width, 3);
    for (size_t k = 0; k < uvs.size(); ++k) {
        int i = wrapIndex(static_cast<int>(std::floor(uvs[k].x * 4)), 4, WrapRule::Repeat);
        int j = wrapIndex(static_cast<int>(std::floor(uvs[k].y * 4)), 4, WrapRule::Clamp);
        glm::dvec4 expected = texelGl(image, i, j);
        for (int ch = 0; ch < 4; ++ch) EXPECT_EQ(out.at(static_cast<int>(k), 0, ch), expected[ch]) << k << " " << ch;
    }
}

TEST_F(SamplerFileGLTest, RowZeroOfTheFileIsTheTopOfTheTexture) {
    // Texel centres of the four corners, compared with the file's pixels directly.
    std::vector<glm::dvec2> uvs = {{0.125, 0.875}, {0.875, 0.875}, {0.125, 0.125}, {0.875, 0.125}};
    const int fileX[4] = {0, 3, 0, 3}, fileY[4] = {0, 0, 3, 3};
    Image out = renderSamples(
        samplingWorkspace(R"(<texture name="pattern" file="pattern.exr"/>)",
                          R"(<sampler name="tex" texture="pattern" filter="nearest"/>)", uvs),
        dir.path(), uvs.size());
    ASSERT_EQ(out.width, 4);
    for (int k = 0; k < 4; ++k)
        for (int ch = 0; ch < 4; ++ch)
            EXPECT_EQ(out.at(k, 0, ch), image.at(fileX[k], fileY[k], ch)) << "corner " << k << " channel " << ch;

    // A pass copying the texture at vTexCoord into a 4x4 target reads back as the file itself
    // (readTarget's row 0 is the top too).
    auto ws = workspaceFromText(R"(<workspace version="1" name="copy" size="4x4">
  <texture name="pattern" file="pattern.exr"/>
  <target name="copy" format="rgba32f" scale="1"/>
  <pass name="copy" target="copy">
    <sampler name="tex" texture="pattern" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D tex;
in vec2 vTexCoord;
out vec4 fragColor;
void main() { fragColor = texture(tex, vTexCoord); }
]]></shader>
  </pass>
</workspace>)",
                                dir.path());
    ASSERT_TRUE(ws);
    GlRun run = runWorkspace(std::move(ws), {{4, 4}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    Image copy = readBack(*run.exec, "copy");
    ASSERT_EQ(copy.width, 4);
    ASSERT_EQ(copy.height, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (int ch = 0; ch < 4; ++ch) EXPECT_EQ(copy.at(x, y, ch), image.at(x, y, ch)) << x << "," << y << " " << ch;
}

TEST_F(SamplerGLTest, SrgbPngIsDecodedToLinear) {
    ScratchDir dir;
    const int bytes[8] = {0, 1, 10, 11, 64, 128, 200, 255};
    Image png;
    png.width = 8;
    png.height = 1;
    png.channels = 4;
    png.pixels.resize(32);
    for (int x = 0; x < 8; ++x) {
        png.at(x, 0, 0) = static_cast<float>(bytes[x]) / 255.0f;
        png.at(x, 0, 1) = static_cast<float>(bytes[7 - x]) / 255.0f;
        png.at(x, 0, 2) = static_cast<float>(bytes[(x + 3) % 8]) / 255.0f;
        png.at(x, 0, 3) = static_cast<float>(bytes[(x + 5) % 8] | 1) / 255.0f;  // alpha never 0
    }
    auto written = writeImage(dir / "ramp.png", png);
    ASSERT_TRUE(written) << written.error();
    std::vector<glm::dvec2> uvs;
    for (int x = 0; x < 8; ++x) uvs.push_back({(x + 0.5) / 8.0, 0.5});
    Image out = renderSamples(
        samplingWorkspace(R"(<texture name="ramp" file="ramp.png" colorspace="srgb" mipmaps="false"/>)",
                          R"(<sampler name="tex" texture="ramp" filter="nearest"/>)", uvs),
        dir.path(), uvs.size());
    ASSERT_EQ(out.width, 8);
    auto decode = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    auto encode = [](double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; };
    // The file holds exactly these bytes.
    auto file = readImage(dir / "ramp.png");
    ASSERT_TRUE(file) << file.error();
    ASSERT_EQ(file->bitsPerChannel, 8);
    for (int x = 0; x < 8; ++x) ASSERT_EQ(file->at(x, 0, 0), bytes[x] / 255.0f) << x;
    // Decoding 8-bit sRGB needs only to round-trip: encoding the result again and rounding to
    // 8 bits gives the original byte (llvmpipe uses a cubic polynomial with about 0.25 step of
    // error, which this allows; exact decoding would be 0 steps off).
    auto expectDecoded = [&](float got, int byte, const char* channel, int x) {
        double expected = decode(byte / 255.0);
        double lo = decode(std::max(byte - 0.5, 0.0) / 255.0), hi = decode(std::min(byte + 0.5, 255.0) / 255.0);
        EXPECT_GE(got, lo) << channel << " byte " << byte << " (exact " << expected << ") at " << x;
        EXPECT_LE(got, hi) << channel << " byte " << byte << " (exact " << expected << ") at " << x;
        EXPECT_EQ(std::lround(encode(got) * 255.0), byte) << channel << " at " << x;
    };
    for (int x = 0; x < 8; ++x) {
        expectDecoded(out.at(x, 0, 0), bytes[x], "red", x);
        expectDecoded(out.at(x, 0, 1), bytes[7 - x], "green", x);
        expectDecoded(out.at(x, 0, 2), bytes[(x + 3) % 8], "blue", x);
        // Alpha stays linear: byte / 255.
        EXPECT_NEAR(out.at(x, 0, 3), (bytes[(x + 5) % 8] | 1) / 255.0, 1e-6) << x;
    }
}

TEST_F(SamplerGLTest, MipmapLevelsOfATargetAreBlockAverages) {
    // Pass 1 writes a 16x16 pattern into a target with mipmaps; pass 2 reads each level with
    // textureLod at texel centres. Level L holds the mean of 2^L x 2^L blocks of level 0.
    auto pattern = [](int x, int y) { return (x * x + 3.0 * y + 0.5 * x * y) / 64.0; };
    struct Sample {
        int level, i, j;
    };
    std::vector<Sample> samples;
    for (int level = 0; level <= 4; ++level) {
        int size = 16 >> level;
        for (int k = 0; k < 3; ++k) samples.push_back({level, (k * 5 + 1) % size, (k * 3 + 2) % size});
    }
    std::ostringstream list;
    for (size_t k = 0; k < samples.size(); ++k) {
        int size = 16 >> samples[k].level;
        list << (k ? ", " : "") << "vec3(" << glslFloat((samples[k].i + 0.5) / size) << ", "
             << glslFloat((samples[k].j + 0.5) / size) << ", " << samples[k].level << ".0)";
    }
    std::ostringstream xml;
    xml << R"(<workspace version="1" name="mips" size="16x16">
  <target name="src" format="rgba32f" scale="1" mipmaps="true"/>
  <target name="out" format="rgba32f" size=")" << samples.size() << R"(x1"/>
  <pass name="pattern" target="src">
    <shader stage="fragment"><![CDATA[
#version 450 core
out vec4 fragColor;
void main() {
    float x = floor(gl_FragCoord.x), y = floor(gl_FragCoord.y);
    fragColor = vec4((x * x + 3.0 * y + 0.5 * x * y) / 64.0, x, y, 1.0);
}
]]></shader>
  </pass>
  <pass name="read" target="out">
    <sampler name="src" target="src" filter="nearest" mipmap="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D src;
out vec4 fragColor;
const vec3 samples[)" << samples.size() << "] = vec3[](" << list.str() << R"();
void main() {
    vec3 s = samples[int(gl_FragCoord.x)];
    fragColor = textureLod(src, s.xy, s.z);
}
]]></shader>
  </pass>
</workspace>)";
    GlRun run = runWorkspace(xml.str(), {{16, 16}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    Image out = readBack(*run.exec, "out");
    ASSERT_EQ(out.width, static_cast<int>(samples.size()));
    for (size_t k = 0; k < samples.size(); ++k) {
        const Sample& s = samples[k];
        int block = 1 << s.level;
        double sum[3] = {0, 0, 0};
        for (int y = s.j * block; y < (s.j + 1) * block; ++y)
            for (int x = s.i * block; x < (s.i + 1) * block; ++x) {
                sum[0] += pattern(x, y);
                sum[1] += x;
                sum[2] += y;
            }
        for (int ch = 0; ch < 3; ++ch) {
            double expected = sum[ch] / (block * block);
            EXPECT_NEAR(out.at(static_cast<int>(k), 0, ch), expected, 1e-5 * std::max(1.0, std::abs(expected)))
                << "level " << s.level << " texel (" << s.i << ", " << s.j << ") channel " << ch;
        }
    }
}

}  // namespace
}  // namespace rmfx::test
