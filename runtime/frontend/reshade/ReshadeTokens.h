#pragma once
// The first phases of the ReShade FX preprocessor (ReshadePreprocessor.h): a file's text split into
// logical lines (line continuations joined, comments replaced by one space, each line knowing the
// physical lines it spans) and a logical line split into preprocessing tokens.
//
//   splitLogicalLines("a /* x\ny */ b\n#define C \\\n 1\n")
//     → {"a   b", line 1, spans 2}, {"#define C  1", line 3, spans 2}

#include <string>
#include <string_view>
#include <vector>

namespace rmfx {

struct LogicalLine {
    std::string text;  // without its line break; comments are one space each
    int line = 1;      // the physical line it starts on (1-based)
    int span = 1;      // how many physical lines it covers (continuations, block comments)
};

// A UTF-8 byte order mark at the start is dropped; "\r\n" counts as one line break. A block comment
// left open ends with the text (`unterminatedComment` then says on which line it opened, else 0).
std::vector<LogicalLine> splitLogicalLines(std::string_view text, int* unterminatedComment = nullptr);

struct PpToken {
    enum class Kind { Identifier, Number, String, Char, Punct, Space, Other };
    Kind kind = Kind::Other;
    std::string text;
    // The macros this token came out of (ids from the macro table, sorted): such a macro is not
    // expanded again from this token, which ends self-reference (`#define X X + 1`).
    std::vector<int> hide;
    bool expanded = false;  // produced by a macro expansion (spacing is guarded where it glues)

    bool is(Kind k, std::string_view t) const { return kind == k && text == t; }
    bool isPunct(std::string_view t) const { return is(Kind::Punct, t); }
    bool isSpace() const { return kind == Kind::Space; }
};

using PpTokens = std::vector<PpToken>;

// Pre-processing tokens as C has them: identifiers, pp-numbers (`1.5f`, `0x1F`, `1e-3`), string and
// character literals (an unterminated one runs to the end of the line), punctuators (the longest
// of `<<=`, `##`, `->`, …), and each run of blanks as one Space token holding it.
PpTokens tokenize(std::string_view line);

// The tokens' text, one after the other.
std::string joinTokens(const PpTokens& tokens);

// Whether `left` followed directly by `right` would read as other tokens (`-` `-1`, `a` `b`).
bool wouldGlue(const PpToken& left, const PpToken& right);

}  // namespace rmfx
