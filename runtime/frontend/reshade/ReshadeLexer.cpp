#include "frontend/reshade/ReshadeLexer.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace rmfx {
namespace {

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool hexDigit(char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; }

constexpr std::array<std::string_view, 2> kPunct3{"<<=", ">>="};
constexpr std::array<std::string_view, 20> kPunct2{"::", "->", "++", "--", "<<", ">>", "<=", ">=", "==", "!=",
                                                   "&&", "||", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^="};

// The length of the number at `at` and whether it is a Float.
size_t numberLength(std::string_view code, size_t at, bool& isFloat) {
    size_t i = at;
    isFloat = false;
    if (code[i] == '0' && i + 1 < code.size() && (code[i + 1] == 'x' || code[i + 1] == 'X')) {
        i += 2;
        while (i < code.size() && hexDigit(code[i])) ++i;
    } else {
        while (i < code.size() && digit(code[i])) ++i;
        if (i < code.size() && code[i] == '.') {
            isFloat = true;
            ++i;
            while (i < code.size() && digit(code[i])) ++i;
        }
        if (i < code.size() && (code[i] == 'e' || code[i] == 'E')) {
            size_t e = i + 1;
            if (e < code.size() && (code[e] == '+' || code[e] == '-')) ++e;
            if (e < code.size() && digit(code[e])) {
                isFloat = true;
                i = e;
                while (i < code.size() && digit(code[i])) ++i;
            }
        }
    }
    while (i < code.size() && std::string_view("uUlLfFhH").find(code[i]) != std::string_view::npos) {
        if (code[i] == 'f' || code[i] == 'F' || code[i] == 'h' || code[i] == 'H') isFloat = true;
        ++i;
    }
    return i - at;
}

}  // namespace

ReshadeLexed lexReshade(std::string_view code, size_t maxTokens) {
    ReshadeLexed out;
    int line = 1;
    size_t i = 0;
    auto push = [&](ReshadeToken::Kind kind, size_t begin, size_t end) {
        out.tokens.push_back({kind, static_cast<uint32_t>(begin), static_cast<uint32_t>(end - begin), line});
    };
    while (i < code.size()) {
        const char c = code[i];
        if (c == '\n') {
            ++line;
            ++i;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++i;
            continue;
        }
        if (c == '/' && i + 1 < code.size() && code[i + 1] == '/') {
            while (i < code.size() && code[i] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < code.size() && code[i + 1] == '*') {
            i += 2;
            while (i < code.size() && !(code[i] == '*' && i + 1 < code.size() && code[i + 1] == '/')) {
                if (code[i] == '\n') ++line;
                ++i;
            }
            i = std::min(code.size(), i + 2);
            continue;
        }
        if (out.tokens.size() >= maxTokens) {
            out.tooMany = true;
            break;
        }
        const size_t begin = i;
        if (identStart(c)) {
            while (i < code.size() && identChar(code[i])) ++i;
            push(ReshadeToken::Kind::Identifier, begin, i);
        } else if (digit(c) || (c == '.' && i + 1 < code.size() && digit(code[i + 1]))) {
            bool isFloat = false;
            i += numberLength(code, i, isFloat);
            push(isFloat ? ReshadeToken::Kind::Float : ReshadeToken::Kind::Int, begin, i);
        } else if (c == '"' || c == '\'') {
            ++i;
            while (i < code.size() && code[i] != c && code[i] != '\n') i += code[i] == '\\' && i + 1 < code.size() && code[i + 1] != '\n' ? 2 : 1;
            if (i < code.size() && code[i] == c) ++i;
            push(c == '"' ? ReshadeToken::Kind::String : ReshadeToken::Kind::Char, begin, i);
        } else {
            size_t length = 1;
            for (std::string_view p : kPunct3)
                if (code.substr(i, 3) == p) length = 3;
            if (length == 1)
                for (std::string_view p : kPunct2)
                    if (code.substr(i, 2) == p) length = 2;
            const bool known = std::string_view("{}[]()<>;:,.=+-*/%&|^!~?#").find(c) != std::string_view::npos;
            i += length;
            push(known || length > 1 ? ReshadeToken::Kind::Punct : ReshadeToken::Kind::Bad, begin, i);
        }
    }
    out.tokens.push_back({ReshadeToken::Kind::End, static_cast<uint32_t>(i), 0, line});
    return out;
}

}  // namespace rmfx
