#include "frontend/reshade/ReshadeTokens.h"

#include <array>
#include <cctype>

namespace rmfx {
namespace {

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\r'; }

// Length of a line break at `at` ("\n" or "\r\n"); 0 when there is none.
size_t lineBreak(std::string_view text, size_t at) {
    if (at < text.size() && text[at] == '\n') return 1;
    if (at + 1 < text.size() && text[at] == '\r' && text[at + 1] == '\n') return 2;
    return 0;
}

// Length of a backslash-newline at `at`; 0 when there is none.
size_t continuation(std::string_view text, size_t at) {
    if (at < text.size() && text[at] == '\\') {
        size_t brk = lineBreak(text, at + 1);
        if (brk) return brk + 1;
    }
    return 0;
}

constexpr std::array<std::string_view, 3> kPunct3{"<<=", ">>=", "..."};
constexpr std::array<std::string_view, 21> kPunct2{"##", "::", "->", "++", "--", "<<", ">>", "<=", ">=", "==", "!=",
                                                   "&&", "||", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^="};

}  // namespace

std::vector<LogicalLine> splitLogicalLines(std::string_view text, int* unterminatedComment) {
    if (unterminatedComment) *unterminatedComment = 0;
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::vector<LogicalLine> lines;
    LogicalLine current;
    int physical = 1;
    size_t i = 0;
    auto finish = [&](size_t breakLength) {
        lines.push_back(std::move(current));
        i += breakLength;
        ++physical;
        current = LogicalLine{};
        current.line = physical;
    };
    while (i < text.size()) {
        if (size_t cont = continuation(text, i)) {
            i += cont;
            ++physical;
            ++current.span;
            continue;
        }
        if (size_t brk = lineBreak(text, i)) {
            finish(brk);
            continue;
        }
        char c = text[i];
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            // To the end of the physical line, as ReShade's lexer reads it: a backslash at the end
            // of a line comment does not carry it onto the next line (C would; GShade's
            // Clarity2.fx ends a comment with "\\" before an #if that ReShade reads).
            while (i < text.size() && !lineBreak(text, i)) ++i;
            current.text += ' ';
            continue;
        }
        if (c == '\\' && i + 1 == text.size()) {  // a continuation with no line after it: nothing
            ++i;
            continue;
        }
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            const int opened = physical;
            i += 2;
            bool closed = false;
            while (i < text.size()) {
                if (text[i] == '*' && i + 1 < text.size() && text[i + 1] == '/') {
                    i += 2;
                    closed = true;
                    break;
                }
                if (size_t brk = lineBreak(text, i)) {
                    i += brk;
                    ++physical;
                    ++current.span;
                } else {
                    ++i;
                }
            }
            if (!closed && unterminatedComment) *unterminatedComment = opened;
            current.text += ' ';
            continue;
        }
        if (c == '"' || c == '\'') {
            // Copied as it is (comment markers inside are text) up to the closing quote or the line's end.
            current.text += c;
            ++i;
            while (i < text.size() && !lineBreak(text, i)) {
                if (size_t cont = continuation(text, i)) {
                    i += cont;
                    ++physical;
                    ++current.span;
                    continue;
                }
                char d = text[i++];
                current.text += d;
                if (d == '\\' && i < text.size() && !lineBreak(text, i)) {
                    current.text += text[i++];
                } else if (d == c) {
                    break;
                }
            }
            continue;
        }
        current.text += c;
        ++i;
    }
    if (!current.text.empty() || current.span > 1) lines.push_back(std::move(current));
    return lines;
}

PpTokens tokenize(std::string_view line) {
    PpTokens tokens;
    size_t i = 0;
    while (i < line.size()) {
        PpToken token;
        const size_t start = i;
        char c = line[i];
        if (blank(c)) {
            while (i < line.size() && blank(line[i])) ++i;
            token.kind = PpToken::Kind::Space;
            token.text = std::string(line.substr(start, i - start));
            tokens.push_back(std::move(token));
            continue;
        }
        if (identStart(c)) {
            while (i < line.size() && identChar(line[i])) ++i;
            token.kind = PpToken::Kind::Identifier;
        } else if (digit(c) || (c == '.' && i + 1 < line.size() && digit(line[i + 1]))) {
            ++i;
            while (i < line.size()) {
                char d = line[i];
                if ((d == '+' || d == '-') && (line[i - 1] == 'e' || line[i - 1] == 'E' || line[i - 1] == 'p' ||
                                               line[i - 1] == 'P')) {
                    ++i;
                } else if (identChar(d) || d == '.') {
                    ++i;
                } else {
                    break;
                }
            }
            token.kind = PpToken::Kind::Number;
        } else if (c == '"' || c == '\'') {
            ++i;
            while (i < line.size()) {
                char d = line[i++];
                if (d == '\\' && i < line.size()) ++i;
                else if (d == c) break;
            }
            token.kind = c == '"' ? PpToken::Kind::String : PpToken::Kind::Char;
        } else {
            token.kind = PpToken::Kind::Punct;
            size_t length = 1;
            for (std::string_view p : kPunct3)
                if (line.substr(i, 3) == p) length = 3;
            if (length == 1)
                for (std::string_view p : kPunct2)
                    if (line.substr(i, 2) == p) length = 2;
            i += length;
            if (length == 1 && !std::ispunct(static_cast<unsigned char>(c))) token.kind = PpToken::Kind::Other;
        }
        token.text = std::string(line.substr(start, i - start));
        tokens.push_back(std::move(token));
    }
    return tokens;
}

std::string joinTokens(const PpTokens& tokens) {
    std::string out;
    for (const PpToken& t : tokens) out += t.text;
    return out;
}

bool wouldGlue(const PpToken& left, const PpToken& right) {
    if (left.text.empty() || right.text.empty() || left.isSpace() || right.isSpace()) return false;
    const char a = left.text.back();
    const char b = right.text.front();
    if (identChar(a) && (identChar(b) || (b == '.' && left.kind == PpToken::Kind::Number))) return true;
    if (a == '.' && digit(b)) return true;
    if (left.kind != PpToken::Kind::Punct || right.kind != PpToken::Kind::Punct) return false;
    const std::string pair{a, b};
    if (pair == "//" || pair == "/*") return true;
    for (std::string_view p : kPunct2)
        if (p == pair) return true;
    return false;
}

}  // namespace rmfx
