// --set overrides: they replace the defaults, and each bad one is an error naming the variable.

#include "validation/Validation.h"

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "ValidationTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::validation_test;

TEST(ValidationOverrides, OverridesReplaceDefaults) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <color name=\"Tint\" value=\"1 1 1\"/>",
                           "  <bool name=\"On\" value=\"false\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    ASSERT_TRUE(l.result.ok());
    Workspace ws = *l.result;
    Result<void> set = applyOverrides(ws, {{"Gain", "2.5"}, {"Tint", "0.5 0.25 0"}, {"On", "true"}});
    EXPECT_TRUE(set.ok());
    EXPECT_EQ(formatAll(set.diagnostics()), "");
    EXPECT_EQ(ws.findVariable("Gain")->value, Value::ofFloat(2.5f));
    EXPECT_EQ(formatValue(ws.findVariable("Tint")->value), "0.5 0.25 0");
    EXPECT_EQ(ws.findVariable("On")->value, Value::ofBool(true));
}

TEST(ValidationOverrides, OverrideErrorsNameTheVariable) {
    test::ScratchDir dir;
    auto l = load(dir, lines({
                           "<workspace version=\"1\">",
                           "  <float name=\"Gain\" value=\"1\"/>",
                           "  <color name=\"Tint\" value=\"1 1 1\"/>",
                           "  <color name=\"Fog\" value=\"1 1 1 0.5\"/>",
                           "  <int name=\"Steps\" value=\"4\"/>",
                           "  <pass name=\"p\">",
                           kPlainShader,
                           "  </pass>",
                           "</workspace>",
                       }));
    ASSERT_TRUE(l.result.ok());
    Workspace ws = *l.result;
    Result<void> set = applyOverrides(ws, {{"Gian", "2"},
                                           {"Gain", "bright"},
                                           {"Tint", "1 0 0 1"},
                                           {"Fog", "1 0 0"},
                                           {"Steps", "2.5"},
                                           {"Gain", "3"}});
    EXPECT_FALSE(set.ok());
    EXPECT_EQ(formatAll(set.diagnostics()),
              l.path + ": error: --set Gian: the workspace has no variable 'Gian' (it has: Gain, Tint, Fog, Steps)\n" +
                  l.path + ":2: error: --set Gain: variable 'Gain' (float): expected numbers, got 'bright'\n" +
                  l.path + ":3: error: --set Tint: variable 'Tint' (color): this color takes 3 numbers (rgb), got 4\n" +
                  l.path + ":4: error: --set Fog: variable 'Fog' (color): this color takes 4 numbers (rgba), got 3\n" +
                  l.path + ":5: error: --set Steps: variable 'Steps' (int): expected an integer, got '2.5'\n");
    // Bad overrides leave the default; good ones still apply.
    EXPECT_EQ(ws.findVariable("Gain")->value, Value::ofFloat(3.0f));
    EXPECT_EQ(ws.findVariable("Tint")->value.type, ValueType::Color3);
    EXPECT_EQ(ws.findVariable("Steps")->value, Value::ofInt(4));

    Workspace empty;
    empty.path = "e.xml";
    EXPECT_EQ(formatAll(applyOverrides(empty, {{"X", "1"}}).diagnostics()),
              "e.xml: error: --set X: the workspace has no variable 'X' (it declares none)\n");
}

}  // namespace
}  // namespace rmfx
