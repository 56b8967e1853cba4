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
