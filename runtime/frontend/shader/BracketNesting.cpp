#include "frontend/shader/BracketNesting.h"

#include <vector>

namespace rmfx {

std::optional<BracketMismatch> findBracketMismatch(std::string_view code) {
    struct Open {
        char c;
        int line;
    };
    std::vector<Open> open;
    int line = 1;
    for (size_t i = 0; i < code.size(); ++i) {
        char c = code[i];
        if (c == '\n') {
            ++line;
        } else if (c == '/' && i + 1 < code.size() && code[i + 1] == '/') {
            while (i + 1 < code.size() && code[i + 1] != '\n') ++i;
        } else if (c == '/' && i + 1 < code.size() && code[i + 1] == '*') {
            for (i += 2; i < code.size() && !(code[i] == '*' && i + 1 < code.size() && code[i + 1] == '/'); ++i)
                if (code[i] == '\n') ++line;
            ++i;
        } else if (c == '"' || c == '\'') {
            for (++i; i < code.size() && code[i] != c && code[i] != '\n'; ++i)
                if (code[i] == '\\') ++i;
            if (i < code.size() && code[i] == '\n') ++line;
        } else if (c == '(' || c == '[' || c == '{') {
            open.push_back({c, line});
        } else if (c == ')' || c == ']' || c == '}') {
            char expected = c == ')' ? '(' : c == ']' ? '[' : '{';
            if (open.empty())
                return BracketMismatch{line, std::string("'") + c + "' closes nothing"};
            if (open.back().c != expected)
                return BracketMismatch{line, std::string("'") + c + "' closes the '" + open.back().c + "' opened at line " +
                                                 std::to_string(open.back().line)};
            open.pop_back();
        }
    }
    if (!open.empty()) {
        // The outermost unclosed opener: the inner ones usually follow from it.
        return BracketMismatch{open.front().line, std::string("'") + open.front().c + "' is never closed"};
    }
    return std::nullopt;
}

}  // namespace rmfx
