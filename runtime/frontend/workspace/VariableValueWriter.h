#pragma once
// The editor's Save: new values of workspace variables written back into the workspace file,
// changing nothing else in it (comments, formatting, attribute order, quotes, line endings,
// encoding declaration and whatever rmfx does not read stay byte for byte as they were).

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "core/Result.h"
#include "core/Value.h"

namespace rmfx {

// `text` with the `value` attribute of each named variable replaced by the new value in its
// shortest form that reads back as the same floats (formatValue). Only workspace variables, the
// variable elements directly inside <workspace>, are changed; pass constants of the same name
// are not. A variable whose file value already reads back bit for bit as the new one keeps its
// text ("0.50" stays "0.50"). A variable without a `value` attribute gets one, right after its
// `name` attribute, in the quotes that attribute uses. Comments, CDATA sections, processing
// instructions and the DOCTYPE are never looked into.
// Errors, one line each, "FILE:LINE: error: <element name="X">: message", name `fileName`:
// malformed XML, a variable the workspace does not declare (or declares twice), a value whose
// type differs from the variable's (a color keeps its count of 3 or 4), a value no file can hold
// (NaN or infinity, an int that is not a whole number up to 2^24, a bool that is not 0 or 1).
Result<std::string> rewriteVariableValues(std::string_view text, const std::string& fileName,
                                          const std::map<std::string, Value>& values);

// Reads `workspaceFile`, rewrites the values (rewriteVariableValues), parses the rewritten text
// with the workspace parser and checks that every variable reads back bit for bit as requested
// (a value outside the variable's min/max, say, makes the file unloadable), and only then
// replaces the file with writeFileAtomically, keeping the previous version as FILE.bak. When no
// value differs from the file, nothing is written. On any error the file is left as it was.
// RenderMonkey .rfx files are refused with an error: they are imported, never rewritten.
Result<void> saveVariableValues(const std::filesystem::path& workspaceFile, const std::map<std::string, Value>& values);

}  // namespace rmfx
