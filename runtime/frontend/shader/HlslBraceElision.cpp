#include "frontend/shader/HlslBraceElision.h"

#include <cctype>
#include <optional>
#include <string_view>
#include <vector>

#include "core/IdentifierSearch.h"

namespace rmfx {
namespace {

// Components of an HLSL vector or matrix type name ("float2" 2, "half3x4" 12); 0 for scalars and
// anything else.
int components(std::string_view type) {
    for (std::string_view base : {"float", "half", "double", "int", "uint", "bool", "min16float", "min10float"}) {
        if (!type.starts_with(base)) continue;
        std::string_view shape = type.substr(base.size());
        if (shape.size() == 1 && shape[0] >= '2' && shape[0] <= '4') return shape[0] - '0';
        if (shape.size() == 3 && shape[0] >= '1' && shape[0] <= '4' && shape[1] == 'x' && shape[2] >= '1' && shape[2] <= '4')
            return (shape[0] - '0') * (shape[2] - '0');
    }
    return 0;
}

size_t skipSpaceBack(std::string_view code, size_t at) {  // the last non-space at or before `at`, npos if none
    while (at != std::string_view::npos && std::isspace(static_cast<unsigned char>(code[at]))) at = at ? at - 1 : std::string_view::npos;
    return at;
}

// The identifier ending at `end` (inclusive): its first character's offset, npos if none.
size_t identifierStart(std::string_view code, size_t end) {
    if (end == std::string_view::npos || !isIdentifierChar(code[end])) return std::string_view::npos;
    size_t start = end;
    while (start > 0 && isIdentifierChar(code[start - 1])) --start;
    return start;
}

struct FlatList {
    std::vector<std::pair<size_t, size_t>> elements;  // [first, last] offsets of each expression
    size_t close = 0;                                 // the closing brace
};

// The top-level comma-separated expressions between the brace at `open` and its match; nullopt
// when the list holds braces of its own or never closes.
std::optional<FlatList> flatList(std::string_view code, size_t open) {
    FlatList list;
    int parens = 0;
    size_t start = open + 1;
    auto finish = [&](size_t end) {  // [start, end) holds one element, or only space (a trailing comma)
        size_t first = start;
        while (first < end && std::isspace(static_cast<unsigned char>(code[first]))) ++first;
        if (first == end) return false;
        size_t last = end - 1;
        while (std::isspace(static_cast<unsigned char>(code[last]))) --last;
        list.elements.emplace_back(first, last);
        return true;
    };
    for (size_t i = open + 1; i < code.size(); ++i) {
        const char c = code[i];
        if (c == '{') return std::nullopt;
        if (c == '(') ++parens;
        if (c == ')') --parens;
        if (c == ',' && parens == 0) {
            if (!finish(i)) return std::nullopt;  // an empty element: not a list we understand
            start = i + 1;
        }
        if (c == '}') {
            finish(i);  // nothing after a trailing comma is fine
            list.close = i;
            return list;
        }
    }
    return std::nullopt;
}

}  // namespace

std::string nestFlatArrayInitializers(const std::string& original) {
    const std::string blanked = withoutComments(original);  // same offsets, comments and strings as spaces
    const std::string_view code = blanked;
    std::vector<std::pair<size_t, char>> inserts;  // offset (before which) and brace
    for (size_t equals = code.find('='); equals != std::string_view::npos; equals = code.find('=', equals + 1)) {
        if (equals + 1 < code.size() && code[equals + 1] == '=') { ++equals; continue; }  // ==
        size_t open = code.find_first_not_of(" \t\r\n", equals + 1);
        if (open == std::string_view::npos || code[open] != '{') continue;
        // Backwards: ']' N '[' NAME TYPE.
        size_t bracket = skipSpaceBack(code, equals ? equals - 1 : std::string_view::npos);
        if (bracket == std::string_view::npos || code[bracket] != ']') continue;
        size_t openBracket = code.rfind('[', bracket);
        if (openBracket == std::string_view::npos) continue;
        std::string_view countText = code.substr(openBracket + 1, bracket - openBracket - 1);
        while (!countText.empty() && std::isspace(static_cast<unsigned char>(countText.front()))) countText.remove_prefix(1);
        while (!countText.empty() && std::isspace(static_cast<unsigned char>(countText.back()))) countText.remove_suffix(1);
        if (countText.empty() || countText.size() > 6 ||
            countText.find_first_not_of("0123456789") != std::string_view::npos)
            continue;
        const size_t count = std::stoul(std::string(countText));
        size_t nameEnd = skipSpaceBack(code, openBracket ? openBracket - 1 : std::string_view::npos);
        size_t nameStart = identifierStart(code, nameEnd);
        if (nameStart == std::string_view::npos || nameStart == 0) continue;
        size_t typeEnd = skipSpaceBack(code, nameStart - 1);
        size_t typeStart = identifierStart(code, typeEnd);
        if (typeStart == std::string_view::npos) continue;
        const int perElement = components(code.substr(typeStart, typeEnd - typeStart + 1));
        if (perElement < 2 || count == 0) continue;
        std::optional<FlatList> list = flatList(code, open);
        if (!list || list->elements.size() != count * static_cast<size_t>(perElement)) continue;
        for (size_t e = 0; e < count; ++e) {
            inserts.emplace_back(list->elements[e * perElement].first, '{');
            inserts.emplace_back(list->elements[e * perElement + perElement - 1].second + 1, '}');
        }
        equals = list->close;
    }
    if (inserts.empty()) return original;
    std::string out;
    out.reserve(original.size() + inserts.size());
    size_t copied = 0;
    for (const auto& [at, brace] : inserts) {
        out.append(original, copied, at - copied);
        out += brace;
        copied = at;
    }
    out.append(original, copied);
    return out;
}

}  // namespace rmfx
