#include "frontend/shader/HlslMulOperands.h"

#include <cctype>
#include <regex>

#include "frontend/shader/HlslBlankedCode.h"

namespace rmfx {
namespace {

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool identifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

bool isIdentifier(std::string_view s) {
    if (s.empty() || !identifierStart(s.front())) return false;
    for (char c : s)
        if (!identifierChar(c)) return false;
    return true;
}

// Where the bracket opened at `open` closes, or npos (never, or by the wrong kind of bracket).
size_t closingOf(std::string_view s, size_t open) {
    std::string expected;  // the closers the open brackets want, innermost last
    for (size_t i = open; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '(') expected += ')';
        else if (c == '[') expected += ']';
        else if (c == '{') expected += '}';
        else if (c == ')' || c == ']' || c == '}') {
            if (expected.empty() || expected.back() != c) return std::string_view::npos;
            expected.pop_back();
            if (expected.empty()) return i;
        }
    }
    return std::string_view::npos;
}

}  // namespace

std::vector<MulCall> mulCalls(const std::string& code) {
    const std::string blanked = blankedHlsl(code);
    const std::string_view s = blanked;
    std::vector<MulCall> calls;
    int line = 1;
    size_t counted = 0;  // newlines counted up to here
    for (size_t at = s.find("mul"); at != std::string_view::npos; at = s.find("mul", at + 3)) {
        if (at > 0 && (identifierChar(s[at - 1]) || s[at - 1] == '.')) continue;
        size_t open = at + 3;
        while (open < s.size() && std::isspace(static_cast<unsigned char>(s[open]))) ++open;
        if (open >= s.size() || s[open] != '(') continue;
        const size_t close = closingOf(s, open);
        if (close == std::string_view::npos) continue;
        // The operands: split at the one comma outside any bracket.
        std::vector<std::string_view> operands;
        int depth = 0;
        size_t start = open + 1;
        for (size_t i = open + 1; i < close; ++i) {
            const char c = s[i];
            if (c == '(' || c == '[' || c == '{') ++depth;
            else if (c == ')' || c == ']' || c == '}') --depth;
            else if (c == ',' && depth == 0) {
                operands.push_back(s.substr(start, i - start));
                start = i + 1;
            }
        }
        operands.push_back(s.substr(start, close - start));
        for (; counted < at; ++counted)
            if (s[counted] == '\n') ++line;
        if (operands.size() != 2 || trimmed(operands[0]).empty() || trimmed(operands[1]).empty()) continue;
        calls.push_back({line, std::string(trimmed(operands[0])), std::string(trimmed(operands[1]))});
    }
    return calls;
}

MulOperandVariable mulOperandVariable(std::string_view operand) {
    std::string_view s = trimmed(operand);
    bool transposed = false;
    for (;;) {
        if (!s.empty() && s.front() == '(' && closingOf(s, 0) == s.size() - 1) {
            s = trimmed(s.substr(1, s.size() - 2));  // (x)
            continue;
        }
        if (!s.empty() && s.front() == '(') {
            // A cast: (type) x, the type one identifier.
            const size_t close = closingOf(s, 0);
            if (close == std::string_view::npos || !isIdentifier(trimmed(s.substr(1, close - 1)))) return {};
            s = trimmed(s.substr(close + 1));
            continue;
        }
        constexpr std::string_view transpose = "transpose";
        if (!transposed && s.substr(0, transpose.size()) == transpose) {
            std::string_view rest = trimmed(s.substr(transpose.size()));
            if (!rest.empty() && rest.front() == '(' && closingOf(rest, 0) == rest.size() - 1) {
                transposed = true;
                s = trimmed(rest.substr(1, rest.size() - 2));
                continue;
            }
        }
        break;
    }
    if (!isIdentifier(s)) return {};
    return {std::string(s), transposed};
}

namespace {

// A type name's shape: floatN / halfN / intN… and vector are vectors, floatNxM… and matrix matrices.
MulOperandShape typeShape(std::string_view type) {
    static const std::regex vector(R"((?:float|half|double|int|uint|bool|min16float|min10float|min16int|min16uint)[1-4])");
    static const std::regex matrix(R"((?:float|half|double|int|uint|bool|min16float|min10float|min16int|min16uint)[1-4]x[1-4])");
    const std::string t(type);
    if (t == "vector" || std::regex_match(t, vector)) return MulOperandShape::Vector;
    if (t == "matrix" || std::regex_match(t, matrix)) return MulOperandShape::Matrix;
    return MulOperandShape::Unknown;
}

}  // namespace

std::map<std::string, MulOperandShape> declaredShapes(const std::string& code) {
    const std::string blanked = blankedHlsl(code);
    // A type, optional template arguments (matrix<float, 4, 4>), then the declared name(s).
    static const std::regex declaration(R"(\b([A-Za-z_][A-Za-z0-9_]*)\s*(?:<[^<>;]*>)?\s+([A-Za-z_][A-Za-z0-9_]*)\s*(?=[;,:=)\[]))");
    std::map<std::string, MulOperandShape> shapes;
    std::map<std::string, bool> conflicting;
    for (auto it = std::sregex_iterator(blanked.begin(), blanked.end(), declaration); it != std::sregex_iterator(); ++it) {
        const MulOperandShape shape = typeShape((*it)[1].str());
        if (shape == MulOperandShape::Unknown) continue;
        const std::string name = (*it)[2].str();
        auto [at, inserted] = shapes.emplace(name, shape);
        if (!inserted && at->second != shape) conflicting[name] = true;
    }
    for (const auto& [name, both] : conflicting) shapes.erase(name);
    return shapes;
}

MulOperandShape mulOperandShape(std::string_view operand, const std::map<std::string, MulOperandShape>& declared) {
    std::string_view s = trimmed(operand);
    while (!s.empty() && s.front() == '(' && closingOf(s, 0) == s.size() - 1) s = trimmed(s.substr(1, s.size() - 2));
    if (s.empty()) return MulOperandShape::Unknown;
    if (s.front() == '(') {
        // A cast: its type says it.
        const size_t close = closingOf(s, 0);
        if (close == std::string_view::npos) return MulOperandShape::Unknown;
        return typeShape(trimmed(s.substr(1, close - 1)));
    }
    // A constructor: a type name, then its arguments to the end.
    size_t name = 0;
    while (name < s.size() && identifierChar(s[name])) ++name;
    if (name > 0 && name < s.size()) {
        size_t open = name;
        while (open < s.size() && std::isspace(static_cast<unsigned char>(s[open]))) ++open;
        if (open < s.size() && s[open] == '(' && closingOf(s, open) == s.size() - 1) return typeShape(s.substr(0, name));
    }
    // A member or swizzle of a variable: identifiers joined by dots.
    static const std::regex member(R"([A-Za-z_][A-Za-z0-9_]*(?:\s*\.\s*[A-Za-z_][A-Za-z0-9_]*)+)");
    const std::string text(s);
    if (std::regex_match(text, member)) return MulOperandShape::Vector;
    if (isIdentifier(s)) {
        auto it = declared.find(text);
        return it == declared.end() ? MulOperandShape::Unknown : it->second;
    }
    return MulOperandShape::Unknown;
}

}  // namespace rmfx
