#pragma once
// Turns one fuzz input into a main text plus files, so that a single byte string can describe a
// workspace or shader together with the files it names:
//
//   text of the main input (a workspace, a top-level shader)
//   //@@ shaders/blur.glsl
//   contents of that file
//   //@@ common.glsl
//   ...
//
// Files are written under a folder of this process's own, emptied for every input.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rmfx::fuzz {

struct FuzzPart {
    std::string name;  // as written after "//@@ "
    std::string text;
};

struct FuzzInput {
    std::string main;            // everything before the first "//@@ " line
    std::vector<FuzzPart> parts;
};

// Splits at lines starting with "//@@ " (at most 64 parts; later markers stay in the text).
FuzzInput splitFuzzInput(std::string_view bytes);

// An empty folder in memory (/dev/shm) or else under the temp folder, the same for the whole
// process (removed at exit).
const std::filesystem::path& freshScratchFolder();

// Writes each part whose name is a relative path of plain components (letters, digits, '_', '-',
// '.'; ".." too) that stays inside freshScratchFolder() as a file under `folder`; the others are
// skipped, so an input never writes outside the scratch folder.
void writeParts(const std::vector<FuzzPart>& parts, const std::filesystem::path& folder);

}  // namespace rmfx::fuzz
