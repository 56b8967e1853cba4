// rmfx render --texture NAME=FILE: parsing the argument, and the texture's files replaced for the
// run (a 2D texture, a cube map from one image or six faces), with an error naming the argument
// for each mistake. The cube map's image is read and its layout recognised by CliTextureGLTest.

#include "validation/TextureArguments.h"

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

using test::ScratchDir;
using test::sourceDir;

TEST(TextureArguments, ParsesNameAndOneFileOrSixFaces) {
    auto one = parseTextureArgument("Sky_Float=env/probe.exr");
    ASSERT_TRUE(one) << one.error();
    EXPECT_EQ(one->name, "Sky_Float");
    ASSERT_EQ(one->files.size(), 1u);
    EXPECT_EQ(one->files[0], "env/probe.exr");
    auto six = parseTextureArgument("Sky=px.hdr,nx.hdr,py.hdr,ny.hdr,pz.hdr,nz.hdr");
    ASSERT_TRUE(six);
    ASSERT_EQ(six->files.size(), 6u);
    EXPECT_EQ(six->files[5], "nz.hdr");
    for (const char* bad : {"probe.exr", "=probe.exr", "Sky=", "Sky=a.exr,,b.exr"}) {
        auto parsed = parseTextureArgument(bad);
        ASSERT_FALSE(parsed) << bad;
        EXPECT_EQ(parsed.error().rfind(std::string("--texture ") + bad + ": ", 0), 0u) << parsed.error();
    }
}

TEST(TextureArguments, ACubeMapTakesOneImageToRecogniseOrSixFaces) {
    ScratchDir dir;
    for (const char* name : {"env.exr", "px.exr", "nx.exr", "py.exr", "ny.exr", "pz.exr", "nz.exr"}) dir.write(name, "x");
    Result<Workspace> loaded = loadWorkspace(sourceDir() / "effects" / "shader_1.xml");
    ASSERT_TRUE(loaded) << formatAll(loaded.diagnostics());
    Workspace ws = *loaded;
    auto one = parseTextureArgument("Sky_Float=" + (dir / "env.exr").string());
    ASSERT_TRUE(one);
    ASSERT_TRUE(replaceTextures(ws, {*one}).ok());
    const Texture* sky = ws.findTexture("Sky_Float");
    ASSERT_EQ(sky->files.size(), 1u);
    EXPECT_EQ(std::filesystem::path(sky->files[0]), (dir / "env.exr").lexically_normal());
    EXPECT_EQ(sky->layout, CubeLayout::FromImage);
    EXPECT_EQ(sky->fileLocations[0].file, "--texture");
    // The other cube map keeps its file.
    EXPECT_EQ(ws.findTexture("Sky_Alpha64")->files, loaded->findTexture("Sky_Alpha64")->files);

    Workspace faces = *loaded;
    std::string list;
    for (const char* name : {"px.exr", "nx.exr", "py.exr", "ny.exr", "pz.exr", "nz.exr"})
        list += (list.empty() ? "" : ",") + (dir / name).string();
    auto six = parseTextureArgument("Sky_Alpha64=" + list);
    ASSERT_TRUE(six);
    ASSERT_TRUE(replaceTextures(faces, {*six}).ok());
    EXPECT_EQ(faces.findTexture("Sky_Alpha64")->layout, CubeLayout::Faces);
    EXPECT_EQ(faces.findTexture("Sky_Alpha64")->files.size(), 6u);
}

TEST(TextureArguments, EveryMistakeIsAnErrorNamingTheArgument) {
    ScratchDir dir;
    dir.write("a.exr", "x");
    dir.write("b.exr", "x");
    Result<Workspace> loaded = loadWorkspace(sourceDir() / "effects" / "shader_1.xml");
    ASSERT_TRUE(loaded);
    const std::string a = (dir / "a.exr").string(), b = (dir / "b.exr").string();
    struct Case {
        std::string argument, message;
    };
    for (const Case& c : std::vector<Case>{
             {"Nope=" + a, "the workspace has no texture 'Nope' (its textures: 'Sky_Alpha64', 'Sky_Float')"},
             {"scene=" + a, "'scene' is an <input>: give its image with --input scene=FILE"},
             {"Sky_Float=" + a + "," + b,
              "'Sky_Float' is a cube map: give one image (2:1 longitude/latitude, 4:3 or 3:4 cross, or a DDS cube "
              "map) or six faces (+x,-x,+y,-y,+z,-z), not 2"},
             {"Sky_Float=" + (dir / "missing.exr").string(), (dir / "missing.exr").string() + ": no such file"},
         }) {
        Workspace ws = *loaded;
        auto parsed = parseTextureArgument(c.argument);
        ASSERT_TRUE(parsed) << c.argument;
        Result<void> replaced = replaceTextures(ws, {*parsed});
        ASSERT_FALSE(replaced) << c.argument;
        ASSERT_EQ(replaced.diagnostics().size(), 1u);
        const Diagnostic& d = replaced.diagnostics()[0];
        EXPECT_EQ(d.element, "--texture " + c.argument);
        EXPECT_EQ(d.message, c.message);
        EXPECT_EQ(d.where.file, ws.path.string());
    }
    Workspace ws = *loaded;
    auto first = parseTextureArgument("Sky_Float=" + a), second = parseTextureArgument("Sky_Float=" + b);
    Result<void> twice = replaceTextures(ws, {*first, *second});
    ASSERT_FALSE(twice);
    EXPECT_EQ(twice.diagnostics()[0].message, "texture 'Sky_Float' is given twice");
}

}  // namespace
}  // namespace rmfx
