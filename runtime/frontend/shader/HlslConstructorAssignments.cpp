#include "frontend/shader/HlslConstructorAssignments.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string_view>

#include "core/IdentifierSearch.h"
#include "core/TextEdits.h"
#include "frontend/shader/HlslBlankedCode.h"

namespace rmfx {
namespace {

struct VectorType {
    std::string base;  // "float", "half", "int", …
    int width = 0;     // 1 for a scalar
};

// "float4" → {float, 4}; "half" → {half, 1}; matrices and anything else: nullopt.
std::optional<VectorType> vectorType(std::string_view word) {
    for (const char* base : {"float", "half", "double", "int", "uint", "bool", "min16float", "min10float", "min16int"}) {
        const std::string_view b(base);
        if (!word.starts_with(b)) continue;
        const std::string_view rest = word.substr(b.size());
        if (rest.empty()) return VectorType{std::string(b), 1};
        if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4') return VectorType{std::string(b), rest[0] - '0'};
        return std::nullopt;
    }
    return std::nullopt;
}

size_t skipSpaceBack(const std::string& code, size_t i) {
    while (i > 0 && std::isspace(static_cast<unsigned char>(code[i - 1]))) --i;
    return i;
}

size_t skipSpace(const std::string& code, size_t i) {
    while (i < code.size() && std::isspace(static_cast<unsigned char>(code[i]))) ++i;
    return i;
}

// The word ending at `end` (exclusive), or empty.
std::string_view wordBefore(const std::string& code, size_t end) {
    size_t start = end;
    while (start > 0 && isIdentifierChar(code[start - 1])) --start;
    return std::string_view(code).substr(start, end - start);
}

// The type `name` was last declared with before `limit`: in `TYPE name`, or in a list
// `TYPE a, b, name` of plain names.
std::optional<VectorType> declaredType(const std::string& code, const std::string& name, size_t limit) {
    for (size_t at = code.rfind(name, limit); at != std::string::npos && at > 0; at = code.rfind(name, at - 1)) {
        if (at + name.size() > limit || isIdentifierChar(code[at - 1]) ||
            (at + name.size() < code.size() && isIdentifierChar(code[at + name.size()])))
            continue;
        size_t i = skipSpaceBack(code, at);
        // Back over the list's earlier names: ", b", ", a".
        while (i > 0 && code[i - 1] == ',') {
            i = skipSpaceBack(code, i - 1);
            const std::string_view previous = wordBefore(code, i);
            if (previous.empty()) break;
            i = skipSpaceBack(code, i - previous.size());
        }
        if (std::optional<VectorType> type = vectorType(wordBefore(code, i))) return type;
        if (at == 0) break;
    }
    return std::nullopt;
}

}  // namespace

HlslConstructorAssignments writeOutConstructorAssignments(const std::string& source) {
    HlslConstructorAssignments out;
    out.code = source;
    const std::string code = blankedHlsl(source);
    std::vector<TextEdit> edits;
    int depth = 0, count = 0;
    size_t statementStart = 0;
    for (size_t i = 0; i < code.size(); ++i) {
        const char c = code[i];
        if (c == '{' || c == '}' || c == ';') {
            depth += c == '{' ? 1 : c == '}' ? -1 : 0;
            statementStart = i + 1;
            continue;
        }
        if (depth <= 0 || i != skipSpace(code, statementStart) || !isIdentifierChar(c)) continue;
        // A statement that starts `TYPEn (`.
        size_t wordEnd = i;
        while (wordEnd < code.size() && isIdentifierChar(code[wordEnd])) ++wordEnd;
        const std::optional<VectorType> whole = vectorType(std::string_view(code).substr(i, wordEnd - i));
        const size_t open = skipSpace(code, wordEnd);
        if (!whole || whole->width < 2 || open >= code.size() || code[open] != '(') continue;
        const size_t close = code.find(')', open);
        if (close == std::string::npos) continue;
        // Plain names only, separated by commas.
        std::vector<std::string> names;
        bool plain = true;
        for (size_t k = open + 1; k <= close && plain;) {
            k = skipSpace(code, k);
            size_t e = k;
            while (e < close && isIdentifierChar(code[e])) ++e;
            if (e == k || std::isdigit(static_cast<unsigned char>(code[k]))) plain = false;
            names.emplace_back(code.substr(k, e - k));
            k = skipSpace(code, e);
            if (k < close && code[k] != ',') plain = false;
            ++k;
        }
        const size_t equals = skipSpace(code, close + 1);
        if (!plain || equals + 1 >= code.size() || code[equals] != '=' || code[equals + 1] == '=') continue;
        const size_t end = code.find(';', equals);
        if (end == std::string::npos || code.find_first_of("{}", equals) < end) continue;
        // Each name's width; together they must fill the constructor.
        std::vector<int> widths;
        for (const std::string& name : names) {
            std::optional<VectorType> type = declaredType(code, name, i);
            if (!type || type->base != whole->base) break;
            widths.push_back(type->width);
        }
        int total = 0;
        for (int w : widths) total += w;
        if (widths.size() != names.size() || total != whole->width) continue;

        const std::string temporary = "rm_unpacked_" + std::to_string(++count);
        std::string unpack;
        for (size_t n = 0, offset = 0; n < names.size(); offset += size_t(widths[n]), ++n)
            unpack += " " + names[n] + " = " + temporary + "." + std::string("xyzw").substr(offset, size_t(widths[n])) + ";";
        // The target's newlines stay, so every line after it keeps its number.
        const std::string newlines(static_cast<size_t>(std::count(code.begin() + static_cast<long>(i),
                                                                  code.begin() + static_cast<long>(equals), '\n')),
                                   '\n');
        edits.push_back({i, equals + 1 - i, "{ " + std::string(code.substr(i, wordEnd - i)) + " " + temporary + " =" + newlines});
        edits.push_back({end + 1, 0, unpack + " }"});
        out.lines.push_back(1 + static_cast<int>(std::count(code.begin(), code.begin() + static_cast<long>(i), '\n')));
        i = end;
        statementStart = end + 1;
    }
    if (!edits.empty()) out.code = applyTextEdits(source, std::move(edits));
    return out;
}

}  // namespace rmfx
