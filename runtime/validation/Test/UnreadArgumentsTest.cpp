// Arguments that would change nothing are found from the frame plan, without GL; read-when
// is checked like every other reference of a workspace.
#include "validation/UnreadArguments.h"

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

using Lines = std::vector<std::string>;

// Two skies a variable chooses between, a mask only a disabled pass samples, and an input only
// the effect "extra" reads.
std::string workspaceXml(const std::string& readWhen) {
    return test::lines({
        R"(<workspace version="1" name="w" size="4x4">)",
        R"(  <int name="Sky_Format" value="0"/>)",
        R"(  <texture name="Sky_A" file="a.png" read-when="Sky_Format=0"/>)",
        R"(  <texture name="Sky_B" file="a.png" read-when=")" + readWhen + R"("/>)",
        R"(  <texture name="Mask" file="a.png"/>)",
        R"(  <input name="plate"/>)",
        R"(  <effect name="extra" passes="extra"/>)",
        R"(  <pass name="sky"><sampler name="A" texture="Sky_A"/><sampler name="B" texture="Sky_B"/>)",
        R"(    <shader stage="fragment">uniform sampler2D A, B; out vec4 c; void main() { c = texture(A, vec2(0)) + texture(B, vec2(0)); }</shader></pass>)",
        R"(  <pass name="masked" enabled="false"><sampler name="M" texture="Mask"/>)",
        R"(    <shader stage="fragment">uniform sampler2D M; out vec4 c; void main() { c = texture(M, vec2(0)); }</shader></pass>)",
        R"(  <pass name="extra"><blend mode="add"/><sampler name="P" texture="plate"/>)",
        R"(    <shader stage="fragment">uniform sampler2D P; out vec4 c; void main() { c = texture(P, vec2(0)); }</shader></pass>)",
        R"(</workspace>)",
    });
}

Lines formatted(const Diagnostics& diagnostics) {
    Lines out;
    for (const Diagnostic& d : diagnostics) out.push_back(d.format());
    return out;
}

WorkspaceLoadOptions withPlaceholders() {
    WorkspaceLoadOptions load;
    load.media.missing = MissingMedia::Placeholder;  // the textures' files do not matter here
    return load;
}

TEST(UnreadArguments, ATextureReadOnlyWhileAVariableHasAnotherValueNamesTheSetting) {
    test::ScratchDir dir;
    const auto file = dir.write("w.xml", workspaceXml("Sky_Format=1"));
    Result<Workspace> ws = loadWorkspace(file, {}, withPlaceholders());
    ASSERT_TRUE(ws.ok()) << formatAll(ws.diagnostics());
    const std::string w = file.string();
    const std::vector<TextureArgument> textures{{"Sky_A", {"x.exr"}, "Sky_A=x.exr"},
                                                {"Sky_B", {"y.exr"}, "Sky_B=y.exr"},
                                                {"Mask", {"m.png"}, "Mask=m.png"}};
    const std::vector<InputArgument> inputs{{"plate", "p.exr", "", "plate=p.exr", nullptr}};
    FramePlanOptions options;
    options.effects = std::vector<std::string>{};
    options.givenInputs = {"plate"};
    EXPECT_EQ(formatted(unreadArgumentWarnings(*ws, options, textures, inputs)),
              (Lines{w + ": warning: --texture Sky_B=y.exr: the passes read texture 'Sky_B' only while Sky_Format is 1 (it is "
                         "0), so the file changes nothing: add --set Sky_Format=1",
                     w + ": warning: --texture Mask=m.png: no pass that runs samples texture 'Mask', so the file changes "
                         "nothing; pass 'masked': culled: disabled, enabled=\"false\"",
                     w + ": warning: --input plate=p.exr: no pass that runs samples input 'plate', so the image changes "
                         "nothing; pass 'extra': culled: effect left out, effect 'extra' not asked for (asked for: none)"}));

    // The setting given, and the effect asked for: nothing to say about them.
    ASSERT_TRUE(applyOverrides(*ws, {{"Sky_Format", "1"}}));
    options.effects = std::vector<std::string>{"extra"};
    EXPECT_EQ(formatted(unreadArgumentWarnings(*ws, options, {textures[1]}, inputs)), Lines{});
}

TEST(UnreadArguments, ReadWhenNamesADeclaredVariableAndAValueOfItsType) {
    test::ScratchDir dir;
    for (const auto& [readWhen, message] : std::vector<std::pair<std::string, std::string>>{
             {"Nothing=1", "read-when names 'Nothing', which is not a declared variable"},
             {"Sky_Format=x", "read-when: 'x' is not a value of int variable 'Sky_Format' (line 2)"},
             {"Sky_Format", "attribute 'read-when' is VARIABLE=VALUE"}}) {
        const auto file = dir.write("w.xml", workspaceXml(readWhen));
        Result<Workspace> ws = loadWorkspace(file, {}, withPlaceholders());
        ASSERT_FALSE(ws.ok()) << readWhen;
        const std::string all = formatAll(ws.diagnostics());
        EXPECT_NE(all.find(file.string() + ":4: error: "), std::string::npos) << all;
        EXPECT_NE(all.find(message), std::string::npos) << all;
    }
}

// An --input that replaces the target a texture's pass draws culls that pass: the texture
// given with it changes nothing (shader_1's sky with --input).
TEST(UnreadArguments, ATextureOnlyTheReplacedPassesSampleIsUnread) {
    test::ScratchDir dir;
    const auto file = dir.write("w.xml", test::lines({
        R"(<workspace version="1" name="w" size="4x4">)",
        R"(  <texture name="Sky" file="a.png"/>)",
        R"(  <target name="scene" format="rgba16f"/>)",
        R"(  <input name="photo" replaces="scene"/>)",
        R"(  <pass name="sky" target="scene"><sampler name="S" texture="Sky"/>)",
        R"(    <shader stage="fragment">uniform sampler2D S; out vec4 c; void main() { c = texture(S, vec2(0)); }</shader></pass>)",
        R"(  <pass name="from_photo" target="scene"><sampler name="P" texture="photo"/>)",
        R"(    <shader stage="fragment">uniform sampler2D P; out vec4 c; void main() { c = texture(P, vec2(0)); }</shader></pass>)",
        R"(  <pass name="screen"><sampler name="T" target="scene"/>)",
        R"(    <shader stage="fragment">uniform sampler2D T; out vec4 c; void main() { c = texture(T, vec2(0)); }</shader></pass>)",
        R"(</workspace>)",
    }));
    Result<Workspace> ws = loadWorkspace(file, {}, withPlaceholders());
    ASSERT_TRUE(ws.ok()) << formatAll(ws.diagnostics());
    const std::vector<TextureArgument> sky{{"Sky", {"x.exr"}, "Sky=x.exr"}};
    FramePlanOptions options;
    EXPECT_EQ(formatted(unreadArgumentWarnings(*ws, options, sky, {})), Lines{});
    options.givenInputs = {"photo"};
    EXPECT_EQ(formatted(unreadArgumentWarnings(*ws, options, sky, {{"", "p.exr", "", "p.exr", nullptr}})),
              (Lines{file.string() + ": warning: --texture Sky=x.exr: no pass that runs samples texture 'Sky', so the file "
                                     "changes nothing; pass 'sky': culled: input given, 'scene' comes from the image given "
                                     "for input 'photo'"}));
}

}  // namespace
}  // namespace rmfx
