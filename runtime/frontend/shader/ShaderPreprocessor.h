#pragma once
// Expands `#include "file"` in shader code and remembers where every resulting line came from,
// so compiler messages ("0:17: …") can be mapped back to the user's file and line.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "model/Workspace.h"

namespace rmfx {

struct PreprocessedShader {
    std::string code;                      // ready for the compiler; starts with #version (GlslLegacy: when the shader has one)
    std::vector<SourceLocation> lineOrigins;  // lineOrigins[i]: origin of line i + 1 of code
    std::vector<std::filesystem::path> files;  // every file read (for hot reload)

    // Maps a 1-based line of `code` to where the user wrote it.
    SourceLocation origin(int line) const;
};

struct ShaderInput {
    std::string code;               // text of the top-level shader
    SourceLocation start;           // file, and the line its first line has there (1 for files)
    std::filesystem::path folder;   // where includes of the top-level text resolve first
    std::filesystem::path root;     // includes may not leave this folder
    std::vector<std::string> defines;  // "NAME" or "NAME VALUE", inserted after #version
    std::vector<std::string> declarations;  // lines inserted after the defines ("uniform bool x;")
    const std::vector<CodeSnippet>* snippets = nullptr;  // found by name before any file
    ShaderDialect dialect = ShaderDialect::Glsl;  // decides the #version put first when the code has none
};

// The text of a shader file; nullopt when it is no regular file (a folder, or a device or FIFO
// such as /dev/zero, whose reading would never end) or cannot be read.
std::optional<std::string> readShaderFile(const std::filesystem::path& file);

// The #version line a shader of this dialect gets when it has none: "#version 450 core",
// "#version 100"; empty for GlslLegacy (no #version means GLSL 1.10) and Hlsl.
const char* defaultVersionLine(ShaderDialect dialect);

// The #version line preprocessed code opens with (preprocessShader moves it first): where the
// line ends (past its newline), the version and whether it is GLSL ES. nullopt: the code has none.
struct OpeningVersion {
    size_t end = 0;
    int number = 0;
    bool es = false;
};
std::optional<OpeningVersion> openingVersion(const std::string& code);

// Includes resolve to a snippet of that name, then relative to the including file, then to `root`. `#pragma once` is honoured.
// Without a #version line, the dialect's defaultVersionLine is put first. The defines and
// declarations follow the #version (or open the text when there is none): plain `#define` and
// `uniform bool` lines, legal in every dialect.
PreprocessedShader preprocessShader(const ShaderInput& input, Diagnostics& diagnostics);

// Rewrites a compiler's info log (glslang, Mesa and NVIDIA styles) into diagnostics located in
// the user's files. Lines the parser does not recognise are kept as messages on the shader.
Diagnostics mapCompilerLog(const std::string& log, const PreprocessedShader& shader, const SourceLocation& fallback,
                           const std::string& element);

}  // namespace rmfx
