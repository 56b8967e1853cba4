// Fuzz target "shader_preprocessor": preprocessShader over a top-level shader and the files and
// snippets it includes (FuzzInputFiles.h), so includes, cycles, #pragma once and #version
// placement meet arbitrary text. Parts:
//   //@@ NAME          a file NAME under the include root (shaders/... sits beside the top level)
//   //@@ snippet:NAME  a workspace <code> snippet NAME
//   //@@ :inline       the top level is inline workspace code (line 7 of fuzz.xml), not a file
//   //@@ :log          a compiler log, mapped back through the result (mapCompilerLog)
// Properties: one origin per line of the result, which starts with a #version line. The HLSL
// initial-value scanner reads the same text: every global it finds has a name and a line in it.

#include <algorithm>

#include "frontend/shader/HlslGlobalInitializers.h"
#include "frontend/shader/HlslWritableGlobals.h"
#include "frontend/shader/ShaderPreprocessor.h"
#include "fuzz/FuzzEntries.h"
#include "fuzz/FuzzInputFiles.h"

namespace rmfx::fuzz {

void fuzzShaderPreprocessor(const std::uint8_t* data, std::size_t size) {
    FuzzInput input = splitFuzzInput({reinterpret_cast<const char*>(data), size});
    std::filesystem::path root = freshScratchFolder() / "root";
    std::filesystem::create_directories(root / "shaders");

    std::vector<CodeSnippet> snippets;
    std::vector<FuzzPart> files;
    bool inlineTop = false;
    std::string log;
    const std::string workspaceFile = (root / "fuzz.xml").string();
    for (FuzzPart& part : input.parts) {
        if (part.name == ":inline") inlineTop = true;
        else if (part.name == ":log") log = part.text;
        else if (part.name.rfind("snippet:", 0) == 0)
            snippets.push_back({part.name.substr(8), part.text, 20 + static_cast<int>(snippets.size()), {workspaceFile, 19}});
        else files.push_back(part);
    }
    writeParts(files, root);

    ShaderInput shader;
    shader.code = input.main;
    shader.root = root;
    shader.defines = {"RMFX_FUZZ 1"};
    shader.declarations = {"uniform bool rmfx_effect_fuzz;"};
    shader.snippets = &snippets;
    if (inlineTop) {
        shader.start = {workspaceFile, 7};
        shader.folder = root;
    } else {
        std::filesystem::path top = root / "shaders" / "main.glsl";
        writeParts({{"shaders/main.glsl", input.main}}, root);
        shader.start = {top.string(), 1};
        shader.folder = top.parent_path();
    }

    Diagnostics diagnostics;
    PreprocessedShader out = preprocessShader(shader, diagnostics);
    formatAll(diagnostics);
    size_t lines = static_cast<size_t>(std::count(out.code.begin(), out.code.end(), '\n'));
    fuzzCheck(!out.code.empty() && out.code.back() == '\n', "the preprocessed code does not end a line");
    fuzzCheck(lines == out.lineOrigins.size(), "the preprocessed code has " + std::to_string(lines) + " lines but " +
                                                   std::to_string(out.lineOrigins.size()) + " line origins");
    std::string_view first(out.code);
    first = first.substr(first.find_first_not_of(" \t"));
    fuzzCheck(first.rfind("#", 0) == 0 && first.find("version") < first.find('\n'),
              "the preprocessed code does not start with #version");
    for (int line : {-1, 0, 1, static_cast<int>(lines), static_cast<int>(lines) + 1}) out.origin(line);
    formatAll(mapCompilerLog(log, out, shader.start, "<shader>"));
    // Both scanners read the code blanked (HlslBlankedCode.h): blanked once, as they would each do.
    const BlankedHlsl blanked(out.code);
    for (const HlslGlobalInitializer& init : findHlslGlobalInitializers(blanked)) {
        fuzzCheck(!init.name.empty() && !init.declaredType.empty(), "an HLSL global without a name or a type");
        fuzzCheck(init.line >= 1 && static_cast<size_t>(init.line) <= lines + 1,
                  "HLSL global '" + init.name + "' at line " + std::to_string(init.line) + " of " + std::to_string(lines));
        fuzzCheck(init.constant || init.values.empty(), "values read from an initializer that is not constant");
    }
    const HlslWritableGlobals writable = giveWrittenGlobalsACopy(out.code, blanked, "main");
    fuzzCheck(std::count(writable.code.begin(), writable.code.end(), '\n') == static_cast<long>(lines),
              "giving written HLSL globals a copy moved lines");
    fuzzCheck(writable.written.size() == writable.lines.size(), "a written HLSL global without its line");
    for (int line : writable.lines)
        fuzzCheck(line >= 1 && static_cast<size_t>(line) <= lines + 1, "a written HLSL global at line " + std::to_string(line));
}

}  // namespace rmfx::fuzz
