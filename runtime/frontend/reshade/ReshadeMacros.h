#pragma once
// The macros of a ReShade FX preprocessing run and their expansion (ReshadePreprocessor.h).
//
//   #define BUFFER_PIXEL_SIZE float2(BUFFER_RCP_WIDTH, BUFFER_RCP_HEIGHT)
//   #define CAT(a, b) a##b
//   #define STR(x) #x
//   CAT(tex, 2D)(s, BUFFER_PIXEL_SIZE); STR(a "b")
//     → tex2D(s, float2((1.0 / BUFFER_WIDTH)… expanded…)); "a \"b\""
//
// As a C preprocessor: object-like and function-like macros (variadic with `...` and
// __VA_ARGS__, `, ## __VA_ARGS__` dropping the comma when there are none), `#` and `##`,
// arguments expanded before they are put in (not those beside `#` or `##`), the result scanned
// again, and a macro never expanded inside its own expansion. __FILE__, __FILE_NAME__,
// __FILE_STEM__ and __LINE__ are built in. A function-like macro whose arguments run past the
// line takes the lines after it (the caller hands them over). Limits keep a hostile file from
// growing without end: 256 macros nested in one another ("macro recursion too high", as ReShade
// says), 2^20 tokens and 2^18 expansions for one line.

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/Diagnostic.h"
#include "frontend/reshade/ReshadeTokens.h"

namespace rmfx {

struct ReshadeMacro {
    enum class Origin { Predefined, User, File };

    std::string name;
    std::vector<std::string> params;  // a variadic macro's last is __VA_ARGS__
    bool functionLike = false;
    bool variadic = false;
    PpTokens body;  // blanks collapsed to one Space token, none at either end
    Origin origin = Origin::File;
    SourceLocation where;

    std::string text() const { return joinTokens(body); }
};

// What follows `#define` (or a caller's "NAME VALUE"): the macro, or why it is malformed
// ("macro name expected", "'#' is not followed by a macro parameter", …).
struct ParsedDefinition {
    std::optional<ReshadeMacro> macro;
    std::string error;
};
ParsedDefinition parseDefinition(const PpTokens& afterDirective);

class MacroTable {
public:
    const ReshadeMacro* find(const std::string& name) const;
    // False (the table unchanged) when a macro of that name exists: ReShade refuses any
    // redefinition, even the same text.
    bool define(ReshadeMacro macro);
    void undefine(const std::string& name);
    // Defined as a macro or built in (__FILE__, __LINE__, …).
    bool isDefined(const std::string& name) const;
    static bool isBuiltIn(const std::string& name);

    // A small number per name, for the macros a token came out of.
    int idOf(const std::string& name);

private:
    std::unordered_map<std::string, ReshadeMacro> macros_;
    std::unordered_map<std::string, int> ids_;
};

struct ExpansionSite {
    std::string file;  // as __FILE__ gives it
    int line = 0;      // as __LINE__ gives it
    // In an #if: the name after `defined` (or `defined (`) is not expanded.
    bool protectDefined = false;
};

struct ExpansionProblem {
    bool error = true;  // false: a warning (ReShade's for a call with the wrong number of arguments)
    std::string macro;  // the macro it is about; may be empty
    std::string message;
};

// Appends the tokens of the next line of text to `tokens` (a Space first, for the line break);
// false when there is none (a directive or the end of the file comes next) or, with
// `onlyOpeningCall`, when that line does not start with '(' (a function-like macro's name at the
// end of a line is then a name, and the next line keeps its own line).
using MoreLines = std::function<bool(PpTokens& tokens, bool onlyOpeningCall)>;

// Expands the macros of `tokens`. `more` (may be null) extends a call whose arguments run on.
// Problems are appended to `problems`; after an error the output holds what was expanded so far.
PpTokens expandMacros(PpTokens tokens, MacroTable& macros, const ExpansionSite& site, const MoreLines* more,
                      std::vector<ExpansionProblem>& problems);

}  // namespace rmfx
