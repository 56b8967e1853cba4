#pragma once
// The C preprocessor of ReShade FX effects (.fx, .fxh): the first step of opening a ReShade effect.
// It turns an effect file into one text with every include, macro and condition resolved, and
// remembers where each of its lines was written, so that later messages point at the user's file.
//
//   ReshadeInput input;
//   input.file = "Shaders/Deband.fx";
//   input.settings.includePaths = {"Shaders"};
//   Diagnostics diagnostics;
//   PreprocessedReshade out = preprocessReshade(input, diagnostics);
//   out.origin(12) → {"Shaders/ReShade.fxh", 40}
//
// What it does, as ReShade's own preprocessor (crosire/reshade, effect_preprocessor.cpp) does:
// - `#include "file"` (and `<file>`, or a macro giving either) looks in the including file's
//   folder, then in settings.includePaths; `#pragma once`; a file including itself is an error.
// - `#define` / `#undef`, object-like and function-like (ReshadeMacros.h); redefining a macro is
//   an error, as in ReShade, even with the same text.
// - `#if` / `#elif` with `defined X`, `defined(X)` and ReShade's `exists "file"`, `#ifdef`,
//   `#ifndef`, `#else`, `#endif` (ReshadeExpression.h); an `#if` left open at the end of its file
//   is an error.
// - `#error` stops with an error; `#warning` warns; `#pragma message "…"` is collected in
//   `messages`; `#pragma reshade …` and `#pragma warning …` in `pragmas` (ReShade reads the first,
//   and hands the second to its compiler); other pragmas warn "unknown pragma ignored".
// - `#line N ["file"]` renumbers the lines after it.
// - The macros of ReshadeSettings.h are defined first.
// Comments become one space, continuations join lines; every line a directive (an #include too,
// before the lines it brings), a skipped block or a comment takes stays as an empty line, and a
// macro call whose arguments run over several lines expands on its first line, followed by empty
// ones. So every line of every file read appears once per inclusion, in order, and each output
// line has an origin. Every problem is a Diagnostic at the user's file and line
// (the line of the call for a problem inside a macro), its element the directive ("#include") or
// the macro ("macro BLUR").
//
// Where it differs from ReShade's (crosire/reshade's effect_preprocessor.cpp as read on 2026-12-08),
// each a superset or a clearer stop: `#error` ends the run (ReShade reads on for more errors);
// `#pragma message` is collected (ReShade warns "unknown pragma ignored"); `#include <file>` and a
// name whose case or slashes differ from the file's are found (ReShade, on Windows, finds the
// latter); #if computes in 64 bits and knows ?:; `F()` gives a one-parameter F an empty argument
// (ReShade warns and drops the call); #error and #warning take plain text besides a string.
// ReShade's __RESHADE_PERMUTATION__ and BUFFER_COLOR_FORMAT are not defined.
//
// Limits, each an error that ends the run rather than a hang: includes nested 32 deep, 4096
// includes, 16 MiB read in all, 16 MiB of output, and the macro limits of ReshadeMacros.h.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "frontend/reshade/ReshadeSettings.h"

namespace rmfx {

struct ReshadeInput {
    std::filesystem::path file;       // the effect; its folder is searched first for includes
    std::optional<std::string> code;  // its text when the caller has it (an editor's buffer); else read from `file`
    ReshadeSettings settings;
};

// A macro the effect tested with #ifdef or #ifndef while it was not defined, or defined by ReShade
// or the user: ReShade's "preprocessor definitions" of an effect, which its overlay lets the user
// change. Only object-like macros still defined at the end are listed, by name.
struct ReshadeDefinition {
    std::string name;
    std::string value;         // the value it had in this run (the user's, when given)
    std::string defaultValue;  // what the effect's own `#define NAME …` under the test says; "" when it has none
    SourceLocation where;      // the first #ifdef / #ifndef that tested it
    bool fromUser = false;     // the value came from settings.defines
    // ReShade's overlay shows it: not a name shorter than 8 characters, starting with '_' or
    // BUFFER_ or RESHADE_, or holding INCLUDE_.
    bool shownInUi = false;
};

struct ReshadeMessage {
    SourceLocation where;
    std::string text;  // the string of `#pragma message "…"`, its escapes kept
};

struct ReshadePragma {
    SourceLocation where;
    std::string name;       // "reshade" or "warning"
    std::string arguments;  // the rest of the line, macros expanded: "skipoptimization"
};

struct PreprocessedReshade {
    std::string code;                          // every line ends with '\n'
    std::vector<SourceLocation> lineOrigins;   // lineOrigins[i]: where line i + 1 of code was written
    std::vector<std::filesystem::path> files;  // every file read, the effect first (for hot reload)
    std::vector<ReshadeDefinition> definitions;
    std::vector<ReshadeMessage> messages;
    std::vector<ReshadePragma> pragmas;

    // Where a 1-based line of `code` was written; out-of-range lines clamp to the first and last.
    SourceLocation origin(int line) const;
};

// Problems are appended to `diagnostics`; the output is whatever was preprocessed before an error
// that ends the run (the files read so far, for hot reload, included).
PreprocessedReshade preprocessReshade(const ReshadeInput& input, Diagnostics& diagnostics);

}  // namespace rmfx
