// File references end to end: what the rmfx binary renders from a texture found through
// backslashes, case and --media; --sandbox on render and validate; replay sandboxing by default
// (a manifest's sandbox="false" or <media>, or --no-sandbox, to allow more); a DDS cube map in
// one file sampled by direction.

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/DdsBytes.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;

class CliMediaGLTest : public GlTest {};

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A 2x2 workspace whose output is the texture read at texel (0, 0) of the file's top row, which
// it names as `reference`.
std::string copyWorkspace(const std::string& reference) {
    return lines({
        "<workspace version=\"1\" name=\"copy\" size=\"2x2\">",
        "  <texture name=\"tex\" file=\"" + reference + "\" mipmaps=\"false\"/>",
        "  <pass name=\"copy\">",
        "    <sampler name=\"src\" texture=\"tex\" filter=\"nearest\"/>",
        "    <shader stage=\"fragment\"><![CDATA[",
        "#version 450 core",
        "uniform sampler2D src;",
        "out vec4 fragColor;",
        "void main() { fragColor = texelFetch(src, ivec2(0, 1), 0); }",
        "]]></shader>",
        "  </pass>",
        "</workspace>",
    });
}

// A 2x2 RGBA float image whose top-left texel is `value`.
void writeTexture(const fs::path& file, glm::vec4 value) {
    Image image;
    image.width = image.height = 2;
    image.channels = 4;
    image.pixels.assign(16, 0.0f);
    for (int c = 0; c < 4; ++c) image.at(0, 0, c) = value[c];
    fs::create_directories(file.parent_path());
    ASSERT_TRUE(writeImage(file, image));
}

}  // namespace

TEST_F(CliMediaGLTest, RenderOpensTheFileFoundThroughBackslashesCaseAndTheMediaPath) {
    ScratchDir dir;
    writeTexture(dir / "Examples/Media/Textures/Stone.exr", {0.25f, 0.5f, 0.75f, 1.0f});
    dir.write("GL2/copy.xml", copyWorkspace("C:\\RenderMonkey\\Examples\\MEDIA\\textures\\stone.EXR"));
    CommandResult without = runRmfx("render GL2/copy.xml -o out.exr", dir.path());
    EXPECT_EQ(without.status, 1);
    EXPECT_TRUE(has(without.err, "GL2/copy.xml:2: error: <texture name=\"tex\">: image file")) << without.err;

    CommandResult r = runRmfx("render GL2/copy.xml -o out.exr -q --media Examples", dir.path());
    ASSERT_EQ(r.status, 0) << r.err;
    auto out = readImage(dir / "out.exr");
    ASSERT_TRUE(out) << out.error();
    EXPECT_EQ(out->at(0, 0, 0), 0.25f);
    EXPECT_EQ(out->at(0, 0, 1), 0.5f);
    EXPECT_EQ(out->at(0, 0, 2), 0.75f);

    CommandResult bad = runRmfx("render GL2/copy.xml --media no-such-folder", dir.path());
    EXPECT_EQ(bad.status, 1);
    EXPECT_EQ(bad.err, "rmfx render: --media: 'no-such-folder' is not a folder\n");
}

TEST_F(CliMediaGLTest, SandboxOnRenderAndValidate) {
    ScratchDir dir;
    writeTexture(dir / "shared/stone.exr", {1.0f, 0.0f, 0.0f, 1.0f});
    dir.write("ws/copy.xml", copyWorkspace("../shared/stone.exr"));
    EXPECT_EQ(runRmfx("validate ws/copy.xml", dir.path()).status, 0);
    CommandResult v = runRmfx("validate --sandbox ws/copy.xml", dir.path());
    EXPECT_EQ(v.status, 1);
    EXPECT_TRUE(has(v.err, "ws/copy.xml:2: error: <texture name=\"tex\">: image file '../shared/stone.exr' leads "
                           "outside the sandbox: it is " +
                               fs::canonical(dir / "shared/stone.exr").string()))
        << v.err;
    EXPECT_EQ(runRmfx("validate ws/copy.xml --sandbox --media shared", dir.path()).status, 0);

    CommandResult r = runRmfx("render ws/copy.xml --sandbox -o out.exr", dir.path());
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(has(r.err, "leads outside the sandbox")) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.exr"));
    EXPECT_EQ(runRmfx("render ws/copy.xml --sandbox --media shared -q -o out.exr", dir.path()).status, 0);
}

TEST_F(CliMediaGLTest, ReplaySandboxesByDefault) {
    ScratchDir dir;
    writeTexture(dir / "shared/stone.exr", {1.0f, 0.0f, 0.0f, 1.0f});
    dir.write("ws/copy.xml", copyWorkspace("../shared/stone.exr"));
    auto manifest = [&](const std::string& root, const std::string& media) {
        return lines({root, media, "  <case name=\"copy\" workspace=\"ws/copy.xml\">",
                      "    <compare reference=\"refs/copy.exr\"/>", "  </case>", "</replay>"});
    };
    dir.write("plain.xml", manifest("<replay version=\"1\">", ""));
    CommandResult refused = runRmfx("replay plain.xml --update --out out", dir.path());
    EXPECT_EQ(refused.status, 1);
    EXPECT_TRUE(has(refused.err + refused.out, "image file '../shared/stone.exr' leads outside the sandbox"))
        << refused.err << refused.out;
    EXPECT_FALSE(fs::exists(dir / "refs/copy.exr"));

    CommandResult cli = runRmfx("replay plain.xml --update --out out --no-sandbox", dir.path());
    EXPECT_EQ(cli.status, 0) << cli.err << cli.out;
    fs::remove(dir / "refs/copy.exr");
    CommandResult media = runRmfx("replay plain.xml --update --out out --media shared", dir.path());
    EXPECT_EQ(media.status, 0) << media.err << media.out;

    dir.write("off.xml", manifest("<replay version=\"1\" sandbox=\"false\">", ""));
    EXPECT_EQ(runRmfx("replay off.xml --out out", dir.path()).status, 0);
    dir.write("declared.xml", manifest("<replay version=\"1\">", "  <media dir=\"shared\"/>"));
    EXPECT_EQ(runRmfx("replay declared.xml --out out", dir.path()).status, 0);
    // --sandbox wins over a manifest that turns it off.
    EXPECT_EQ(runRmfx("replay off.xml --out out --sandbox", dir.path()).status, 1);
}

TEST_F(CliMediaGLTest, DdsCubeMapInOneFileIsSampledByDirection) {
    ScratchDir dir;
    using namespace dds;
    Bytes b = header("DXT1", kCubeMap | kAllFaces);
    for (uint16_t c : {kRed, kGreen, kBlue, kYellow, kMagenta, kWhite}) colorBlock(b, c, 0, kAllZero);
    writeBytes(dir, "sky.dds", b);
    // Pixel i looks along the axis of face i (+x -x +y -y +z -z).
    auto ws = workspaceFromText(lines({
                                    "<workspace version=\"1\" name=\"sky\" size=\"6x1\">",
                                    "  <cubemap name=\"sky\" file=\"sky.dds\" mipmaps=\"false\"/>",
                                    "  <target name=\"faces\" format=\"rgba32f\" scale=\"1\"/>",
                                    "  <pass name=\"look\" target=\"faces\">",
                                    "    <sampler name=\"env\" texture=\"sky\" filter=\"nearest\"/>",
                                    "    <shader stage=\"fragment\"><![CDATA[",
                                    "#version 450 core",
                                    "uniform samplerCube env;",
                                    "out vec4 fragColor;",
                                    "const vec3 axes[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0),",
                                    "                             vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1));",
                                    "void main() { fragColor = texture(env, axes[int(gl_FragCoord.x)]); }",
                                    "]]></shader>",
                                    "  </pass>",
                                    "</workspace>",
                                }),
                                dir.path());
    ASSERT_TRUE(ws);
    GlRun run = runWorkspace(std::move(ws), {{6, 1}, 1, 1.0f / 60.0f});
    ASSERT_TRUE(run.exec);
    auto faces = run.exec->readTarget("faces");
    ASSERT_TRUE(faces) << faces.error();
    const glm::vec3 expected[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {1, 1, 1}};
    for (int i = 0; i < 6; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(faces->at(i, 0, c), expected[i][c]) << "face " << i << " channel " << c;
}

}  // namespace rmfx::test

namespace rmfx::test {

// --missing-media placeholder: a missing texture and cube map read as the magenta and grey
// checker, a missing model named like a torus draws exactly as the built-in torus, one warning
// each; without it the same files are errors. `rmfx list` says which media are missing.
TEST_F(CliMediaGLTest, MissingMediaPlaceholdersRenderWithAWarningPerFile) {
    ScratchDir dir;
    auto workspace = [](const std::string& draw) {
        return lines({
            "<workspace version=\"1\" name=\"missing\" size=\"64x64\">",
            "  <texture name=\"stone\" file=\"C:\\RenderMonkey\\Media\\Fieldstone.tga\" mipmaps=\"false\"/>",
            "  <cubemap name=\"sky\" file=\"C:\\RenderMonkey\\Media\\Sky.dds\"/>",
            "  <output format=\"rgba32f\"/>",
            "  <pass name=\"show\">",
            "    <sampler name=\"stoneMap\" texture=\"stone\" filter=\"nearest\"/>",
            "    <sampler name=\"skyMap\" texture=\"sky\" filter=\"nearest\"/>",
            "    " + draw,
            "    <shader stage=\"fragment\"><![CDATA[",
            "#version 450 core",
            "uniform sampler2D stoneMap;",
            "uniform samplerCube skyMap;",
            "out vec4 fragColor;",
            "void main() {",
            "    ivec2 p = ivec2(gl_FragCoord.xy);",
            "    fragColor = vec4(texelFetch(stoneMap, p, 0).rg, texture(skyMap, vec3(1.0, 0.3, -0.2)).rb);",
            "}",
            "]]></shader>",
            "  </pass>",
            "</workspace>",
        });
    };
    dir.write("fx.xml", workspace(""));
    CommandResult strict = runRmfx("render fx.xml -o strict.exr", dir.path());
    EXPECT_EQ(strict.status, 1);
    EXPECT_TRUE(has(strict.err, "fx.xml:2: error: <texture name=\"stone\">: image file")) << strict.err;
    EXPECT_TRUE(has(strict.err, "fx.xml:3: error: <cubemap name=\"sky\">: image file")) << strict.err;

    CommandResult r = runRmfx("render fx.xml -o out.exr --missing-media placeholder", dir.path());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(has(r.err, "fx.xml:2: warning: <texture name=\"stone\">: image file 'C:\\RenderMonkey\\Media\\Fieldstone.tga' not found"))
        << r.err;
    EXPECT_TRUE(has(r.err, "; a magenta and grey checker stands in for the texture (--missing-media placeholder)")) << r.err;
    EXPECT_TRUE(has(r.err, "fx.xml:3: warning: <cubemap name=\"sky\">")) << r.err;
    auto out = readImage(dir / "out.exr");
    ASSERT_TRUE(out) << out.error();
    // Every texel of the 2D placeholder is magenta (r 1, g 0) or grey (0.2, 0.2), in 8x8 squares.
    int magenta = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const float red = out->at(x, y, 0), green = out->at(x, y, 1);
            const bool isMagenta = red == 1.0f && green == 0.0f, isGrey = red == 0.2f && green == 0.2f;
            ASSERT_TRUE(isMagenta || isGrey) << "pixel " << x << "," << y << ": " << red << " " << green;
            magenta += isMagenta;
            if (x + 8 < 64) {
                EXPECT_NE(out->at(x + 8, y, 0), red) << "pixel " << x << "," << y;
            }
            if (x % 8) {
                EXPECT_EQ(out->at(x - 1, y, 0), red) << "pixel " << x << "," << y;
            }
        }
    EXPECT_EQ(magenta, 64 * 64 / 2);
    // The cube map's sample: magenta (r 1, b 1) or grey (0.2, 0.2).
    const float skyRed = out->at(5, 5, 2), skyBlue = out->at(5, 5, 3);
    EXPECT_TRUE((skyRed == 1.0f && skyBlue == 1.0f) || (skyRed == 0.2f && skyBlue == 0.2f)) << skyRed << " " << skyBlue;

    // A missing model named like a torus: the built-in torus, pixel for pixel.
    const std::string shade = "fragColor = vec4(gl_FragCoord.z, 0.5, 0.25, 1.0);";
    auto modelWorkspace = [&](const std::string& draw) {
        std::string text = workspace(draw);
        text.replace(text.find("fragColor = vec4(texelFetch"), std::string("fragColor = vec4(texelFetch(stoneMap, p, 0).rg, texture(skyMap, vec3(1.0, 0.3, -0.2)).rb);").size(), shade);
        return text;
    };
    dir.write("model.xml", modelWorkspace("<draw file=\"..\\Models\\Donut_Torus.3ds\"/>"));
    dir.write("torus.xml", modelWorkspace("<draw mesh=\"torus\"/>"));
    CommandResult model = runRmfx("render model.xml -o model.exr --missing-media placeholder", dir.path());
    ASSERT_EQ(model.status, 0) << model.err;
    EXPECT_TRUE(has(model.err, "model.xml:8: warning: <draw>: model file '..\\Models\\Donut_Torus.3ds' not found")) << model.err;
    EXPECT_TRUE(has(model.err, "drawing rmfx's built-in 'torus' in its place (--missing-media placeholder)")) << model.err;
    ASSERT_EQ(runRmfx("render torus.xml -o torus.exr -q --missing-media placeholder", dir.path()).status, 0);
    auto drawn = readImage(dir / "model.exr"), torus = readImage(dir / "torus.exr");
    ASSERT_TRUE(drawn && torus);
    EXPECT_EQ(drawn->pixels, torus->pixels);
    int covered = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) covered += torus->at(x, y, 1) == 0.5f;
    EXPECT_GT(covered, 200);  // the torus is in view, not an empty frame twice
}

TEST_F(CliMediaGLTest, ListShowsWhichMediaAreMissingAndWhatStandsIn) {
    ScratchDir dir;
    std::string rfx = readText(sourceDir() / "tests" / "rfx" / "lit_teapot.rfx");
    dir.write("lit.rfx", rfx);
    dir.write("Media/Textures/ramp.png", "");  // found by name through --media (list does not read it)
    CommandResult plain = runRmfx("list lit.rfx", dir.path());
    ASSERT_EQ(plain.status, 0) << plain.err;
    EXPECT_TRUE(has(plain.out, "    media files: 2 of 2 missing\n")) << plain.out;
    EXPECT_TRUE(has(plain.out, "      ..\\Media\\Textures\\RAMP.PNG: missing (an error; --missing-media placeholder renders with a stand-in)\n"))
        << plain.out;
    EXPECT_TRUE(has(plain.out, "Teapot.3ds: missing; rmfx's built-in 'teapot' stands in\n")) << plain.out;

    CommandResult found = runRmfx("list lit.rfx --media Media --missing-media placeholder", dir.path());
    ASSERT_EQ(found.status, 0) << found.err;
    EXPECT_TRUE(has(found.out, "    media files: 1 of 2 missing\n")) << found.out;
    EXPECT_TRUE(has(found.out, "      ..\\Media\\Textures\\RAMP.PNG → " + fs::weakly_canonical(dir / "Media/Textures/ramp.png").generic_string()))
        << found.out;
    EXPECT_EQ(runRmfx("list lit.rfx --missing-media sometimes", dir.path()).status, 1);
}

}  // namespace rmfx::test
