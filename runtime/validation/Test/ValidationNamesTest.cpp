// Validation of names: duplicate variables, targets, passes and cubemaps name the first one's line;
// what format-by and scale-by name must fit; a workspace needs a pass.

#include "validation/Validation.h"

#include <gtest/gtest.h>

#include "ValidationTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::validation_test;

TEST(ValidationNames, DuplicateVariableNamesTheFirstLine) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <vec3 name=\"Gain\" value=\"1 2 3\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":3: error: <vec3 name=\"Gain\">: duplicate variable name 'Gain' (first "
                                        "declared at line 2)"}));
}

TEST(ValidationNames, DuplicateTargetNamesTheFirstLine) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"a\" format=\"rgba8\"/>",
                           "",
                           "  <target name=\"a\" format=\"rgba16f\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":4: error: <target name=\"a\">: duplicate target name 'a' (first declared at "
                                        "line 2)"}));
}

TEST(ValidationNames, FormatByNeedsAnIntVariableWithAFormatPerValue) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <int name=\"Enc\" value=\"3\"/>",
                           "  <int name=\"Mode\" value=\"0\" options=\"a, b, c\"/>",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <target name=\"a\" format=\"rgba8 rgba16f\" format-by=\"Enc\"/>",
                           "  <target name=\"b\" format=\"rgba8 rgba16f\" format-by=\"Mode\"/>",
                           "  <target name=\"c\" format=\"rgba8 rgba16f\" format-by=\"Gain\"/>",
                           "  <target name=\"d\" format=\"rgba8 rgba16f\" format-by=\"Nope\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors,
              (Lines{
                  l.path + ":5: error: <target name=\"a\">: variable 'Enc' = 3 picks none of the 2 formats (values 0 to 1)",
                  l.path + ":6: error: <target name=\"b\">: format lists 2 formats, but variable 'Mode' (line 3) has 3 "
                           "options: give one format per option",
                  l.path + ":7: error: <target name=\"c\">: format-by variable 'Gain' (line 4) is a float; it must be an int",
                  l.path + ":8: error: <target name=\"d\">: format-by names 'Nope', which is not a declared variable",
              }));
}

TEST(ValidationNames, ScaleByNeedsAnIntVariablePickingOneScale) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <int name=\"D\" value=\"3\"/>",
                           "  <int name=\"Mode\" value=\"0\" options=\"a, b\"/>",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <target name=\"a\" format=\"rgba8\" scale=\"1/2 1/4 1/8\" scale-by=\"D\"/>",
                           "  <target name=\"b\" format=\"rgba8\" scale=\"1/2 1/4 1/8\" scale-by=\"Mode\"/>",
                           "  <target name=\"c\" format=\"rgba8\" scale=\"1/2 1/4\" scale-by=\"Gain\"/>",
                           "  <target name=\"d\" format=\"rgba8\" scale=\"1/2 1/4\" scale-by=\"Nope\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors,
              (Lines{
                  l.path + ":5: error: <target name=\"a\">: variable 'D' = 3 picks none of the 3 scales (values 0 to 2)",
                  l.path + ":6: error: <target name=\"b\">: scale lists 3 scales, but variable 'Mode' (line 3) has 2 "
                           "options: give one scale per option",
                  l.path + ":7: error: <target name=\"c\">: scale-by variable 'Gain' (line 4) is a float; it must be an int",
                  l.path + ":8: error: <target name=\"d\">: scale-by names 'Nope', which is not a declared variable",
              }));
}

TEST(ValidationNames, DuplicatePassNamesTheFirstLine) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":5: error: <pass name=\"p\">: duplicate pass name 'p' (first declared at "
                                        "line 2)"}));
}

TEST(ValidationNames, DuplicateCubemapIsNamedAsACubemap) {
    test::ScratchDir dir;
    dir.write("a.png", "");
    dir.write("cross.png", "");
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <texture name=\"env\" file=\"a.png\"/>",
                           "  <cubemap name=\"env\" file=\"cross.png\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":3: error: <cubemap name=\"env\">: duplicate texture name 'env' (first "
                                        "declared at line 2)"}));
}

TEST(ValidationNames, TargetNamedOutputClashesWithTheImplicitOutput) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <target name=\"output\" format=\"rgba8\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    EXPECT_EQ(l.errors, (Lines{l.path + ":2: error: <target name=\"output\">: the name 'output' is taken by the "
                                        "implicit output target; rename the target, or make it the output with "
                                        "<output target=\"output\"/>"}));

    // Made the output, the name is fine.
    auto ok = load(dir, lines({
                            "<workspace version=\"1\">",
                            "  <target name=\"output\" format=\"rgba8\"/>",
                            "  <pass name=\"p\">",
                            kPlainShader,
                            "  </pass>",
                            "  <output target=\"output\"/>",
                            "</workspace>",
                        }));
    EXPECT_EQ(ok.errors, Lines{});
}

TEST(ValidationNames, WorkspaceWithoutPasses) {
    // Built in memory: no file line to point at.
    Workspace ws;
    ws.path = "mem.xml";
    EXPECT_EQ(formatAll(validateWorkspace(ws).diagnostics()), "mem.xml: error: <workspace>: no <pass>: nothing to render\n");
}

}  // namespace
}  // namespace rmfx
