#pragma once
// Whether shader code names an identifier: a whole-word match, not a substring ("Ke" is not in
// "Kernel"), outside comments and string literals.

#include <string>
#include <string_view>

namespace rmfx {

// A character of a C-like identifier: a letter, a digit or '_' (the C locale, as a regex's \w).
bool isIdentifierChar(char c);

bool mentionsIdentifier(std::string_view code, std::string_view name);
// How many times, by the same rules: a declaration and a use are two.
int mentionCount(std::string_view code, std::string_view name);

// Every whole-word `from` in `code` replaced by `to` (comments and strings included: for
// generated code, whose words are all code).
void replaceIdentifier(std::string& code, std::string_view from, std::string_view to);

// The code with its // and /* */ comments and "string literals" turned into spaces, newlines kept
// (offsets and line numbers still match the input).
std::string withoutComments(std::string_view code);

// Whether GLSL code declares a vertex input `name`: a statement holding the word `attribute` or
// `in` before the name, which ends it (";", "," or "["). No regex: shaders can be long.
bool declaresVertexInput(std::string_view code, std::string_view name);

// Whether one line of GLSL holds the word `uniform` and, after it and before a ';', the word `name`
// (comments not skipped). No regex: libstdc++'s recurses once per character of a long line.
bool lineDeclaresUniform(std::string_view line, std::string_view name);

}  // namespace rmfx
