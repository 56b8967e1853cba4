#include "frontend/workspace/VariableValueWriter.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/Diagnostic.h"
#include "frontend/rfx/RfxImporter.h"
#include "frontend/workspace/WorkspaceParser.h"
#include "io/file/AtomicFile.h"
#include "io/xml/XmlTagScanner.h"

namespace rmfx {
namespace {

std::string errorLine(const std::string& file, int line, const std::string& element, const std::string& message) {
    return Diagnostic{Diagnostic::Severity::Error, {file, line}, element, message}.format();
}

// "a float", "an int", "a color with 3 numbers (rgb)"
std::string describeType(ValueType type, bool colorCountKnown = true) {
    if (type == ValueType::Color3 && colorCountKnown) return "a color with 3 numbers (rgb)";
    if (type == ValueType::Color4 && colorCountKnown) return "a color with 4 numbers (rgba)";
    return std::string(type == ValueType::Int ? "an " : "a ") + valueTypeName(type);
}

// Whether two values read back as the same bits (0 and -0 differ); a bool is its truth value.
bool sameBits(const Value& a, const Value& b) {
    if (a.type != b.type) return false;
    if (a.type == ValueType::Bool) return a.asBool() == b.asBool();
    for (int i = 0; i < componentCount(a.type); ++i)
        if (std::bit_cast<std::uint32_t>(a.data[i]) != std::bit_cast<std::uint32_t>(b.data[i])) return false;
    return true;
}

// Why no workspace file can hold `value` (the parser would refuse it); empty when one can.
std::string unwritable(const Value& value) {
    for (int i = 0; i < componentCount(value.type); ++i)
        if (!std::isfinite(value.data[i]))
            return componentCount(value.type) == 1
                       ? std::string("the new value is not a finite number")
                       : "component " + std::to_string(i + 1) + " of the new value is not a finite number";
    float f = value.data[0];
    if (value.type == ValueType::Int && (f != std::floor(f) || std::fabs(f) > 16777216.0f))
        return "an int holds a whole number from -16777216 to 16777216, not " + formatValue(Value::ofFloat(f));
    if (value.type == ValueType::Bool && f != 0.0f && f != 1.0f)
        return "a bool holds 0 (false) or 1 (true), not " + formatValue(Value::ofFloat(f));
    return {};
}

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// The new value's text; a bool the file wrote as 1/0 stays in that spelling.
std::string valueText(const Value& value, std::string_view current) {
    if (value.type == ValueType::Bool && (current == "0" || current == "1")) return value.asBool() ? "1" : "0";
    return formatValue(value);
}

struct Edit {
    size_t begin = 0, end = 0;  // the bytes replaced
    std::string text;
};

std::string joined(const std::vector<std::string>& parts, const std::string& separator) {
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : separator) + p;
    return out;
}

}  // namespace

Result<std::string> rewriteVariableValues(std::string_view text, const std::string& fileName,
                                          const std::map<std::string, Value>& values) {
    auto scanned = xml::scanStartTags(text, fileName);
    if (!scanned) return Error{scanned.error()};
    const std::vector<xml::StartTag>& tags = *scanned;
    if (tags.empty()) return Error{errorLine(fileName, 1, "", "no <workspace> element")};
    if (tags[0].name != "workspace")
        return Error{errorLine(fileName, tags[0].line, "",
                               "the root element must be <workspace>, not <" + tags[0].name + ">")};

    auto attributeText = [&](const xml::AttributeSpan& a) {
        return xml::decodeAttributeValue(text.substr(a.valueBegin, a.valueEnd - a.valueBegin));
    };
    // Workspace variables are the children of the root (tag 0); deeper ones are pass constants.
    std::map<std::string, std::vector<size_t>> variables, constants;
    for (size_t i = 1; i < tags.size(); ++i) {
        const xml::AttributeSpan* name = tags[i].attribute("name");
        if (!name || !valueTypeFromElement(tags[i].name)) continue;
        (tags[i].parent == 0 ? variables : constants)[attributeText(*name)].push_back(i);
    }

    std::vector<std::string> errors;
    std::vector<Edit> edits;
    for (const auto& [name, value] : values) {
        auto found = variables.find(name);
        if (found == variables.end()) {
            std::string message = "the workspace has no variable '" + name + "'";
            if (auto constant = constants.find(name); constant != constants.end())
                message += "; line " + std::to_string(tags[constant->second[0]].line) +
                           " declares a constant of that name inside <" + tags[tags[constant->second[0]].parent].name +
                           ">, which is not a workspace variable";
            std::vector<std::string> known;
            for (const auto& entry : variables) known.push_back(entry.first);
            message += known.empty() ? " (it declares none)" : " (it has: " + joined(known, ", ") + ")";
            errors.push_back(errorLine(fileName, 0, "variable '" + name + "'", message));
            continue;
        }
        const xml::StartTag& tag = tags[found->second[0]];
        const std::string label = "<" + tag.name + " name=\"" + name + "\">";
        if (found->second.size() > 1) {
            std::vector<std::string> lines;
            for (size_t i : found->second) lines.push_back(std::to_string(tags[i].line));
            errors.push_back(errorLine(fileName, tags[found->second[1]].line, label,
                                       "variable '" + name + "' is declared more than once (lines " +
                                           joined(lines, ", ") + "): which one to change is unclear"));
            continue;
        }
        ValueType type = *valueTypeFromElement(tag.name);
        const xml::AttributeSpan* valueAttribute = tag.attribute("value");
        std::string currentText = valueAttribute ? attributeText(*valueAttribute) : std::string();
        std::optional<Value> current;
        if (valueAttribute)
            if (Result<Value> parsed = parseValue(type, currentText)) current = *parsed;

        bool isColor = type == ValueType::Color4;  // the element; its count comes from the value
        bool typeMatches = isColor ? (value.type == ValueType::Color3 || value.type == ValueType::Color4) &&
                                         (!current || current->type == value.type)
                                   : value.type == type;
        if (!typeMatches) {
            ValueType declared = isColor && current ? current->type : type;
            errors.push_back(errorLine(fileName, tag.line, label,
                                       "variable '" + name + "' is " + describeType(declared, current.has_value()) +
                                           ", but the new value (" + formatValue(value) + ") is " +
                                           describeType(value.type)));
            continue;
        }
        if (std::string why = unwritable(value); !why.empty()) {
            errors.push_back(errorLine(fileName, tag.line, label, "variable '" + name + "': " + why));
            continue;
        }
        if (current && sameBits(*current, value)) continue;
        std::string newText = valueText(value, trimmed(currentText));
        if (valueAttribute) {
            edits.push_back({valueAttribute->valueBegin, valueAttribute->valueEnd, newText});
        } else {
            const xml::AttributeSpan& nameAttribute = *tag.attribute("name");
            size_t afterName = nameAttribute.valueEnd + 1;  // past the closing quote
            std::string quote(1, nameAttribute.quote);
            edits.push_back({afterName, afterName, " value=" + quote + newText + quote});
        }
    }
    if (!errors.empty()) return Error{joined(errors, "\n")};

    std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.begin < b.begin; });
    std::string out;
    out.reserve(text.size() + 64 * edits.size());
    size_t copied = 0;
    for (const Edit& e : edits) {
        out.append(text.substr(copied, e.begin - copied));
        out += e.text;
        copied = e.end;
    }
    out.append(text.substr(copied));
    return out;
}

Result<void> saveVariableValues(const std::filesystem::path& workspaceFile, const std::map<std::string, Value>& values) {
    if (isRfxPath(workspaceFile))
        return Error{workspaceFile.string() +
                     ": error: saving tweaked values into a RenderMonkey .rfx file is not supported (rmfx never "
                     "rewrites .rfx files); pass the values with --set NAME=VALUE, or note them down"};
    auto text = readWholeFile(workspaceFile);
    if (!text) return Error{text.error()};
    const std::string file = workspaceFile.string();
    auto rewritten = rewriteVariableValues(*text, file, values);
    if (!rewritten) return Error{rewritten.error()};
    if (*rewritten == *text) return {};  // every value is already in the file

    std::filesystem::path folder = workspaceFile.parent_path().empty() ? "." : workspaceFile.parent_path();
    Result<Workspace> parsed = parseWorkspaceText(*rewritten, workspaceFile, folder);
    if (!parsed) {
        std::vector<std::string> problems;
        for (const Diagnostic& d : parsed.diagnostics())
            if (d.severity == Diagnostic::Severity::Error) problems.push_back(d.format());
        return Error{"not saved: with the new values, " + file + " would not load:\n" + joined(problems, "\n")};
    }
    for (const auto& [name, value] : values) {
        const Variable* v = parsed->findVariable(name);
        if (!v || !sameBits(v->value, value))
            return Error{errorLine(file, v ? v->where.line : 0, "variable '" + name + "'",
                                   "not saved: the rewritten file reads " +
                                       (v ? "the value back as " + formatValue(v->value) : std::string("no such variable")) +
                                       " instead of " + formatValue(value))};
    }
    return writeFileAtomically(workspaceFile, *rewritten, true);
}

}  // namespace rmfx
