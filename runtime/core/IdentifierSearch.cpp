#include "core/IdentifierSearch.h"

#include <algorithm>
#include <cctype>

namespace rmfx {

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Where `word` occurs in `text` at or after `from` as a whole word; npos when nowhere.
static size_t findWord(std::string_view text, std::string_view word, size_t from = 0) {
    if (word.empty()) return std::string_view::npos;
    for (size_t at = text.find(word, from); at != std::string_view::npos; at = text.find(word, at + 1)) {
        bool before = at > 0 && isIdentifierChar(text[at - 1]);
        bool after = at + word.size() < text.size() && isIdentifierChar(text[at + word.size()]);
        if (!before && !after) return at;
    }
    return std::string_view::npos;
}

void replaceIdentifier(std::string& code, std::string_view from, std::string_view to) {
    if (from.empty()) return;
    for (size_t at = findWord(code, from); at != std::string_view::npos; at = findWord(code, from, at + to.size()))
        code.replace(at, from.size(), to);
}

std::string withoutComments(std::string_view input) {
    std::string out(input);
    size_t i = 0;
    auto blank = [&](size_t end) {  // a line at a time (a fill, where a step per byte was slower)
        end = std::min(end, out.size());
        while (i < end) {
            const size_t line = std::min(out.find('\n', i), end);
            std::fill(out.begin() + static_cast<long>(i), out.begin() + static_cast<long>(line), ' ');
            i = line < end ? line + 1 : end;
        }
    };
    while (i < out.size()) {
        const char next = i + 1 < out.size() ? out[i + 1] : '\0';
        if (out[i] == '/' && next == '/') {
            size_t end = out.find('\n', i);
            blank(end == std::string::npos ? out.size() : end);
        } else if (out[i] == '/' && next == '*') {
            size_t end = out.find("*/", i + 2);
            blank(end == std::string::npos ? out.size() : end + 2);
        } else if (out[i] == '"') {
            size_t end = out.find_first_of("\"\n", i + 1);
            blank(end == std::string::npos ? out.size() : out[end] == '"' ? end + 1 : end);
        } else {
            // On to the next '/' or '"' (a library search rather than a step per byte).
            i = std::min(out.find_first_of("/\"", i + 1), out.size());
        }
    }
    return out;
}

bool mentionsIdentifier(std::string_view text, std::string_view name) {
    if (name.empty() || text.find(name) == std::string_view::npos) return false;
    const std::string uncommented = withoutComments(text);
    return findWord(uncommented, name) != std::string_view::npos;
}

int mentionCount(std::string_view text, std::string_view name) {
    if (name.empty() || text.find(name) == std::string_view::npos) return 0;
    const std::string uncommented = withoutComments(text);
    int count = 0;
    for (size_t at = findWord(uncommented, name); at != std::string_view::npos; at = findWord(uncommented, name, at + 1)) ++count;
    return count;
}

bool declaresVertexInput(std::string_view code, std::string_view name) {
    if (name.empty()) return false;
    for (size_t at = code.find(name); at != std::string_view::npos; at = code.find(name, at + 1)) {
        size_t end = at + name.size();
        if ((at > 0 && isIdentifierChar(code[at - 1])) || (end < code.size() && isIdentifierChar(code[end]))) continue;
        size_t next = code.find_first_not_of(" \t\r\n", end);
        if (next == std::string_view::npos || (code[next] != ';' && code[next] != ',' && code[next] != '[')) continue;
        size_t start = code.find_last_of(";{}", at);
        std::string_view statement = code.substr(start == std::string_view::npos ? 0 : start + 1, at - (start == std::string_view::npos ? 0 : start + 1));
        if (mentionsIdentifier(statement, "attribute") || mentionsIdentifier(statement, "in")) return true;
    }
    return false;
}

bool lineDeclaresUniform(std::string_view line, std::string_view name) {
    constexpr std::string_view keyword = "uniform";
    for (size_t at = findWord(line, keyword); at != std::string_view::npos; at = findWord(line, keyword, at + 1)) {
        std::string_view after = line.substr(at + keyword.size());
        if (findWord(after.substr(0, after.find(';')), name) != std::string_view::npos) return true;
    }
    return false;
}

}  // namespace rmfx
