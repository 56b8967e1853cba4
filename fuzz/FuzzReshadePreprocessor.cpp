// Fuzz target "reshade_preprocessor": preprocessReshade over an effect and the files it includes
// (FuzzInputFiles.h: "//@@ NAME" parts are files beside the effect; "//@@ inc/NAME" ones lie in
// the include path), so macros, #if expressions, includes and their limits meet arbitrary text;
// then parseReshadeEffect over its output.
// Properties: one origin per line of the output, which ends a line when it has any; the files
// read start with the effect; the definitions are sorted by name and each is listed once; every
// function body the parser keeps is a span of the output from a '{' (to a '}' when it closes).

#include <algorithm>

#include "frontend/reshade/ReshadeParser.h"
#include "frontend/reshade/ReshadePreprocessor.h"
#include "fuzz/FuzzEntries.h"
#include "fuzz/FuzzInputFiles.h"

namespace rmfx::fuzz {

void fuzzReshadePreprocessor(const std::uint8_t* data, std::size_t size) {
    FuzzInput input = splitFuzzInput({reinterpret_cast<const char*>(data), size});
    std::filesystem::path root = freshScratchFolder() / "root";
    std::filesystem::create_directories(root / "inc");
    writeParts(input.parts, root);
    writeParts({{"main.fx", input.main}}, root);

    ReshadeInput effect;
    effect.file = root / "main.fx";
    effect.settings.includePaths = {root / "inc"};
    effect.settings.defines = {"FUZZ_DEFINE=1", "FUZZ_FLAG"};
    Diagnostics diagnostics;
    PreprocessedReshade out = preprocessReshade(effect, diagnostics);
    formatAll(diagnostics);
    const size_t lines = static_cast<size_t>(std::count(out.code.begin(), out.code.end(), '\n'));
    fuzzCheck(out.code.empty() || out.code.back() == '\n', "the preprocessed effect does not end a line");
    fuzzCheck(lines == out.lineOrigins.size(), "the preprocessed effect has " + std::to_string(lines) + " lines but " +
                                                   std::to_string(out.lineOrigins.size()) + " line origins");
    fuzzCheck(!out.files.empty() && out.files.front() == effect.file, "the files read do not start with the effect");
    for (size_t i = 1; i < out.definitions.size(); ++i)
        fuzzCheck(out.definitions[i - 1].name < out.definitions[i].name, "definitions not sorted, or one listed twice");
    for (int line : {-1, 0, 1, static_cast<int>(lines), static_cast<int>(lines) + 1}) out.origin(line);

    const ReshadeEffect parsed = parseReshadeEffect(out, diagnostics);
    for (const ReshadeFunction& f : parsed.functions) {
        fuzzCheck(f.body.begin < f.body.end && f.body.end <= out.code.size(), "a function body is not a span of the code");
        fuzzCheck(out.code[f.body.begin] == '{', "a function body does not start with '{'");
    }
    fuzzCheck(parsed.order.size() == parsed.uniforms.size() + parsed.textures.size() + parsed.samplers.size() +
                                         parsed.storages.size() + parsed.structs.size() + parsed.variables.size() +
                                         parsed.functions.size() + parsed.techniques.size(),
              "the declarations' order does not list each once");
}

}  // namespace rmfx::fuzz
