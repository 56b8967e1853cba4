#include "frontend/shader/HlslMulOperands.h"

#include <cctype>

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

}  // namespace rmfx
