// <input> declarations (parsed, validated) and rmfx render --input: which input an argument
// names, the image read into the input's texture, the viewport it sets, and every error naming
// the argument and the file.

#include "validation/ImageInputs.h"

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "io/image/ImageIO.h"
#include "tests/support/TestSupport.h"
#include "validation/Validation.h"

namespace rmfx {
namespace {

using test::lines;

const std::string kShader =
    "    <shader stage=\"fragment\">uniform sampler2D Image; out vec4 c; void main() { c = texture(Image, vec2(0.5)); }</shader>";

// A workspace of 16x8 whose scene an image may replace, plus an environment input with no file.
std::string twoInputs() {
    return lines({
        "<workspace version=\"1\" name=\"two\" size=\"16x8\">",
        "  <target name=\"scene\" format=\"rgba16f\"/>",
        "  <input name=\"scene\" replaces=\"scene\" description=\"your image\"/>",
        "  <input name=\"env\"/>",
        "  <pass name=\"draw\" target=\"scene\">",
        "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(1.0); }</shader>",
        "  </pass>",
        "  <pass name=\"from_input\" target=\"scene\">",
        "    <sampler name=\"Image\" texture=\"scene\"/>",
        kShader,
        "  </pass>",
        "  <pass name=\"screen\">",
        "    <sampler name=\"Scene\" target=\"scene\"/>",
        "    <sampler name=\"Image\" texture=\"env\"/>",
        kShader,
        "  </pass>",
        "</workspace>",
    });
}

Workspace parsed(const std::string& xml) {
    Result<Workspace> p = parseWorkspaceText(xml, "ws.xml", ".");
    EXPECT_TRUE(p.ok()) << formatAll(p.diagnostics());
    return p ? std::move(*p) : Workspace{};
}

// A w x h RGBA float image whose pixel (x, y) is (x, y, x + y, 1).
Image ramp(int w, int h) {
    Image image;
    image.width = w;
    image.height = h;
    image.channels = 4;
    image.highDynamicRange = true;
    image.pixels.resize(static_cast<size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            image.at(x, y, 0) = static_cast<float>(x);
            image.at(x, y, 1) = static_cast<float>(y);
            image.at(x, y, 2) = static_cast<float>(x + y);
            image.at(x, y, 3) = 1.0f;
        }
    return image;
}

std::filesystem::path writeExr(const test::ScratchDir& dir, const std::string& name, const Image& image) {
    std::filesystem::path file = dir / name;
    Result<void> written = writeImage(file, image);
    EXPECT_TRUE(written.ok()) << written.error();
    return file;
}

TEST(ImageInputs, AnInputDeclaresItsTextureAndWhatItReplaces) {
    Workspace ws = parsed(twoInputs());
    ASSERT_EQ(ws.inputs.size(), 2u);
    EXPECT_EQ(ws.inputs[0].name, "scene");
    EXPECT_EQ(ws.inputs[0].replaces, "scene");
    EXPECT_TRUE(ws.inputs[0].sizesViewport);  // it replaces a target
    EXPECT_EQ(ws.inputs[0].description, "your image");
    EXPECT_EQ(ws.inputs[0].where.line, 3);
    EXPECT_FALSE(ws.inputs[1].sizesViewport);
    const Texture* texture = ws.findTexture("scene");
    ASSERT_NE(texture, nullptr);
    EXPECT_EQ(texture->kind, TextureKind::Texture2D);
    EXPECT_TRUE(texture->files.empty());
    EXPECT_FALSE(texture->mipmaps);
    EXPECT_EQ(texture->where.line, 3);
    EXPECT_TRUE(validateWorkspace(ws, {.compileShaders = false}).ok());
}

TEST(ImageInputs, AnInputWithAFileKeepsItWhenNoImageIsGiven) {
    Workspace ws = parsed(lines({"<workspace version=\"1\">",
                                 "  <input name=\"Input\" file=\"photo.exr\" viewport=\"image\" colorspace=\"srgb\"/>",
                                 "  <pass name=\"screen\">", "    <sampler name=\"Image\" texture=\"Input\"/>", kShader,
                                 "  </pass>", "</workspace>"}));
    EXPECT_TRUE(ws.inputs.at(0).sizesViewport);
    EXPECT_EQ(ws.findTexture("Input")->files, (std::vector<std::string>{"photo.exr"}));
    EXPECT_EQ(ws.findTexture("Input")->colorSpace, ColorSpace::Srgb);
}

TEST(ImageInputs, DeclarationErrorsNameTheLineAndTheInput) {
    auto errors = [](const std::string& body) {
        Result<Workspace> p = parseWorkspaceText(lines({"<workspace version=\"1\">", body, "  <pass name=\"draw\" target=\"scene\">",
                                                        "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(1.0); }</shader>",
                                                        "  </pass>", "  <pass name=\"screen\">",
                                                        "    <sampler name=\"Image\" target=\"scene\"/>", kShader,
                                                        "  </pass>", "  <target name=\"scene\" format=\"rgba16f\"/>", "</workspace>"}),
                                                 "ws.xml", ".");
        if (!p) return formatAll(p.diagnostics());
        return formatAll(validateWorkspace(*p, {.compileShaders = false}).diagnostics());
    };
    EXPECT_EQ(errors("  <input name=\"photo\" replaces=\"sceen\"/>"),
              "ws.xml:2: error: <input name=\"photo\">: replaces target 'sceen', which is not declared (it has: scene; "
              "the output is 'output')\n");
    EXPECT_EQ(errors("  <input name=\"photo\" replaces=\"scene\"/>"),
              "ws.xml:2: error: <input name=\"photo\">: replaces target 'scene', but no pass samples input 'photo': "
              "nothing would put the image into 'scene'\n");
    EXPECT_EQ(errors("  <input name=\"photo\"/>"),
              "ws.xml:2: warning: <input name=\"photo\">: no pass samples input 'photo': an image given for it is not used\n");
    EXPECT_NE(errors("  <input name=\"photo\" replaces=\"scene\" file=\"a.exr\"/>")
                  .find("an input that replaces a target has no default file"),
              std::string::npos);
    EXPECT_NE(errors("  <input name=\"photo\" viewport=\"huge\"/>").find("viewport"), std::string::npos);
    EXPECT_NE(errors("  <texture name=\"photo\" file=\"a.png\"/>\n  <input name=\"photo\"/>")
                  .find("<input name=\"photo\">: duplicate texture name 'photo' (first declared at line 2)"),
              std::string::npos);
}

TEST(ImageInputs, ArgumentsNameAnInputOrOnlyAFile) {
    InputArgument named = parseInputArgument("scene=shots/a.exr");
    EXPECT_EQ(named.name, "scene");
    EXPECT_EQ(named.file, "shots/a.exr");
    EXPECT_EQ(named.text, "scene=shots/a.exr");
    InputArgument bare = parseInputArgument("shots/a.exr");
    EXPECT_EQ(bare.name, "");
    EXPECT_EQ(bare.file, "shots/a.exr");
    // What comes before '=' is no identifier: a file name.
    EXPECT_EQ(parseInputArgument("my-shot=1.exr").name, "");
    EXPECT_EQ(parseInputArgument("my-shot=1.exr").file, "my-shot=1.exr");
    // An existing file whose name looks like NAME=FILE is the file.
    test::ScratchDir dir;
    std::filesystem::path odd = writeExr(dir, "scene=odd.exr", ramp(2, 2));
    EXPECT_EQ(parseInputArgument(odd.string()).name, "");
    EXPECT_EQ(parseInputArgument(odd.string()).file, odd);
}

TEST(ImageInputs, AnImageFillsItsInputAndSetsTheViewport) {
    test::ScratchDir dir;
    std::filesystem::path file = writeExr(dir, "shot.exr", ramp(7, 5));
    Workspace ws = parsed(twoInputs());
    Result<SuppliedInputs> supplied = supplyInputs(ws, {parseInputArgument("scene=" + file.string())}, std::nullopt);
    ASSERT_TRUE(supplied.ok()) << formatAll(supplied.diagnostics());
    EXPECT_EQ(supplied->given, (std::set<std::string>{"scene"}));
    EXPECT_EQ(supplied->viewport, glm::ivec2(7, 5));
    const std::shared_ptr<const Image>& image = ws.findTexture("scene")->supplied;
    ASSERT_TRUE(image);
    ASSERT_EQ(image->width, 7);
    ASSERT_EQ(image->channels, 4);
    EXPECT_EQ(image->at(6, 4, 0), 6.0f);
    EXPECT_EQ(image->at(6, 4, 1), 4.0f);
    EXPECT_EQ(image->at(6, 4, 2), 10.0f);
    EXPECT_EQ(ws.findTexture("env")->supplied, nullptr);
}

TEST(ImageInputs, AGivenSizeResamplesTheImageThatSetsTheViewportAndSaysSo) {
    test::ScratchDir dir;
    Image flat = ramp(8, 4);
    for (float& v : flat.pixels) v = 2.5f;
    std::filesystem::path file = writeExr(dir, "flat.exr", flat);
    Workspace ws = parsed(twoInputs());
    Result<SuppliedInputs> supplied = supplyInputs(ws, {parseInputArgument("scene=" + file.string())}, glm::ivec2(3, 5));
    ASSERT_TRUE(supplied.ok()) << formatAll(supplied.diagnostics());
    EXPECT_EQ(supplied->viewport, glm::ivec2(3, 5));
    const Image& image = *ws.findTexture("scene")->supplied;
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 5);
    for (float v : image.pixels) EXPECT_NEAR(v, 2.5f, 1e-5f);  // a constant stays that constant
    EXPECT_NE(formatAll(supplied.diagnostics()).find("resampled from 8x4 to 3x5 (triangle filter)"), std::string::npos)
        << formatAll(supplied.diagnostics());
    // An input that does not set the viewport keeps its own size.
    Workspace other = parsed(twoInputs());
    Result<SuppliedInputs> env = supplyInputs(other, {parseInputArgument("env=" + file.string())}, glm::ivec2(3, 5));
    ASSERT_TRUE(env.ok()) << formatAll(env.diagnostics());
    EXPECT_EQ(other.findTexture("env")->supplied->width, 8);
}

TEST(ImageInputs, BadArgumentsAreErrorsNamingTheArgument) {
    test::ScratchDir dir;
    std::filesystem::path file = writeExr(dir, "shot.exr", ramp(4, 4));
    Workspace ws = parsed(twoInputs());
    auto error = [&](std::vector<std::string> arguments) {
        std::vector<InputArgument> parsedArguments;
        for (const std::string& a : arguments) parsedArguments.push_back(parseInputArgument(a));
        Result<SuppliedInputs> supplied = supplyInputs(ws, parsedArguments, std::nullopt);
        EXPECT_FALSE(supplied.ok());
        return supplied.error();
    };
    EXPECT_EQ(error({file.string()}), "ws.xml: error: --input " + file.string() +
                                          ": name the input: --input NAME=FILE (its inputs: 'scene', 'env')");
    EXPECT_EQ(error({"sky=" + file.string()}),
              "ws.xml: error: --input sky=" + file.string() + ": the workspace has no input 'sky' (its inputs: 'scene', 'env')");
    EXPECT_EQ(error({"scene=" + file.string(), "scene=" + file.string()}),
              "ws.xml: error: --input scene=" + file.string() + ": input 'scene' is already given by --input scene=" +
                  file.string());
    std::string missing = error({"scene=" + (dir / "nope.exr").string()});
    EXPECT_NE(missing.find((dir / "nope.exr").string()), std::string::npos) << missing;
    EXPECT_NE(missing.find("--input scene="), std::string::npos) << missing;
    EXPECT_EQ(ws.findTexture("scene")->supplied, nullptr);  // nothing half-supplied
}

TEST(ImageInputs, AnImageOverTheSizeLimitIsRefusedBeforeItIsRead) {
    test::ScratchDir dir;
    std::filesystem::path file = writeExr(dir, "wide.exr", ramp(40, 2));
    Workspace ws = parsed(twoInputs());
    Result<SuppliedInputs> supplied = supplyInputs(ws, {parseInputArgument("scene=" + file.string())}, std::nullopt, 32);
    ASSERT_FALSE(supplied.ok());
    EXPECT_NE(supplied.error().find("40x2"), std::string::npos) << supplied.error();
    EXPECT_NE(supplied.error().find(file.string()), std::string::npos) << supplied.error();
}

}  // namespace
}  // namespace rmfx
