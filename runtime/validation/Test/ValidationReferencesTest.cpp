// Validation of references: targets, textures and samplers a pass names must exist, a pass may not
// sample what it writes (except last frame's), mipmap filtering needs mipmaps, pass constants match.

#include "validation/Validation.h"

#include <gtest/gtest.h>

#include "ValidationTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::validation_test;

TEST(ValidationReferences, UndefinedTargetInPass) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\" target=\"nowhere\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":2: error: <pass name=\"p\">: target 'nowhere' is not declared"}));
}

TEST(ValidationReferences, UndefinedTextureAndTargetInSamplers) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           "    <sampler name=\"a\" texture=\"noise\"/>",
                           "    <sampler name=\"b\" target=\"blur\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{
                            l.path + ":3: error: <sampler name=\"a\">: texture 'noise' is not declared",
                            l.path + ":4: error: <sampler name=\"b\">: target 'blur' is not declared",
                        }));
}

TEST(ValidationReferences, UndefinedOutputTarget) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "  <output target=\"final\"/>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":5: error: <output>: target 'final' is not declared"}));
}

TEST(ValidationReferences, PassSamplingWhatItWrites) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <pass name=\"p\" target=\"a\">",
                           "    <sampler name=\"s\" target=\"a\"/>",
                           kPlainShader,
                           "  </pass>",
                           "  <pass name=\"q\">",
                           "    <sampler name=\"s\" target=\"output\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{
                            l.path + ":4: error: <sampler name=\"s\">: pass 'p' samples target 'a', which it also "
                                     "writes (use frame=\"previous\" to read last frame's contents, or a second target)",
                            l.path + ":8: error: <sampler name=\"s\">: pass 'q' samples target 'output', which it "
                                     "also writes (use frame=\"previous\" to read last frame's contents, or a second "
                                     "target)",
                        }));
}

TEST(ValidationReferences, PreviousFrameOfTheWrittenTargetIsFine) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <pass name=\"p\" target=\"a\">",
                           "    <sampler name=\"s\" target=\"a\" frame=\"previous\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D s; out vec4 c; void main() { c = "
                           "texture(s, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "  <pass name=\"q\">",
                           "    <sampler name=\"s\" target=\"a\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D s; out vec4 c; void main() { c = "
                           "texture(s, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, Lines{});
    EXPECT_EQ(l.warnings, Lines{});
    EXPECT_TRUE(l.result.ok());
}

TEST(ValidationReferences, MipmapFilteringNeedsMipmaps) {
    test::ScratchDir dir;
    dir.write("noise.png", "");
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <texture name=\"noise\" file=\"noise.png\" mipmaps=\"false\"/>",
                           "  <pass name=\"p\">",
                           "    <sampler name=\"s\" target=\"a\" frame=\"previous\" mipmap=\"linear\"/>",
                           "    <sampler name=\"t\" texture=\"noise\" mipmap=\"nearest\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{
                            l.path + ":5: error: <sampler name=\"s\">: mipmap filtering, but target 'a' is declared "
                                     "without mipmaps=\"true\"",
                            l.path + ":6: error: <sampler name=\"t\">: mipmap filtering, but texture 'noise' has "
                                     "mipmaps=\"false\"",
                        }));
}

TEST(ValidationReferences, MipmapFilteringOfTheImplicitOutput) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"scene\">",
                           kPlainShader,
                           "  </pass>",
                           "  <pass name=\"p\" target=\"a\">",
                           "    <sampler name=\"s\" target=\"output\" mipmap=\"linear\"/>",
                           kPlainShader,
                           "  </pass>",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":6: error: <sampler name=\"s\">: mipmap filtering, but the implicit output "
                                        "target has no mipmaps (declare a target with mipmaps=\"true\" and name it "
                                        "in <output target=...>)"}));
}

TEST(ValidationReferences, SecondSamplerWithTheSameName) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <pass name=\"p\">",
                           "    <sampler name=\"s\" target=\"a\" frame=\"previous\"/>",
                           "    <sampler name=\"s\" target=\"a\" frame=\"previous\" filter=\"nearest\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":5: error: <sampler name=\"s\">: a second sampler named 's' in <pass "
                                        "name=\"p\">"}));
}

TEST(ValidationReferences, PassConstantOfAnotherType) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <pass name=\"p\">",
                           "    <vec3 name=\"Gain\" value=\"1 1 1\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <vec3 name=\"Gain\">: pass constant 'Gain' is a vec3 but variable "
                                        "'Gain' (line 2) is a float"}));
}

TEST(ValidationReferences, PassConstantColorOfAnotherWidth) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <color name=\"Tint\" value=\"1 1 1\"/>",
                           "  <pass name=\"p\">",
                           "    <color name=\"Tint\" value=\"1 1 1 1\"/>",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <color name=\"Tint\">: pass constant 'Tint' is a color (rgba) but "
                                        "variable 'Tint' (line 2) is a color (rgb)"}));
}

}  // namespace
}  // namespace rmfx
