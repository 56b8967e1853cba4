// The workspace parser on attribute values: numbers, enum words, component counts, sizes and scales,
// ranges, widget hints and reserved names, each an error at its line.

#include "frontend/workspace/WorkspaceParser.h"

#include <gtest/gtest.h>

#include "WorkspaceParserTestSupport.h"

namespace rmfx {
namespace {

using namespace test;
using namespace test::workspace_parser;

TEST(WorkspaceParserValues, BadNumber) {
    EXPECT_EQ(errorsOf(workspace({"  <camera distance=\"far\"/>"})),
              (Lines{at + "2: error: <camera>: attribute 'distance': expected a number, got 'far'"}));
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"g\" value=\"1\" min=\"low\"/>"})),
              (Lines{at + "2: error: <float name=\"g\">: attribute 'min': expected a number, got 'low'"}));
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"g\" value=\"1.5.2\"/>"})),
              (Lines{at + "2: error: <float name=\"g\">: attribute 'value': expected numbers, got '1.5.2'"}));
    EXPECT_EQ(errorsOf(workspace({"  <bool name=\"b\" value=\"yes\"/>"})),
              (Lines{at + "2: error: <bool name=\"b\">: attribute 'value': expected true or false, got 'yes'"}));
}

TEST(WorkspaceParserValues, BadEnumWordListsTheChoices) {
    auto d = errorsOf(workspace({
        "  <pass name=\"p\">",
        "    <blend mode=\"screen\"/>",
        "    <sampler name=\"s\" target=\"t\" wrap=\"wrap\"/>",
        "  </pass>",
    }));
    EXPECT_EQ(d, (Lines{
                     at + "3: error: <blend>: attribute 'mode': 'screen' is not one of: none, add, alpha, "
                          "premultiplied, multiply, custom",
                     at + "4: error: <sampler name=\"s\">: attribute 'wrap': 'wrap' is not one of: repeat, clamp, "
                          "mirror, border",
                 }));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgb8\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: attribute 'format': unknown format 'rgb8' (expected "
                          "rgba8, rgba16f, rgba32f, r16f, r32f, rg16f, rg32f, rgba16, r11g11b10f, rgb10a2, r8, rg8)"}));
}

TEST(WorkspaceParserValues, FormatListFollowsTheFormatByVariable) {
    auto parsed = parse(workspace({"  <target name=\"t\" format=\"rgba16f, rgba16 rgba8\" format-by=\"Enc\"/>"}));
    ASSERT_TRUE(parsed.ok());
    const RenderTarget& t = parsed->targets.at(0);
    EXPECT_EQ(t.formatVariable, "Enc");
    EXPECT_EQ(t.formats, (std::vector<TargetFormat>{TargetFormat::RGBA16F, TargetFormat::RGBA16, TargetFormat::RGBA8}));
    EXPECT_EQ(t.format, TargetFormat::RGBA16F);
    EXPECT_EQ(selectTargetFormat(t, nullptr), std::nullopt);
    Value two = Value::ofInt(2);
    EXPECT_EQ(selectTargetFormat(t, &two), TargetFormat::RGBA8);
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba16f rgba8\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: attribute 'format': a list of formats needs "
                          "format-by=\"VARIABLE\", the int variable whose value picks one"}));
}

TEST(WorkspaceParserValues, WrongComponentCount) {
    EXPECT_EQ(errorsOf(workspace({"  <vec3 name=\"v\" value=\"1 2\"/>"})),
              (Lines{at + "2: error: <vec3 name=\"v\">: attribute 'value': a vec3 takes 3 numbers, got 2"}));
    EXPECT_EQ(errorsOf(workspace({"  <color name=\"c\" value=\"1 0\"/>"})),
              (Lines{at + "2: error: <color name=\"c\">: attribute 'value': a color takes 3 (rgb) or 4 (rgba) "
                          "numbers, got 2"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <clear color=\"0 0 0\"/>", "  </pass>"})),
              (Lines{at + "3: error: <clear>: attribute 'color': expected 4 numbers, got '0 0 0'"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <draw mesh=\"cube\" scale=\"1 2\"/>", "  </pass>"})),
              (Lines{at + "3: error: <draw>: attribute 'scale': expected 1 or 3 numbers, got '1 2'"}));
}

TEST(WorkspaceParserValues, IntWithFraction) {
    EXPECT_EQ(errorsOf(workspace({"  <int name=\"n\" value=\"2.5\"/>"})),
              (Lines{at + "2: error: <int name=\"n\">: attribute 'value': expected an integer, got '2.5'"}));
    EXPECT_EQ(errorsOf(workspace({"  <cubemap name=\"e\" file=\"e.hdr\" layout=\"equirect\" face-size=\"0.5\"/>"})),
              (Lines{at + "2: error: <cubemap name=\"e\">: attribute 'face-size': expected an integer ≥ 1, got '0.5'"}));
}

TEST(WorkspaceParserValues, BadSizeOrScale) {
    EXPECT_EQ(errorsOf("<workspace version=\"1\" size=\"512\"><pass name=\"p\"/></workspace>"),
              (Lines{at + "1: error: <workspace>: attribute 'size': expected WIDTHxHEIGHT such as 512x512, got '512'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" size=\"0x4\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: attribute 'size': expected WIDTHxHEIGHT such as 64x64, got '0x4'"}));
    const std::string scaleError = "attribute 'scale': expected one or two fractions of the viewport in (0, 16] such as "
                                   "1/4 or \"1/2 1/4\" (x and y; a list of choices needs scale-by=\"VARIABLE\"), got ";
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" scale=\"1/0\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: " + scaleError + "'1/0'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" scale=\"-1\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: " + scaleError + "'-1'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" scale=\"1/2 1/4 1/8\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: " + scaleError + "'1/2 1/4 1/8'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" size=\"4x4\" scale=\"1\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: give either 'size' (absolute) or 'scale' (relative to the "
                          "viewport), not both"}));
}

TEST(WorkspaceParserValues, ScaleByListsOneFractionPerValue) {
    Workspace ws = parsedOk(workspace({"  <int name=\"D\" value=\"1\"/>",
                                       "  <target name=\"t\" format=\"rgba8\" scale=\"1/2, 1/4 1/8\" scale-by=\"D\"/>"}));
    ASSERT_EQ(ws.targets.size(), 1u);
    const RenderTarget& t = ws.targets[0];
    EXPECT_EQ(t.scaleVariable, "D");
    ASSERT_EQ(t.scales.size(), 3u);
    EXPECT_EQ(t.scales[2].scaleX, 0.125);
    EXPECT_EQ(t.scales[2].scaleY, 0.125);
    EXPECT_EQ(t.size.scaleX, 0.5);  // the first choice until a value picks one

    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" scale=\"1/2 0 1/8\" scale-by=\"D\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: attribute 'scale': expected fractions of the viewport in (0, 16] "
                          "such as \"1/2 1/4 1/8\" (one per value of 'D'), got '0'"}));
    EXPECT_EQ(errorsOf(workspace({"  <target name=\"t\" format=\"rgba8\" size=\"4x4\" scale-by=\"D\"/>"})),
              (Lines{at + "2: error: <target name=\"t\">: attribute 'scale-by' needs 'scale' with one fraction per value"}));
}

TEST(WorkspaceParserValues, MinGreaterThanMax) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"g\" value=\"1.5\" min=\"2\" max=\"1\"/>"})),
              (Lines{at + "2: error: <float name=\"g\">: min (2) is greater than max (1)"}));
}

TEST(WorkspaceParserValues, ValueOutsideRange) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"g\" value=\"9\" min=\"0\" max=\"8\"/>"})),
              (Lines{at + "2: error: <float name=\"g\">: value 9 lies outside [0, 8]"}));
    EXPECT_EQ(errorsOf(workspace({"", "  <vec3 name=\"v\" value=\"0.5 -1 0\" min=\"0\"/>"})),
              (Lines{at + "3: error: <vec3 name=\"v\">: value 0.5 -1 0 lies outside [0, inf]"}));
    EXPECT_EQ(errorsOf(workspace({"  <int name=\"n\" value=\"3\" max=\"2\"/>"})),
              (Lines{at + "2: error: <int name=\"n\">: value 3 lies outside [-inf, 2]"}));
}

TEST(WorkspaceParserValues, WidgetHintsCheckTheirNeeds) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"g\" value=\"1\" min=\"0\" ui=\"slider\"/>"})),
              (Lines{at + "2: error: <float name=\"g\">: ui=\"slider\" needs both min and max"}));
    EXPECT_EQ(errorsOf(workspace({"  <int name=\"m\" value=\"0\" ui=\"combo\"/>"})),
              (Lines{at + "2: error: <int name=\"m\">: ui=\"combo\" needs attribute 'options'"}));
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"m\" value=\"0\" options=\"a, b\"/>"})),
              (Lines{at + "2: error: <float name=\"m\">: attribute 'options' applies to int variables"}));
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"m\" value=\"0\" ui=\"combo\" options=\"a, b\"/>"})),
              (Lines{at + "2: error: <float name=\"m\">: ui=\"combo\" applies to int variables",
                     at + "2: error: <float name=\"m\">: attribute 'options' applies to int variables"}));
    EXPECT_EQ(errorsOf(workspace({"  <int name=\"m\" value=\"2\" options=\"a, b\"/>"})),
              (Lines{at + "2: error: <int name=\"m\">: value 2 does not select one of the 2 options"}));
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"m\" value=\"0\" ui=\"checkbox\"/>"})),
              (Lines{at + "2: error: <float name=\"m\">: ui=\"checkbox\" applies to bool variables"}));
    EXPECT_EQ(errorsOf(workspace({"  <bool name=\"b\" value=\"true\" min=\"0\"/>"})),
              (Lines{at + "2: error: <bool name=\"b\">: attribute 'min' does not apply to a bool"}));
}

TEST(WorkspaceParserValues, ReservedPrefix) {
    EXPECT_EQ(errorsOf(workspace({"  <float name=\"rm_Time\" value=\"0\"/>"})),
              (Lines{at + "2: error: <float name=\"rm_Time\">: the prefix rm_ is reserved for predefined variables"}));
    EXPECT_EQ(errorsOf(workspace({"  <pass name=\"p\">", "    <vec2 name=\"rm_ViewportSize\" value=\"1 1\"/>", "  </pass>"})),
              (Lines{at + "3: error: <vec2 name=\"rm_ViewportSize\">: the prefix rm_ is reserved for predefined "
                          "variables"}));
}

}  // namespace
}  // namespace rmfx
