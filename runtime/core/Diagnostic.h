#pragma once
// A problem found in user input (a workspace, a shader, an image), located in a file.
// Programming mistakes are asserts; everything the user can get wrong becomes a Diagnostic.

#include <string>
#include <vector>

namespace rmfx {

struct SourceLocation {
    std::string file;  // as the user named it, or the workspace path
    int line = 0;      // 1-based; 0 when the problem has no line (a missing file, say)
};

struct Diagnostic {
    enum class Severity { Error, Warning };

    Severity severity = Severity::Error;
    SourceLocation where;
    std::string element;  // "<pass name=\"blur\">", "variable Exposure_Level", … ; may be empty
    std::string message;

    // "file:line: error: element: message"
    std::string format() const;
};

using Diagnostics = std::vector<Diagnostic>;

bool hasErrors(const Diagnostics& diagnostics);
std::string formatAll(const Diagnostics& diagnostics);

}  // namespace rmfx
