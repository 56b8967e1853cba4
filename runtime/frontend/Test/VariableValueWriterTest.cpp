#include "frontend/workspace/VariableValueWriter.h"

#include <sys/resource.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <limits>
#include <regex>
#include <atomic>
#include <set>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "io/file/AtomicFile.h"
#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

namespace fs = std::filesystem;
using test::lines;
using test::readText;

// ---- helpers, independent of the code under test ----

std::vector<std::uint32_t> bits(const Value& v) {
    std::vector<std::uint32_t> out;
    for (int i = 0; i < componentCount(v.type); ++i) out.push_back(std::bit_cast<std::uint32_t>(v.data[i]));
    return out;
}

::testing::AssertionResult sameBits(const Value& actual, const Value& expected) {
    if (actual.type == expected.type && bits(actual) == bits(expected)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << valueTypeName(actual.type) << " " << formatValue(actual) << " (bits differ from) "
                                         << valueTypeName(expected.type) << " " << formatValue(expected);
}

Value vec(ValueType type, std::initializer_list<float> components) {
    Value v;
    v.type = type;
    std::copy(components.begin(), components.end(), v.data.begin());
    return v;
}

Workspace parsed(const std::string& text, const std::string& file = "test.xml") {
    Result<Workspace> p = parseWorkspaceText(text, file, test::sourceDir() / "effects");
    EXPECT_TRUE(p.ok()) << formatAll(p.diagnostics());
    return p ? *p : Workspace{};
}

// A workspace around `body` (its top-level declarations) that the parser accepts.
std::string workspace(const std::string& body, const std::string& passBody = "") {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<workspace version=\"1\">\n" + body +
           "  <pass name=\"p\">\n" + passBody +
           "    <shader stage=\"fragment\"><![CDATA[out vec4 c; void main() { c = vec4(1.0); }]]></shader>\n"
           "  </pass>\n</workspace>\n";
}

std::string rewritten(std::string_view text, const std::map<std::string, Value>& values) {
    auto out = rewriteVariableValues(text, "test.xml", values);
    EXPECT_TRUE(out.ok()) << (out.ok() ? "" : out.error());
    return out.ok() ? *out : std::string();
}

std::string rejection(std::string_view text, const std::map<std::string, Value>& values) {
    auto out = rewriteVariableValues(text, "test.xml", values);
    EXPECT_FALSE(out.ok()) << "rewritten as:\n" << (out.ok() ? *out : "");
    return out.ok() ? std::string() : out.error();
}

// Everything the parser reads from a workspace except the values of its variables.
std::string everythingButValues(const Workspace& ws) {
    std::ostringstream s;
    auto numbers = [&](auto v) {
        for (int i = 0; i < v.length(); ++i) s << v[i] << ' ';
    };
    auto optional = [&](const std::optional<float>& f) { s << (f ? std::to_string(*f) : "-") << ' '; };
    s << ws.name << '|' << ws.description << '|' << ws.width << 'x' << ws.height << '\n';
    const auto& c = ws.camera;
    numbers(c.target);
    s << c.distance << ' ' << c.yawDegrees << ' ' << c.pitchDegrees << ' ' << c.fovYDegrees << ' ' << c.nearPlane
      << ' ' << c.farPlane << ' ' << c.where.line << '\n';
    auto variable = [&](const Variable& v, bool withValue) {
        s << "var " << v.name << ' ' << valueTypeName(v.value.type) << ' ' << componentCount(v.value.type) << ' ';
        if (withValue) s << formatValue(v.value) << ' ';
        optional(v.min), optional(v.max), optional(v.step);
        s << static_cast<int>(v.widget) << ' ' << v.hdr << ' ' << v.description << ' ' << v.where.line;
        for (const auto& o : v.options) s << " [" << o << ']';
        s << '\n';
    };
    for (const Variable& v : ws.variables) variable(v, false);
    for (const CodeSnippet& cs : ws.snippets) s << "code " << cs.name << ' ' << cs.codeLine << '\n' << cs.code << '\n';
    for (const Texture& t : ws.textures) {
        s << "tex " << t.name << ' ' << static_cast<int>(t.kind) << static_cast<int>(t.layout)
          << static_cast<int>(t.colorSpace) << t.mipmaps << ' ' << t.faceSize << ' ' << t.where.line;
        for (const auto& f : t.files) s << ' ' << f;
        s << '\n';
    }
    for (const RenderTarget& t : ws.targets) {
        s << "target " << t.name << ' ' << targetFormatName(t.format) << ' ' << t.formatVariable << ' '
          << t.size.relative << ' ' << t.size.scaleX << ' ' << t.size.scaleY << ' ' << t.size.width << ' '
          << t.size.height << ' ' << t.mipmaps << ' ';
        numbers(t.initial);
        for (TargetFormat f : t.formats) s << targetFormatName(f) << ' ';
        s << t.where.line << '\n';
    }
    for (const Pass& p : ws.passes) {
        s << "pass " << p.name << ' ' << p.target << ' ' << p.enabled << ' ' << p.where.line << '\n';
        if (p.clear.color) numbers(*p.clear.color);
        s << (p.clear.depth ? std::to_string(*p.clear.depth) : "-") << ' ';
        const BlendState& b = p.blend;
        s << b.enabled << static_cast<int>(b.srcColor) << static_cast<int>(b.dstColor) << static_cast<int>(b.srcAlpha)
          << static_cast<int>(b.dstAlpha) << static_cast<int>(b.colorOp) << static_cast<int>(b.alphaOp) << ' ';
        numbers(b.constant);
        s << p.depth.test << p.depth.write << static_cast<int>(p.depth.func) << static_cast<int>(p.raster.cull)
          << p.raster.frontCounterClockwise << '\n';
        for (const ShaderSource& sh : p.shaders)
            s << "shader " << static_cast<int>(sh.stage) << ' ' << sh.file << ' ' << sh.codeLine << '\n' << sh.code << '\n';
        for (const Sampler& sa : p.samplers) {
            s << "sampler " << sa.uniform << ' ' << sa.texture << ' ' << sa.target << ' ' << sa.previousFrame
              << static_cast<int>(sa.filter) << static_cast<int>(sa.mipmap) << static_cast<int>(sa.wrapS)
              << static_cast<int>(sa.wrapT) << ' ';
            numbers(sa.border);
            s << '\n';
        }
        for (const Variable& v : p.constants) variable(v, true);  // pass constants keep their values
        const DrawCall& d = p.draw;
        s << "draw " << (d.mesh ? static_cast<int>(*d.mesh) : -1) << ' ' << d.file << ' ';
        numbers(d.translate), numbers(d.rotateDegrees), numbers(d.scale);
        s << '\n';
    }
    s << "output " << ws.output.target << ' ' << targetFormatName(ws.output.format) << ' '
      << static_cast<int>(ws.output.transform) << '\n';
    return s.str();
}

// A value of the variable's type that differs from its default in every component and that the
// parser accepts for it (inside min/max, one of the options): floats with many digits.
Value changedValue(const Variable& v) {
    const Value& old = v.value;
    if (old.type == ValueType::Bool) return Value::ofBool(!old.asBool());
    if (old.type == ValueType::Int) {
        int n = static_cast<int>(v.options.size());
        if (n > 1) return Value::ofInt((old.asInt() + 1) % n);
        int next = old.asInt() + 1;
        if (v.max && static_cast<float>(next) > *v.max) next = old.asInt() - 1;
        return Value::ofInt(next);
    }
    static constexpr float candidates[] = {0.1234567f, 3e-7f, 1234.5677f, 0.70710677f, -0.33333334f, 7.654321e-3f};
    constexpr int count = sizeof candidates / sizeof candidates[0];
    Value out = old;
    for (int i = 0; i < componentCount(old.type); ++i) {
        bool found = false;
        for (int k = 0; k < count && !found; ++k) {
            float c = candidates[(i + k) % count];
            if ((v.min && c < *v.min) || (v.max && c > *v.max) || c == old.data[i]) continue;
            out.data[i] = c;
            found = true;
        }
        if (!found) out.data[i] = *v.min + (*v.max - *v.min) * 0.3456789f;
    }
    return out;
}

struct Span {
    size_t begin, end;  // the old value's text, inside its quotes
};

// Where each workspace variable's value text is, found from the parser's line numbers: the
// element starts on its line, and its value attribute follows before the element ends.
std::vector<Span> valueSpans(const std::string& text, const Workspace& ws) {
    std::vector<Span> spans;
    for (const Variable& v : ws.variables) {
        size_t lineStart = 0;
        for (int line = 1; line < v.where.line; ++line) lineStart = text.find('\n', lineStart) + 1;
        size_t begin = text.find(std::string("<") + valueTypeName(v.value.type), lineStart);
        size_t end = text.find("/>", begin);
        std::string element = text.substr(begin, end - begin);
        EXPECT_NE(element.find("name=\"" + v.name + "\""), std::string::npos) << element;
        std::smatch m;
        EXPECT_TRUE(std::regex_search(element, m, std::regex(R"(\svalue\s*=\s*"([^"]*)\")"))) << element;
        spans.push_back({begin + m.position(1), begin + m.position(1) + m.length(1)});
        EXPECT_TRUE(spans.size() == 1 || spans[spans.size() - 2].end < spans.back().begin);
    }
    return spans;
}

// ---- every shipped workspace ----

TEST(VariableValueWriter, EveryEffectWorkspaceChangesOnlyItsValues) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(test::sourceDir() / "effects"))
        if (entry.path().extension() == ".xml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 10u);
    size_t variablesChanged = 0;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        const std::string text = readText(file);
        const Workspace before = parsed(text, file.string());
        std::map<std::string, Value> values;
        for (const Variable& v : before.variables) {
            values[v.name] = changedValue(v);
            ASSERT_NE(bits(values[v.name]), bits(v.value)) << v.name;
        }
        variablesChanged += values.size();
        auto out = rewriteVariableValues(text, file.string(), values);
        ASSERT_TRUE(out.ok()) << out.error();
        const std::string& after = *out;

        // (a) The parser reads the new values bit for bit, and everything else as before.
        const Workspace reread = parsed(after, file.string());
        ASSERT_EQ(reread.variables.size(), before.variables.size());
        for (const Variable& v : reread.variables) EXPECT_TRUE(sameBits(v.value, values.at(v.name))) << v.name;
        EXPECT_EQ(everythingButValues(reread), everythingButValues(before));

        // (b) Outside the old value texts the bytes are the same, in the same order; each new
        // value text parses to the requested value.
        std::vector<Span> spans = valueSpans(text, before);
        size_t oldAt = 0, newAt = 0;
        for (size_t i = 0; i < spans.size(); ++i) {
            const Variable& v = before.variables[i];
            std::string piece = text.substr(oldAt, spans[i].begin - oldAt);
            ASSERT_EQ(after.substr(newAt, piece.size()), piece) << "before the value of " << v.name;
            newAt += piece.size();
            size_t close = after.find('"', newAt);
            ASSERT_NE(close, std::string::npos);
            std::string newText = after.substr(newAt, close - newAt);
            Result<Value> value = parseValue(v.value.type, newText);
            ASSERT_TRUE(value) << v.name << " '" << newText << "': " << value.error();
            EXPECT_TRUE(sameBits(*value, values.at(v.name))) << v.name << " written '" << newText << "'";
            newAt = close;
            oldAt = spans[i].end;
        }
        EXPECT_EQ(after.substr(newAt), text.substr(oldAt));
    }
    EXPECT_GE(variablesChanged, 40u);
}

// ---- hand-written files ----

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

// ---- saving ----

std::set<std::string> filesIn(const fs::path& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
    return names;
}

struct stat statOf(const fs::path& path) {
    struct stat s {};
    EXPECT_EQ(::stat(path.c_str(), &s), 0) << path;
    return s;
}

TEST(VariableValueWriter, SaveReplacesTheFileAndKeepsTheOldOneAsBak) {
    test::ScratchDir dir;
    const std::string original = workspace("  <float name=\"Gain\" value=\"0.50\"/>\n  <int name=\"Mode\" value=\"1\"/>\n");
    fs::path file = dir.write("look.xml", original);
    ASSERT_EQ(::chmod(file.c_str(), 0640), 0);
    ino_t oldInode = statOf(file).st_ino;

    auto saved = saveVariableValues(file, {{"Gain", Value::ofFloat(0.75f)}, {"Mode", Value::ofInt(1)}});
    ASSERT_TRUE(saved.ok()) << saved.error();
    const std::string first = workspace("  <float name=\"Gain\" value=\"0.75\"/>\n  <int name=\"Mode\" value=\"1\"/>\n");
    EXPECT_EQ(readText(file), first);
    EXPECT_EQ(readText(dir / "look.xml.bak"), original);
    EXPECT_EQ(statOf(file).st_mode & 07777, 0640u);
    // The old file itself became the backup (a link, never a moment without look.xml).
    EXPECT_EQ(statOf(dir / "look.xml.bak").st_ino, oldInode);
    EXPECT_NE(statOf(file).st_ino, oldInode);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml", "look.xml.bak"}));

    ASSERT_TRUE(saveVariableValues(file, {{"Mode", Value::ofInt(3)}}).ok());
    EXPECT_EQ(readText(file), workspace("  <float name=\"Gain\" value=\"0.75\"/>\n  <int name=\"Mode\" value=\"3\"/>\n"));
    EXPECT_EQ(readText(dir / "look.xml.bak"), first);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml", "look.xml.bak"}));
}

TEST(VariableValueWriter, SaveWithNothingChangedWritesNothing) {
    test::ScratchDir dir;
    fs::path file = dir.write("look.xml", workspace("  <float name=\"Gain\" value=\"0.50\"/>\n"));
    ino_t inode = statOf(file).st_ino;
    ASSERT_TRUE(saveVariableValues(file, {{"Gain", Value::ofFloat(0.5f)}}).ok());
    EXPECT_EQ(statOf(file).st_ino, inode);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml"}));
}

TEST(VariableValueWriter, SaveRefusesValuesTheFileCouldNotLoad) {
    test::ScratchDir dir;
    const std::string original = workspace("  <float name=\"Gain\" value=\"1\" min=\"0\" max=\"4\"/>\n");
    fs::path file = dir.write("look.xml", original);
    auto saved = saveVariableValues(file, {{"Gain", Value::ofFloat(5.0f)}});
    ASSERT_FALSE(saved.ok());
    EXPECT_EQ(saved.error(), "not saved: with the new values, " + file.string() + " would not load:\n" + file.string() +
                                 ":3: error: <float name=\"Gain\">: value 5 lies outside [0, 4]");
    EXPECT_EQ(readText(file), original);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml"}));

    auto unknown = saveVariableValues(file, {{"Gian", Value::ofFloat(1.0f)}});
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error(), file.string() + ": error: variable 'Gian': the workspace has no variable 'Gian' (it has: Gain)");
    EXPECT_EQ(readText(file), original);

    auto missing = saveVariableValues(dir / "gone.xml", {{"Gain", Value::ofFloat(1.0f)}});
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error(), "cannot read '" + (dir / "gone.xml").string() + "': No such file or directory");
}

TEST(VariableValueWriter, SaveFollowsASymbolicLink) {
    test::ScratchDir dir;
    const std::string original = workspace("  <float name=\"Gain\" value=\"1\"/>\n");
    fs::path real = dir.write("real.xml", original);
    fs::path link = dir / "link.xml";
    fs::create_symlink("real.xml", link);
    ASSERT_TRUE(saveVariableValues(link, {{"Gain", Value::ofFloat(2.0f)}}).ok());
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(readText(real), workspace("  <float name=\"Gain\" value=\"2\"/>\n"));
    EXPECT_EQ(readText(dir / "real.xml.bak"), original);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"link.xml", "real.xml", "real.xml.bak"}));
}

TEST(AtomicFile, WritesNewFilesAndOptionallyNoBackup) {
    test::ScratchDir dir;
    fs::path file = dir / "new.txt";
    ASSERT_TRUE(writeFileAtomically(file, "one\n").ok());
    EXPECT_EQ(readText(file), "one\n");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"new.txt"}));  // nothing to back up
    ASSERT_TRUE(writeFileAtomically(file, "two\n", false).ok());
    EXPECT_EQ(readText(file), "two\n");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"new.txt"}));
    ASSERT_EQ(::chmod(file.c_str(), 0604), 0);
    ASSERT_TRUE(writeFileAtomically(file, "three\n").ok());
    EXPECT_EQ(statOf(file).st_mode & 07777, 0604u);
    EXPECT_EQ(statOf(dir / "new.txt.bak").st_mode & 07777, 0604u);
    EXPECT_EQ(readText(dir / "new.txt.bak"), "two\n");
}

TEST(AtomicFile, AReaderAlwaysFindsTheOldOrTheNewCompleteFile) {
    // While one thread saves again and again, another keeps reading the file: every read must
    // find the file and see one of the two complete versions, never a missing or partial one.
    test::ScratchDir dir;
    const std::string a(200000, 'a'), b(300000, 'b');
    fs::path file = dir.write("look.xml", a);
    std::atomic<bool> done{false};
    std::atomic<int> reads{0}, missing{0}, partial{0};
    std::thread reader([&] {
        while (!done) {
            std::string seen;
            int fd = ::open(file.c_str(), O_RDONLY);
            if (fd < 0) {
                ++missing;
                continue;
            }
            char buffer[65536];
            for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) seen.append(buffer, static_cast<size_t>(n));
            ::close(fd);
            if (seen != a && seen != b) ++partial;
            ++reads;
        }
    });
    for (int i = 0; i < 100; ++i) ASSERT_TRUE(writeFileAtomically(file, i % 2 ? a : b).ok());
    done = true;
    reader.join();
    EXPECT_GT(reads.load(), 0);
    EXPECT_EQ(missing.load(), 0);
    EXPECT_EQ(partial.load(), 0);
    EXPECT_EQ(readText(file), a);
    EXPECT_EQ(readText(dir / "look.xml.bak"), b);
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml", "look.xml.bak"}));
}

TEST(AtomicFile, MissingFolderIsAnErrorNamingThePath) {
    test::ScratchDir dir;
    fs::path file = dir / "missing" / "look.xml";
    auto written = writeFileAtomically(file, "x");
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error(), "cannot save '" + file.string() + "': cannot create a temporary file in '" +
                                   (dir / "missing").string() + "': No such file or directory");
    EXPECT_TRUE(filesIn(dir.path()).empty());
}

TEST(AtomicFile, AFolderInThePlaceOfTheFileIsAnError) {
    test::ScratchDir dir;
    fs::create_directory(dir / "look.xml");
    auto written = writeFileAtomically(dir / "look.xml", "x");
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error(), "cannot save '" + (dir / "look.xml").string() + "': it is not a regular file");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml"}));
}

TEST(AtomicFile, ABackupThatCannotBeReplacedLeavesEverythingAsItWas) {
    test::ScratchDir dir;
    fs::path file = dir.write("look.xml", "old");
    fs::create_directory(dir / "look.xml.bak");
    fs::path bak = dir / "look.xml.bak";
    dir.write("look.xml.bak/keep", "k");
    auto written = writeFileAtomically(file, "new");
    ASSERT_FALSE(written.ok());
    EXPECT_NE(written.error().find("cannot save '" + file.string() + "': cannot rename '"), std::string::npos)
        << written.error();
    EXPECT_NE(written.error().find("to '" + bak.string() + "': Is a directory"), std::string::npos) << written.error();
    EXPECT_EQ(readText(file), "old");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml", "look.xml.bak"}));
}

TEST(AtomicFile, AFailedWriteLeavesTheOriginalAndNoTemporaryFile) {
    // A file size limit makes write() fail half way (EFBIG), as a full disk would; this works
    // for root too, whom a read-only folder does not stop.
    test::ScratchDir dir;
    fs::path file = dir.write("look.xml", "old contents");
    struct rlimit saved {};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    struct rlimit small = saved;
    small.rlim_cur = 4096;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    auto written = writeFileAtomically(file, std::string(100000, 'x'));
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previousHandler);
    ASSERT_FALSE(written.ok());
    EXPECT_NE(written.error().find("cannot save '" + file.string() + "': cannot write '"), std::string::npos)
        << written.error();
    EXPECT_NE(written.error().find("': File too large"), std::string::npos) << written.error();
    EXPECT_EQ(readText(file), "old contents");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml"}));
}

TEST(AtomicFile, AReadOnlyFolderIsAnError) {
    if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders";
    test::ScratchDir dir;
    fs::path file = dir.write("look.xml", "old");
    ASSERT_EQ(::chmod(dir.path().c_str(), 0555), 0);
    auto written = writeFileAtomically(file, "new");
    ::chmod(dir.path().c_str(), 0755);
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error(), "cannot save '" + file.string() + "': cannot create a temporary file in '" +
                                   dir.path().string() + "': Permission denied");
    EXPECT_EQ(readText(file), "old");
    EXPECT_EQ(filesIn(dir.path()), (std::set<std::string>{"look.xml"}));
}

}  // namespace
}  // namespace rmfx
