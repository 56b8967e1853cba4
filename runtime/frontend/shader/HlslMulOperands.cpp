#include "frontend/shader/HlslMulOperands.h"

#include <algorithm>
#include <cctype>

#include "core/IdentifierSearch.h"
#include "frontend/shader/HlslBlankedCode.h"

namespace rmfx {
namespace {

constexpr size_t kLongestOperand = 256;

bool identifierStart(char c) { return isIdentifierChar(c) && std::isdigit(static_cast<unsigned char>(c)) == 0; }

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

bool isIdentifier(std::string_view s) {
    if (s.empty() || !identifierStart(s.front())) return false;
    for (char c : s)
        if (!isIdentifierChar(c)) return false;
    return true;
}

// For each opening bracket, where it closes (npos: never, or by the wrong kind): one pass, so
// that code of many nested calls is not scanned again for each.
std::vector<size_t> closers(std::string_view s) {
    std::vector<size_t> closes(s.size(), std::string_view::npos);
    std::vector<size_t> open;  // positions, innermost last
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '(' || c == '[' || c == '{') {
            open.push_back(i);
        } else if (c == ')' || c == ']' || c == '}') {
            if (open.empty()) continue;
            const char opener = s[open.back()];
            if ((opener == '(' && c == ')') || (opener == '[' && c == ']') || (opener == '{' && c == '}')) {
                closes[open.back()] = i;
                open.pop_back();
            } else {
                open.clear();  // a mismatch: nothing open before it closes properly
            }
        }
    }
    return closes;
}

// Where the bracket opened at `open` of a short text (an operand) closes, or npos.
size_t closingOf(std::string_view s, size_t open) { return closers(s)[open]; }

}  // namespace

std::vector<MulCall> mulCalls(const std::string& code) {
    const std::string blanked = blankedHlsl(code);
    const std::string_view s = blanked;
    const std::vector<size_t> closes = closers(s);
    std::vector<MulCall> calls;
    int line = 1;
    size_t counted = 0;  // newlines counted up to here
    for (size_t at = s.find("mul"); at != std::string_view::npos; at = s.find("mul", at + 3)) {
        if (at > 0 && (isIdentifierChar(s[at - 1]) || s[at - 1] == '.')) continue;
        size_t open = at + 3;
        while (open < s.size() && std::isspace(static_cast<unsigned char>(s[open]))) ++open;
        if (open >= s.size() || s[open] != '(') continue;
        const size_t close = closes[open];
        if (close == std::string_view::npos) continue;
        // Operands that say which way round are short (a name, a cast, float4(p, 1)); long ones are
        // not kept, so that deeply nested calls do not copy the code once per level.
        if (close - open > 2 * kLongestOperand) continue;
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
        if (trimmed(operands[0]).size() > kLongestOperand || trimmed(operands[1]).size() > kLongestOperand) continue;
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
    if (type == "vector") return MulOperandShape::Vector;
    if (type == "matrix") return MulOperandShape::Matrix;
    for (std::string_view scalar : {"float", "half", "double", "int", "uint", "bool", "min16float", "min10float", "min16int", "min16uint"}) {
        if (type.substr(0, scalar.size()) != scalar) continue;
        const std::string_view rest = type.substr(scalar.size());
        auto dimension = [](char c) { return c >= '1' && c <= '4'; };
        if (rest.size() == 1 && dimension(rest[0])) return MulOperandShape::Vector;
        if (rest.size() == 3 && dimension(rest[0]) && rest[1] == 'x' && dimension(rest[2])) return MulOperandShape::Matrix;
    }
    return MulOperandShape::Unknown;
}

}  // namespace

std::map<std::string, MulOperandShape> declaredShapes(const std::string& code) {
    const std::string blanked = blankedHlsl(code);
    const std::string_view s = blanked;
    std::map<std::string, MulOperandShape> shapes;
    std::map<std::string, bool> conflicting;
    auto skipSpace = [&](size_t i) {
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        return i;
    };
    size_t i = 0;
    while (i < s.size()) {
        if (!identifierStart(s[i]) || (i > 0 && (isIdentifierChar(s[i - 1]) || s[i - 1] == '.'))) {
            ++i;
            continue;
        }
        size_t end = i;
        while (end < s.size() && isIdentifierChar(s[end])) ++end;
        const MulOperandShape shape = typeShape(s.substr(i, end - i));
        i = end;
        if (shape == MulOperandShape::Unknown) continue;
        // A type, optional template arguments (matrix<float, 4, 4>), then the declared name.
        size_t at = skipSpace(end);
        if (at < s.size() && s[at] == '<') {
            const size_t close = s.substr(0, std::min(s.size(), at + 64)).find_first_of(">;", at);
            if (close == std::string_view::npos || s[close] != '>') continue;
            at = skipSpace(close + 1);
        } else if (at == end) {
            continue;  // no space before the name
        }
        if (at >= s.size() || !identifierStart(s[at])) continue;
        size_t nameEnd = at;
        while (nameEnd < s.size() && isIdentifierChar(s[nameEnd])) ++nameEnd;
        const size_t after = skipSpace(nameEnd);
        if (after >= s.size() || std::string_view(";,:=)[").find(s[after]) == std::string_view::npos) continue;
        const std::string name(s.substr(at, nameEnd - at));
        auto [known, inserted] = shapes.emplace(name, shape);
        if (!inserted && known->second != shape) conflicting[name] = true;
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
    while (name < s.size() && isIdentifierChar(s[name])) ++name;
    if (name > 0 && name < s.size()) {
        size_t open = name;
        while (open < s.size() && std::isspace(static_cast<unsigned char>(s[open]))) ++open;
        if (open < s.size() && s[open] == '(' && closingOf(s, open) == s.size() - 1) return typeShape(s.substr(0, name));
    }
    // A member or swizzle of a variable: identifiers joined by dots.
    if (s.find('.') != std::string_view::npos) {
        for (std::string_view rest = s;;) {
            const size_t dot = rest.find('.');
            if (!isIdentifier(trimmed(rest.substr(0, dot)))) return MulOperandShape::Unknown;
            if (dot == std::string_view::npos) return MulOperandShape::Vector;
            rest = rest.substr(dot + 1);
        }
    }
    if (!isIdentifier(s)) return MulOperandShape::Unknown;
    auto it = declared.find(std::string(s));
    return it == declared.end() ? MulOperandShape::Unknown : it->second;
}

std::vector<MatrixAssignment> matrixAssignments(std::string_view code) {
    std::vector<MatrixAssignment> out;
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; };
    auto skipSpace = [&](size_t i) {
        while (i < code.size() && space(code[i])) ++i;
        return i;
    };
    for (size_t i = 0; i < code.size();) {
        size_t at = i;
        if (i > 0 && isIdentifierChar(code[i - 1])) at = std::string_view::npos;  // no word starts here
        else if (code.substr(i).starts_with("float4x4")) at += 8;
        else if (code.substr(i).starts_with("matrix")) at += 6;
        else at = std::string_view::npos;
        if (at == std::string_view::npos || at >= code.size() || !space(code[at])) {
            ++i;
            continue;
        }
        const size_t nameStart = skipSpace(at);
        size_t nameEnd = nameStart;
        while (nameEnd < code.size() && isIdentifierChar(code[nameEnd])) ++nameEnd;
        const size_t equals = skipSpace(nameEnd);
        if (nameEnd == nameStart || equals >= code.size() || code[equals] != '=') {
            ++i;
            continue;
        }
        const size_t valueStart = skipSpace(equals + 1);
        const size_t semicolon = code.find(';', valueStart);
        if (semicolon == std::string_view::npos) break;  // no ';' from here on: no later match either
        out.push_back({code.substr(nameStart, nameEnd - nameStart), code.substr(valueStart, semicolon - valueStart)});
        i = semicolon + 1;
    }
    return out;
}

}  // namespace rmfx
