// Rewriting a workspace's variable values in its text: every type in its shortest form, any float
// surviving the round trip, everything but the values kept (comments, CDATA, quotes, spacing, line
// endings, unknown elements), and each value or text it cannot write an error naming it.

#include "frontend/workspace/VariableValueWriter.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "VariableValueWriterTestSupport.h"

namespace rmfx {
namespace {

namespace fs = std::filesystem;
using test::lines;
using test::readText;
using namespace test::value_writer;

Value vec(ValueType type, std::initializer_list<float> components) {
    Value v;
    v.type = type;
    std::copy(components.begin(), components.end(), v.data.begin());
    return v;
}

std::string rejection(std::string_view text, const std::map<std::string, Value>& values) {
    auto out = rewriteVariableValues(text, "test.xml", values);
    EXPECT_FALSE(out.ok()) << "rewritten as:\n" << (out.ok() ? *out : "");
    return out.ok() ? std::string() : out.error();
}

TEST(VariableValueWriter, EveryTypeIsWrittenInItsShortestForm) {
    const std::string body = lines({
        "  <float name=\"F\" value=\"0.5\"/>",
        "  <int name=\"I\" value=\"2\"/>",
        "  <bool name=\"B\" value=\"true\"/>",
        "  <bool name=\"B01\" value=\"1\"/>",
        "  <vec2 name=\"V2\" value=\"0 0\"/>",
        "  <vec3 name=\"V3\" value=\"0, 0, 0\"/>",
        "  <vec4 name=\"V4\" value=\"0 0 0 0\"/>",
        "  <color name=\"C3\" value=\"1 1 1\"/>",
        "  <color name=\"C4\" value=\"1 1 1 1\"/>",
        "  <mat4 name=\"M\" value=\"1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\"/>",
    });
    std::map<std::string, Value> values = {
        {"F", Value::ofFloat(0.1234567f)},
        {"I", Value::ofInt(-16777216)},
        {"B", Value::ofBool(false)},
        {"B01", Value::ofBool(false)},
        {"V2", vec(ValueType::Vec2, {3e-7f, -1.5f})},
        {"V3", vec(ValueType::Vec3, {1.0f / 3.0f, 100.0f, -0.0f})},
        {"V4", vec(ValueType::Vec4, {1e-45f, 3.4028235e38f, 0.1f, 16777217.0f})},
        {"C3", vec(ValueType::Color3, {0.9f, 0.75f, 0.5f})},
        {"C4", vec(ValueType::Color4, {0.25f, 0.5f, 1.0f, 0.125f})},
        {"M", vec(ValueType::Mat4, {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0.1f, 0.2f, 0.3f, 1})},
    };
    std::string out = rewritten(workspace(body), values);
    EXPECT_EQ(out, workspace(lines({
                       "  <float name=\"F\" value=\"0.1234567\"/>",
                       "  <int name=\"I\" value=\"-16777216\"/>",
                       "  <bool name=\"B\" value=\"false\"/>",
                       "  <bool name=\"B01\" value=\"0\"/>",  // the file's spelling of bools is kept
                       "  <vec2 name=\"V2\" value=\"3e-07 -1.5\"/>",
                       "  <vec3 name=\"V3\" value=\"0.33333334 100 -0\"/>",
                       "  <vec4 name=\"V4\" value=\"1e-45 3.4028235e+38 0.1 16777216\"/>",
                       "  <color name=\"C3\" value=\"0.9 0.75 0.5\"/>",
                       "  <color name=\"C4\" value=\"0.25 0.5 1 0.125\"/>",
                       "  <mat4 name=\"M\" value=\"2 0 0 0 0 2 0 0 0 0 2 0 0.1 0.2 0.3 1\"/>",
                   })));
    Workspace ws = parsed(out);
    for (const auto& [name, value] : values) {
        const Variable* v = ws.findVariable(name);
        ASSERT_TRUE(v) << name;
        EXPECT_TRUE(sameBits(v->value, value)) << name;
    }
}

TEST(VariableValueWriter, AnyFloatSurvivesWritingAndReading) {
    // A sweep over the float bit patterns (every 65521st, plus the edges): what the writer
    // writes, the parser reads back bit for bit.
    std::vector<float> floats = {0.0f, -0.0f, 1e-45f, -1e-45f, 1.17549435e-38f, 3.4028235e38f, -3.4028235e38f};
    for (std::uint64_t b = 0; b < (1ull << 32); b += 65521) {
        float f = std::bit_cast<float>(static_cast<std::uint32_t>(b));
        if (std::isfinite(f)) floats.push_back(f);
    }
    const std::string text = workspace("  <float name=\"F\" value=\"7\"/>\n");
    size_t checked = 0;
    for (float f : floats) {
        auto out = rewriteVariableValues(text, "test.xml", {{"F", Value::ofFloat(f)}});
        ASSERT_TRUE(out.ok()) << out.error();
        Result<Workspace> p = parseWorkspaceText(*out, "test.xml", ".");
        ASSERT_TRUE(p.ok()) << formatAll(p.diagnostics());
        ASSERT_EQ(p->variables.size(), 1u);
        ASSERT_TRUE(sameBits(p->variables[0].value, Value::ofFloat(f)));
        ++checked;
    }
    EXPECT_GT(checked, 60000u);
}

TEST(VariableValueWriter, CommentsCdataAndInstructionsAreNotLookedInto) {
    const std::string fake = "<float name=\"Exposure_Level\" value=\"1\"/>";
    const std::string text = lines({
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>",
        "<!DOCTYPE workspace [ <!ENTITY fake '" + fake + "'> <!-- ]> " + fake + " --> ]>",
        "<?editor " + fake + " ?>",
        "<!-- " + fake + " -->",
        "<workspace version=\"1\">",
        "  <!-- <float name=\"Exposure_Level\" value=\"2\"/> -->",
        "  <code name=\"fake.glsl\"><![CDATA[ // " + fake + " ]]></code>",
        "  <float name=\"Exposure_Level\" value=\"3\"/>",
        "  <pass name=\"p\">",
        "    <shader stage=\"fragment\"><![CDATA[",
        "// " + fake,
        "out vec4 c; void main() { c = vec4(1.0); }",
        "]]></shader>",
        "  </pass>",
        "</workspace>",
    });
    std::string expected = text;
    size_t real = expected.find("value=\"3\"");
    ASSERT_NE(real, std::string::npos);
    expected.replace(real, 9, "value=\"0.5\"");
    EXPECT_EQ(rewritten(text, {{"Exposure_Level", Value::ofFloat(0.5f)}}), expected);
}

TEST(VariableValueWriter, ShaderCodeInCdataIsKept) {
    const std::string code = "\n// <float name=\"Exposure_Level\" value=\"1\"/>\nout vec4 c; void main() { c = vec4(1.0); }\n";
    const std::string text = workspace("  <float name=\"Exposure_Level\" value=\"1\"/>\n",
                                       "    <shader stage=\"vertex\"><![CDATA[" + code + "]]></shader>\n");
    std::string out = rewritten(text, {{"Exposure_Level", Value::ofFloat(2.0f)}});
    Workspace ws = parsed(out);
    ASSERT_EQ(ws.passes.size(), 1u);
    ASSERT_EQ(ws.passes[0].shaders.size(), 2u);  // the vertex shader above, the fragment shader of workspace()
    EXPECT_EQ(ws.passes[0].shaders[0].code, code);
    EXPECT_TRUE(sameBits(ws.variables[0].value, Value::ofFloat(2.0f)));
    std::string expected = text;
    expected.replace(expected.find("value=\"1\""), 9, "value=\"2\"");
    EXPECT_EQ(out, expected);
}

TEST(VariableValueWriter, QuotesSpacingAndAttributeOrderAreKept) {
    const std::string body = lines({
        "  <float name='Gain' value='0.50' min='0' max='4' description='say \"hi\" &amp; &lt;go&gt; > 1'/>",
        "  <vec3",
        "      description = \"value='9'\"",
        "      value\t=  \"1 2 3\"",
        "      name=\"Dir\"",
        "  />",
        "  <color value=\"1 0 0\" name='Tint' ></color>",
    });
    std::string out = rewritten(workspace(body), {{"Gain", Value::ofFloat(0.25f)},
                                                  {"Dir", vec(ValueType::Vec3, {-1, 0.5f, 2})},
                                                  {"Tint", vec(ValueType::Color3, {0, 1, 0})}});
    EXPECT_EQ(out, workspace(lines({
                       "  <float name='Gain' value='0.25' min='0' max='4' description='say \"hi\" &amp; &lt;go&gt; > 1'/>",
                       "  <vec3",
                       "      description = \"value='9'\"",
                       "      value\t=  \"-1 0.5 2\"",
                       "      name=\"Dir\"",
                       "  />",
                       "  <color value=\"0 1 0\" name='Tint' ></color>",
                   })));
    Workspace ws = parsed(out);
    ASSERT_EQ(ws.variables.size(), 3u);
    EXPECT_EQ(ws.variables[0].description, "say \"hi\" & <go> > 1");
}

TEST(VariableValueWriter, CrlfLineEndingsAndUtf8TextAreKept) {
    const std::string text =
        "\xEF\xBB\xBF<?xml version=\"1.0\" encoding=\"UTF-8\"?>\r\n"
        "<workspace version=\"1\" name=\"gl\xC3\xBChen\">\r\n"
        "  <description>\xC3\x9C" "berstrahlung \xE2\x80\x94 gl\xC3\xBChen \xE2\x9C\xA8</description>\r\n"
        "  <float name=\"Gain\" value=\"1\"\r\n"
        "         description=\"Helligkeit \xC3\x97" "2\"/>\r\n"
        "  <pass name=\"p\">\r\n"
        "    <shader stage=\"fragment\"><![CDATA[out vec4 c; void main() { c = vec4(1.0); }]]></shader>\r\n"
        "  </pass>\r\n"
        "</workspace>\r\n";
    std::string out = rewritten(text, {{"Gain", Value::ofFloat(1.5f)}});
    std::string expected = text;
    expected.replace(expected.find("value=\"1\""), 9, "value=\"1.5\"");
    EXPECT_EQ(out, expected);
    Workspace ws = parsed(out);
    ASSERT_EQ(ws.variables.size(), 1u);
    EXPECT_EQ(ws.variables[0].where.line, 4);
    EXPECT_EQ(ws.description, "\xC3\x9C" "berstrahlung \xE2\x80\x94 gl\xC3\xBChen \xE2\x9C\xA8");
}

TEST(VariableValueWriter, MissingValueAttributeIsAddedAfterTheName) {
    const std::string text = workspace(lines({
        "  <float name=\"Gain\" min=\"0\"/>",
        "  <color description=\"no value yet\" name='Tint'/>",
    }));
    std::string out = rewritten(text, {{"Gain", Value::ofFloat(0.25f)}, {"Tint", vec(ValueType::Color4, {1, 0.5f, 0, 1})}});
    EXPECT_EQ(out, workspace(lines({
                       "  <float name=\"Gain\" value=\"0.25\" min=\"0\"/>",
                       "  <color description=\"no value yet\" name='Tint' value='1 0.5 0 1'/>",
                   })));
    Workspace ws = parsed(out);
    ASSERT_EQ(ws.variables.size(), 2u);
    EXPECT_TRUE(sameBits(ws.variables[0].value, Value::ofFloat(0.25f)));
    EXPECT_TRUE(sameBits(ws.variables[1].value, vec(ValueType::Color4, {1, 0.5f, 0, 1})));
}

TEST(VariableValueWriter, PassConstantsOfTheSameNameStay) {
    const std::string text = workspace("  <float name=\"Gain\" value=\"1\"/>\n",
                                       "    <float name=\"Gain\" value=\"1\"/>\n    <vec2 name=\"Dir\" value=\"1 0\"/>\n");
    std::string out = rewritten(text, {{"Gain", Value::ofFloat(8.0f)}});
    EXPECT_EQ(out, workspace("  <float name=\"Gain\" value=\"8\"/>\n",
                             "    <float name=\"Gain\" value=\"1\"/>\n    <vec2 name=\"Dir\" value=\"1 0\"/>\n"));
    Workspace ws = parsed(out);
    ASSERT_EQ(ws.passes.size(), 1u);
    ASSERT_EQ(ws.passes[0].constants.size(), 2u);
    EXPECT_TRUE(sameBits(ws.passes[0].constants[0].value, Value::ofFloat(1.0f)));

    // A pass constant is no workspace variable: asking for it names where it is.
    EXPECT_EQ(rejection(text, {{"Dir", vec(ValueType::Vec2, {0, 1})}}),
              "test.xml: error: variable 'Dir': the workspace has no variable 'Dir'; line 6 declares a constant of that "
              "name inside <pass>, which is not a workspace variable (it has: Gain)");
}

TEST(VariableValueWriter, ElementsAndAttributesRmfxDoesNotKnowStay) {
    const std::string text = lines({
        "<workspace version=\"1\" xmlns:ed=\"urn:editor\">",
        "  <ed:layout panel=\"left\"><float name=\"Gain\" value=\"5\"/></ed:layout>",
        "  <float name=\"Gain\" ed:locked=\"true\" value=\"1\" future=\"x\"/>",
        "  <future><![CDATA[ ]]><!-- c --></future>",
        "</workspace>",
    });
    EXPECT_EQ(rewritten(text, {{"Gain", Value::ofFloat(2.0f)}}),
              lines({
                  "<workspace version=\"1\" xmlns:ed=\"urn:editor\">",
                  "  <ed:layout panel=\"left\"><float name=\"Gain\" value=\"5\"/></ed:layout>",
                  "  <float name=\"Gain\" ed:locked=\"true\" value=\"2\" future=\"x\"/>",
                  "  <future><![CDATA[ ]]><!-- c --></future>",
                  "</workspace>",
              }));
}

TEST(VariableValueWriter, UnchangedValuesKeepTheirText) {
    const std::string text = workspace(lines({
        "  <float name=\"Gain\" value=\" 0.50 \"/>",
        "  <vec3 name=\"Dir\" value=\"1.0, 2.00,3e0\"/>",
        "  <bool name=\"On\" value=\"1\"/>",
        "  <float name=\"Coded\" value=\"&#48;.25\"/>",
    }));
    EXPECT_EQ(rewritten(text, {{"Gain", Value::ofFloat(0.5f)},
                               {"Dir", vec(ValueType::Vec3, {1, 2, 3})},
                               {"On", Value::ofBool(true)},
                               {"Coded", Value::ofFloat(0.25f)}}),
              text);
    // -0 reads back with another sign bit than 0: that is a change.
    const std::string zero = workspace("  <float name=\"Z\" value=\"0\"/>\n");
    EXPECT_EQ(rewritten(zero, {{"Z", Value::ofFloat(-0.0f)}}), workspace("  <float name=\"Z\" value=\"-0\"/>\n"));
}

TEST(VariableValueWriter, UnknownVariableIsAnErrorNamingIt) {
    const std::string text = workspace("  <float name=\"Gain\" value=\"1\"/>\n  <int name=\"Mode\" value=\"0\"/>\n");
    EXPECT_EQ(rejection(text, {{"Gian", Value::ofFloat(2.0f)}}),
              "test.xml: error: variable 'Gian': the workspace has no variable 'Gian' (it has: Gain, Mode)");
    EXPECT_EQ(rejection(workspace(""), {{"Gain", Value::ofFloat(2.0f)}}),
              "test.xml: error: variable 'Gain': the workspace has no variable 'Gain' (it declares none)");
}

TEST(VariableValueWriter, WrongTypesAndUnwritableValuesAreErrors) {
    const std::string text = workspace(lines({
        "  <float name=\"Gain\" value=\"1\"/>",
        "  <color name=\"Tint\" value=\"1 1 1\"/>",
        "  <int name=\"Mode\" value=\"0\"/>",
        "  <bool name=\"On\" value=\"true\"/>",
        "  <vec2 name=\"Dir\" value=\"0 1\"/>",
    }));
    EXPECT_EQ(rejection(text, {{"Gain", vec(ValueType::Vec3, {1, 2, 3})}}),
              "test.xml:3: error: <float name=\"Gain\">: variable 'Gain' is a float, but the new value (1 2 3) is a vec3");
    EXPECT_EQ(rejection(text, {{"Tint", vec(ValueType::Color4, {1, 1, 1, 1})}}),
              "test.xml:4: error: <color name=\"Tint\">: variable 'Tint' is a color with 3 numbers (rgb), but the new "
              "value (1 1 1 1) is a color with 4 numbers (rgba)");
    EXPECT_EQ(rejection(text, {{"Mode", Value::ofFloat(1.0f)}}),
              "test.xml:5: error: <int name=\"Mode\">: variable 'Mode' is an int, but the new value (1) is a float");
    Value half = Value::ofInt(0);
    half.data[0] = 2.5f;
    EXPECT_EQ(rejection(text, {{"Mode", half}}),
              "test.xml:5: error: <int name=\"Mode\">: variable 'Mode': an int holds a whole number from -16777216 to "
              "16777216, not 2.5");
    Value maybe = Value::ofBool(true);
    maybe.data[0] = 0.5f;
    EXPECT_EQ(rejection(text, {{"On", maybe}}),
              "test.xml:6: error: <bool name=\"On\">: variable 'On': a bool holds 0 (false) or 1 (true), not 0.5");
    EXPECT_EQ(rejection(text, {{"Gain", Value::ofFloat(std::numeric_limits<float>::quiet_NaN())}}),
              "test.xml:3: error: <float name=\"Gain\">: variable 'Gain': the new value is not a finite number");
    EXPECT_EQ(rejection(text, {{"Dir", vec(ValueType::Vec2, {0, std::numeric_limits<float>::infinity()})}}),
              "test.xml:7: error: <vec2 name=\"Dir\">: variable 'Dir': component 2 of the new value is not a finite "
              "number");
    // Every problem is reported, one line each, in the order of the names.
    EXPECT_EQ(rejection(text, {{"Gain", Value::ofBool(true)}, {"Nope", Value::ofFloat(1)}, {"Dir", Value::ofFloat(0)}}),
              "test.xml:7: error: <vec2 name=\"Dir\">: variable 'Dir' is a vec2, but the new value (0) is a float\n"
              "test.xml:3: error: <float name=\"Gain\">: variable 'Gain' is a float, but the new value (true) is a bool\n"
              "test.xml: error: variable 'Nope': the workspace has no variable 'Nope' (it has: Dir, Gain, Mode, On, Tint)");
}

TEST(VariableValueWriter, DuplicateVariableIsAnError) {
    const std::string text = workspace("  <float name=\"Gain\" value=\"1\"/>\n  <float name=\"Gain\" value=\"2\"/>\n");
    EXPECT_EQ(rejection(text, {{"Gain", Value::ofFloat(3)}}),
              "test.xml:4: error: <float name=\"Gain\">: variable 'Gain' is declared more than once (lines 3, 4): "
              "which one to change is unclear");
}

TEST(VariableValueWriter, MalformedTextIsAnErrorWithItsLine) {
    const std::map<std::string, Value> gain = {{"Gain", Value::ofFloat(2)}};
    EXPECT_EQ(rejection(lines({"<workspace version=\"1\">", "  <float name=\"Gain\" value=\"1\"/>", "  <!-- open",
                               "</workspace>"}),
                        gain),
              "test.xml:3: error: malformed XML: a comment (<!--) is never closed ('-->' expected)");
    EXPECT_EQ(rejection(lines({"<workspace version=\"1\">", "  <pass name=\"p\">", "  <float name=\"Gain\" value=\"1\"/>",
                               "</workspace>"}),
                        gain),
              "test.xml:4: error: malformed XML: end tag </workspace> does not match <pass> (line 2)");
    EXPECT_EQ(rejection(lines({"<workspace version=\"1\">", "  <float name=Gain value=\"1\"/>", "</workspace>"}), gain),
              "test.xml:2: error: malformed XML: the value of attribute 'name' of <float> must be in quotes");
    EXPECT_EQ(rejection(lines({"<workspace version=\"1\">", "  <float name=\"Gain\" value=\"1/>", "</workspace>"}), gain),
              "test.xml:2: error: malformed XML: the value of attribute 'value' of <float> has no closing quote (\")");
    EXPECT_EQ(rejection(lines({"<workspace version=\"1\">", "  <float name=\"Gain\" value=\"1\"/>"}), gain),
              "test.xml:1: error: malformed XML: <workspace> is never closed (</workspace> expected)");
    EXPECT_EQ(rejection(lines({"<workspace version=\"1\">", "  <float name=\"Gain\" value=\"1\" value=\"2\"/>",
                               "</workspace>"}),
                        gain),
              "test.xml:2: error: malformed XML: attribute 'value' is given twice in <float>");
    EXPECT_EQ(rejection(lines({"<effect>", "  <float name=\"Gain\" value=\"1\"/>", "</effect>"}), gain),
              "test.xml:1: error: the root element must be <workspace>, not <effect>");
    EXPECT_EQ(rejection("<!-- nothing -->\n", gain), "test.xml:1: error: no <workspace> element");
}

}  // namespace
}  // namespace rmfx
