// Validation of effects: the passes and switches they name, their source and gate (what they start
// from and what is written before them), and cycles of passes.

#include "validation/Validation.h"

#include <gtest/gtest.h>

#include "ValidationTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::validation_test;

TEST(ValidationEffects, EffectsNameDeclaredPassesAndScalarSwitches) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <vec3 name=\"Tint\" value=\"1 1 1\"/>",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <effect name=\"a\" passes=\"p q\" switch=\"Gain\"/>",
                           "  <effect name=\"b\" passes=\"p\" switch=\"Tint Missing\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "  <output effects=\"a c\"/>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{
                            l.path + ":4: error: <effect name=\"a\">: pass 'q' is not declared",
                            l.path + ":5: error: <effect name=\"b\">: pass 'p' already belongs to effect 'a' (line 4): a "
                                     "pass belongs to one effect",
                            l.path + ":5: error: <effect name=\"b\">: switch 'Tint' (line 2) is a vec3; a switch is a "
                                     "bool, int or float",
                            l.path + ":5: error: <effect name=\"b\">: switch 'Missing' is not a declared variable",
                            l.path + ":9: error: <output>: effects: no effect named 'c' is declared",
                        }));
}

// Skipping an effect whose source holds nothing must leave what running it leaves: the checks.
TEST(ValidationEffects, AnEffectsSourceIsATargetItStartsFromAndOnlyItWritesWhatItHandsOn) {
    test::ScratchDir dir;
    const std::string reads = "    <sampler name=\"S\" target=\"src\"/>";
    const std::string sampling = "    <shader stage=\"fragment\">uniform sampler2D S; out vec4 c; void main() { c = texture(S, vec2(0.5)); }</shader>";
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"src\" format=\"rgba8\"/>",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <target name=\"b\" format=\"rgba8\"/>",
                           "  <target name=\"d\" format=\"rgba8\"/>",
                           "  <effect name=\"unknown\" passes=\"p1\" source=\"nope\"/>",
                           "  <effect name=\"self\" passes=\"p2\" source=\"a\"/>",
                           "  <effect name=\"over\" passes=\"p3\" source=\"src\"/>",
                           "  <effect name=\"unread\" passes=\"p5\" source=\"src\"/>",
                           "  <effect name=\"history\" passes=\"p6\" source=\"src\"/>",
                           "  <pass name=\"make\" target=\"src\">", kPlainShader, "  </pass>",
                           "  <pass name=\"p1\" target=\"a\">", reads, sampling, "  </pass>",
                           "  <pass name=\"p2\" target=\"a\">", reads, sampling, "  </pass>",
                           "  <pass name=\"p3\" target=\"b\">", reads, sampling, "  </pass>",
                           "  <pass name=\"p4\" target=\"b\">", kPlainShader, "  </pass>",
                           "  <pass name=\"p5\" target=\"d\">", kPlainShader, "  </pass>",
                           "  <pass name=\"p6\" target=\"d\">",
                           reads,
                           "    <sampler name=\"H\" target=\"d\" frame=\"previous\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D S; uniform sampler2D H; out vec4 c;",
                           "      void main() { c = texture(S, vec2(0.5)) + texture(H, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors,
              (Lines{
                  l.path + ":6: error: <effect name=\"unknown\">: source: no render target 'nope' (it has: src, a, b, d; the output is 'output')",
                  l.path + ":7: error: <effect name=\"self\">: source 'a' is written by pass 'p2' of the effect itself; the "
                           "source is what the effect starts from, written before it by passes outside it",
                  l.path + ":8: error: <effect name=\"over\">: pass 'p3' writes 'b', which pass 'p4' outside the effect writes "
                           "too: a skipped effect's targets are cleared to zero, which would lose what 'p4' wrote",
                  l.path + ":9: error: <effect name=\"unread\">: pass 'p5' writes 'd', which is read with frame=\"previous\": "
                           "a skipped frame could not leave what running it leaves there, so the effect cannot have a source",
                  l.path + ":9: error: <effect name=\"unread\">: pass 'p5' writes 'd', which pass 'p6' outside the effect writes "
                           "too: a skipped effect's targets are cleared to zero, which would lose what 'p6' wrote",
                  l.path + ":9: error: <effect name=\"unread\">: no pass of the effect reads its source 'src', directly or "
                           "through what passes before it make of it",
                  l.path + ":10: error: <effect name=\"history\">: pass 'p6' writes 'd', which is read with "
                           "frame=\"previous\": a skipped frame could not leave what running it leaves there, so the effect "
                           "cannot have a source",
                  l.path + ":10: error: <effect name=\"history\">: pass 'p6' reads 'd' with frame=\"previous\": the effect "
                           "cannot have a source",
                  l.path + ":10: error: <effect name=\"history\">: pass 'p6' writes 'd', which pass 'p5' outside the effect "
                           "writes too: a skipped effect's targets are cleared to zero, which would lose what 'p5' wrote",
              }));
}

TEST(ValidationEffects, AnEffectsSourceIsCompleteBeforeItsFirstPass) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"src\" format=\"rgba8\"/>",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <effect name=\"e\" passes=\"p\" source=\"src\"/>",
                           "  <pass name=\"make\" target=\"src\">", kPlainShader, "  </pass>",
                           "  <pass name=\"p\" target=\"a\">",
                           "    <sampler name=\"S\" target=\"src\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D S; out vec4 c; void main() { c = texture(S, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "  <pass name=\"more\" target=\"src\">", kPlainShader, "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <effect name=\"e\">: pass 'more' writes the source 'src' after pass 'p' "
                                        "of the effect: whether the effect contributes is decided before its first pass, so "
                                        "the source must be complete by then"}));
}

// <effect gate>: counted in place of the source, so it must exist, differ from the source, be
// written outside the effect and be complete before the effect's first pass.
TEST(ValidationEffects, AnEffectsGateIsWrittenBeforeTheEffectByPassesOutsideIt) {
    test::ScratchDir dir;
    const std::string sampling = "    <shader stage=\"fragment\">uniform sampler2D S; out vec4 c; void main() { c = texture(S, vec2(0.5)); }</shader>";
    auto reading = [&](const std::string& pass, const std::string& target) {
        return "  <pass name=\"" + pass + "\" target=\"" + target + "\">\n    <sampler name=\"S\" target=\"src\"/>\n" + sampling +
               "\n  </pass>";
    };
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"src\" format=\"rgba8\"/>",
                           "  <target name=\"g\" format=\"r32f\" size=\"1x1\"/>",
                           "  <target name=\"g2\" format=\"r32f\" size=\"1x1\"/>",
                           "  <target name=\"g3\" format=\"r32f\" size=\"1x1\"/>",
                           "  <target name=\"g4\" format=\"r32f\" size=\"1x1\"/>",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <target name=\"b\" format=\"rgba8\"/>",
                           "  <target name=\"c\" format=\"rgba8\"/>",
                           "  <target name=\"d\" format=\"rgba8\"/>",
                           "  <target name=\"e\" format=\"rgba8\"/>",
                           "  <target name=\"f\" format=\"rgba8\"/>",
                           "  <effect name=\"good\" passes=\"pa\" source=\"src\" gate=\"g\"/>",
                           "  <effect name=\"unknown\" passes=\"pb\" source=\"src\" gate=\"nope\"/>",
                           "  <effect name=\"same\" passes=\"pc\" source=\"src\" gate=\"src\"/>",
                           "  <effect name=\"inside\" passes=\"pd inner\" source=\"src\" gate=\"g2\"/>",
                           "  <effect name=\"late\" passes=\"pe\" source=\"src\" gate=\"g3\"/>",
                           "  <effect name=\"unwritten\" passes=\"pf\" source=\"src\" gate=\"g4\"/>",
                           "  <pass name=\"make\" target=\"src\">", kPlainShader, "  </pass>",
                           "  <pass name=\"bound\" target=\"g\">", kPlainShader, "  </pass>",
                           reading("pa", "a"), reading("pb", "b"), reading("pc", "c"), reading("pd", "d"),
                           "  <pass name=\"inner\" target=\"g2\">", kPlainShader, "  </pass>",
                           reading("pe", "e"),
                           "  <pass name=\"after\" target=\"g3\">", kPlainShader, "  </pass>",
                           reading("pf", "f"),
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors,
              (Lines{
                  l.path + ":14: error: <effect name=\"unknown\">: gate: no render target 'nope' (it has: src, g, g2, g3, g4, a, b, "
                           "c, d, e, f; the output is 'output')",
                  l.path + ":15: error: <effect name=\"same\">: gate 'src' is the source itself: leave 'gate' out to count the source",
                  l.path + ":16: error: <effect name=\"inside\">: gate 'g2' is written by pass 'inner' of the effect itself; the "
                           "gate is written before the effect, by passes outside it",
                  l.path + ":17: error: <effect name=\"late\">: pass 'after' writes the gate 'g3' after pass 'pe' of the effect: "
                           "whether the effect contributes is decided before its first pass, so the gate must be complete by then",
                  l.path + ":18: error: <effect name=\"unwritten\">: no pass writes the gate 'g4' before the effect",
              }));
}

// hdr_lighting's bloom and star start from 'bright' through star_source, a blur of it outside
// both: reading through a pass before the effect counts; through last frame's contents it does not.
TEST(ValidationEffects, AnEffectMayReadItsSourceThroughPassesBeforeIt) {
    test::ScratchDir dir;
    const std::string sampling = "    <shader stage=\"fragment\">uniform sampler2D S; out vec4 c; void main() { c = texture(S, vec2(0.5)); }</shader>";
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"src\" format=\"rgba8\"/>",
                           "  <target name=\"blurred\" format=\"rgba8\"/>",
                           "  <target name=\"late\" format=\"rgba8\"/>",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <target name=\"b\" format=\"rgba8\"/>",
                           "  <effect name=\"through\" passes=\"pa\" source=\"src\"/>",
                           "  <effect name=\"history\" passes=\"pb\" source=\"src\"/>",
                           "  <pass name=\"make\" target=\"src\">", kPlainShader, "  </pass>",
                           "  <pass name=\"blur\" target=\"blurred\">", "    <sampler name=\"S\" target=\"src\"/>", sampling, "  </pass>",
                           "  <pass name=\"pa\" target=\"a\">", "    <sampler name=\"S\" target=\"blurred\"/>", sampling, "  </pass>",
                           "  <pass name=\"remember\" target=\"late\">",
                           "    <sampler name=\"S\" target=\"src\" frame=\"previous\"/>", sampling, "  </pass>",
                           "  <pass name=\"pb\" target=\"b\">", "    <sampler name=\"S\" target=\"late\"/>", sampling, "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":8: error: <effect name=\"history\">: no pass of the effect reads its source "
                                        "'src', directly or through what passes before it make of it"}));
}

TEST(ValidationEffects, ACycleOfPassesIsAnErrorNamingThem) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "  <target name=\"b\" format=\"rgba8\"/>",
                           "  <pass name=\"pa\" target=\"a\">",
                           "    <sampler name=\"s\" target=\"b\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D s; out vec4 c; void main() { c = texture(s, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "  <pass name=\"pb\" target=\"b\">",
                           "    <sampler name=\"s\" target=\"a\"/>",
                           "    <shader stage=\"fragment\">uniform sampler2D s; out vec4 c; void main() { c = texture(s, vec2(0.5)); }</shader>",
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":5: error: <sampler name=\"s\">: passes form a cycle: 'pa' reads 'b' from 'pb', "
                                        "'pb' reads 'a' from 'pa'; read one of them with frame=\"previous\" to take last "
                                        "frame's contents"}));
}

}  // namespace
}  // namespace rmfx
