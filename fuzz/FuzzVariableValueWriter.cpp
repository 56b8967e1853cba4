// Fuzz target "variable_value_writer": the editor's Save (runtime/VariableValueWriter.h) over
// arbitrary workspace text. The new values come from a part "//@@ :values" (FuzzInputFiles.h),
// one "NAME TYPE VALUE" a line ("Exposure float 0.5", "Tint color 1 0 0"), or else are every
// variable the text declares, each changed. Properties of a rewrite that succeeds:
//  - outside the `value` attributes of the variables asked for (or the `value` attribute the
//    writer adds after `name`), the text is byte for byte what it was;
//  - each such attribute reads back as the value asked for, bit for bit (bools by truth);
//  - rewriting the result again with the same values changes nothing;
//  - saveVariableValues leaves the rewritten text in the file and the original in FILE.bak, or,
//    when it refuses, the original in the file.

#include <bit>
#include <cmath>
#include <sstream>

#include "frontend/workspace/VariableValueWriter.h"
#include "frontend/workspace/WorkspaceParser.h"
#include "fuzz/FuzzEntries.h"
#include "fuzz/FuzzInputFiles.h"
#include "io/file/AtomicFile.h"
#include "io/xml/XmlTagScanner.h"

namespace rmfx::fuzz {
namespace {

using Values = std::map<std::string, Value>;

Values valuesFromLines(const std::string& text) {
    Values out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string name, type, rest;
        words >> name >> type;
        std::getline(words, rest);
        auto valueType = valueTypeFromElement(type);
        if (name.empty() || !valueType) continue;
        if (Result<Value> value = parseValue(*valueType, rest)) out[name] = *value;
    }
    return out;
}

// Every declared variable with a different value of its type.
Values changedValues(const std::string& text) {
    Values out;
    Result<Workspace> parsed = parseWorkspaceText(text, "fuzz.xml", ".");
    if (!parsed) return out;
    for (const Variable& v : parsed->variables) {
        Value changed = v.value;
        if (v.value.type == ValueType::Bool) changed.data[0] = v.value.asBool() ? 0.0f : 1.0f;
        else if (v.value.type == ValueType::Int) changed.data[0] = v.value.data[0] >= 16777216.0f ? 0.0f : v.value.data[0] + 1.0f;
        else changed.data[0] = std::isfinite(v.value.data[0] * 0.5f + 0.25f) ? v.value.data[0] * 0.5f + 0.25f : 0.0f;
        out[v.name] = changed;
    }
    return out;
}

bool readsBackAs(ValueType declared, const std::string& text, const Value& wanted) {
    Result<Value> value = parseValue(declared, text);
    if (!value || value->type != wanted.type) return false;
    if (wanted.type == ValueType::Bool) return value->asBool() == wanted.asBool();
    for (int i = 0; i < componentCount(wanted.type); ++i)
        if (std::bit_cast<std::uint32_t>(value->data[i]) != std::bit_cast<std::uint32_t>(wanted.data[i])) return false;
    return true;
}

// The spans a rewrite may change, in document order: for each workspace variable asked for,
// its value attribute's contents, or (where it had none) everything the writer inserted.
struct Hole {
    size_t begin = 0, end = 0;
    ValueType declared = ValueType::Float;
    const Value* wanted = nullptr;
};

std::vector<Hole> holes(std::string_view text, const std::vector<xml::StartTag>& tags, const Values& values,
                        const std::vector<bool>* hadValue) {
    std::vector<Hole> out;
    for (size_t i = 1; i < tags.size(); ++i) {
        const xml::StartTag& tag = tags[i];
        auto type = valueTypeFromElement(tag.name);
        const xml::AttributeSpan* name = tag.attribute("name");
        if (tag.parent != 0 || !type || !name) continue;
        auto it = values.find(xml::decodeAttributeValue(text.substr(name->valueBegin, name->valueEnd - name->valueBegin)));
        if (it == values.end()) continue;
        const xml::AttributeSpan* value = tag.attribute("value");
        if (!value) {
            out.push_back({name->valueEnd + 1, name->valueEnd + 1, *type, &it->second});
        } else if (hadValue && !(*hadValue)[i]) {
            out.push_back({name->valueEnd + 1, value->valueEnd + 1, *type, &it->second});
        } else {
            out.push_back({value->valueBegin, value->valueEnd, *type, &it->second});
        }
    }
    return out;
}

void checkRewrite(const std::string& before, const std::string& after, const Values& values) {
    auto tagsBefore = xml::scanStartTags(before, "before");
    auto tagsAfter = xml::scanStartTags(after, "after");
    fuzzCheck(tagsBefore.ok(), "a rewritten text was not well-formed before");
    fuzzCheck(tagsAfter.ok(), "the rewritten text is no longer well-formed: " + (tagsAfter ? "" : tagsAfter.error()));
    fuzzCheck(tagsBefore->size() == tagsAfter->size(), "the rewrite changed the number of elements");
    std::vector<bool> hadValue(tagsBefore->size());
    for (size_t i = 0; i < hadValue.size(); ++i) hadValue[i] = (*tagsBefore)[i].attribute("value") != nullptr;
    std::vector<Hole> was = holes(before, *tagsBefore, values, nullptr);
    std::vector<Hole> is = holes(after, *tagsAfter, values, &hadValue);
    fuzzCheck(was.size() == is.size(), "the rewrite changed which variables it finds");
    size_t b = 0, a = 0;
    for (size_t k = 0; k <= was.size(); ++k) {
        size_t bEnd = k < was.size() ? was[k].begin : before.size();
        size_t aEnd = k < is.size() ? is[k].begin : after.size();
        fuzzCheck(std::string_view(before).substr(b, bEnd - b) == std::string_view(after).substr(a, aEnd - a),
                  "the rewrite changed text outside the value attributes (near byte " + std::to_string(b) + ")");
        if (k == was.size()) break;
        std::string written = after.substr(is[k].begin, is[k].end - is[k].begin);
        if (was[k].begin == was[k].end) {  // inserted: ` value="..."` in the name's quotes
            size_t open = written.find_first_of("\"'");
            written = written.substr(open + 1, written.size() - open - 2);
        }
        fuzzCheck(readsBackAs(is[k].declared, xml::decodeAttributeValue(written), *is[k].wanted),
                  "value '" + written + "' does not read back as " + formatValue(*is[k].wanted));
        b = was[k].end;
        a = is[k].end;
    }
}

void checkSave(const std::string& text, const Values& values, const Result<std::string>& rewritten) {
    std::filesystem::path file = freshScratchFolder() / "workspace.xml";
    writeParts({{"workspace.xml", text}}, file.parent_path());
    Result<void> saved = saveVariableValues(file, values);
    auto now = readWholeFile(file);
    fuzzCheck(now.ok(), "the workspace file is gone after a save");
    if (!saved) {
        fuzzCheck(*now == text, "a refused save changed the file: " + saved.error());
        return;
    }
    fuzzCheck(rewritten.ok() && *now == *rewritten, "the saved file is not the rewritten text");
    if (*rewritten == text) return;
    auto backup = readWholeFile(file.string() + ".bak");
    fuzzCheck(backup.ok() && *backup == text, "the backup is not the previous file");
}

}  // namespace

void fuzzVariableValueWriter(const std::uint8_t* data, std::size_t size) {
    FuzzInput input = splitFuzzInput({reinterpret_cast<const char*>(data), size});
    Values values;
    bool listed = false;
    for (const FuzzPart& part : input.parts)
        if (part.name == ":values") {
            values = valuesFromLines(part.text);
            listed = true;
        }
    if (!listed) values = changedValues(input.main);

    Result<std::string> rewritten = rewriteVariableValues(input.main, "fuzz.xml", values);
    if (rewritten) {
        checkRewrite(input.main, *rewritten, values);
        auto again = rewriteVariableValues(*rewritten, "fuzz.xml", values);
        fuzzCheck(again.ok() && *again == *rewritten, "rewriting the rewritten text with the same values changes it");
    }
    checkSave(input.main, values, rewritten);
}

}  // namespace rmfx::fuzz
