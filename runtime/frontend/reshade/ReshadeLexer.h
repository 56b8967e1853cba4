#pragma once
// The tokens of preprocessed ReShade FX code (ReshadePreprocessor.h's output), for the parser
// (ReshadeParser.h). Each token is a place in the code (offset, length) and the line of the code it
// starts on, which PreprocessedReshade::origin maps to the user's file and line.
//
//   lexReshade("float4 x = 1.5f; // c\n").tokens
//     → Identifier "float4", Identifier "x", Punct "=", Float "1.5f", Punct ";", End

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace rmfx {

struct ReshadeToken {
    enum class Kind { End, Identifier, Int, Float, String, Char, Punct, Bad };
    Kind kind = Kind::End;
    uint32_t offset = 0;
    uint32_t length = 0;
    int line = 1;  // 1-based line of the code
};

struct ReshadeLexed {
    std::vector<ReshadeToken> tokens;  // always ends with one End token
    bool tooMany = false;              // lexing stopped at maxTokens (the End token is where it stopped)
};

// Comments are skipped (the preprocessor already made them blanks); an unterminated string runs to
// the end of its line; a character that starts no token is one Bad token. Numbers: decimal, hex
// (0x), octal (leading 0), with a fraction or exponent a Float; suffixes (u, l, f, h) belong to the
// number. Punctuators are the longest of `<<=`, `::`, `&&`, …, else one character.
ReshadeLexed lexReshade(std::string_view code, size_t maxTokens = size_t(4) << 20);

}  // namespace rmfx
