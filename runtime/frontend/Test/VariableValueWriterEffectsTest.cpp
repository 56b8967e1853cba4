// Every shipped workspace (effects/*.xml) with every variable changed: the writer changes only the
// values' text, and the parser reads back exactly what was written and everything else as before.

#include "frontend/workspace/VariableValueWriter.h"

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "VariableValueWriterTestSupport.h"

namespace rmfx {
namespace {

namespace fs = std::filesystem;
using test::readText;
using namespace test::value_writer;

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

TEST(VariableValueWriterEffects, EveryEffectWorkspaceChangesOnlyItsValues) {
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

}  // namespace
}  // namespace rmfx
