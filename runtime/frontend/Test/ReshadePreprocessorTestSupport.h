#pragma once
// What the ReshadePreprocessor*Test files share: a run over text written to a scratch folder, and
// its output, origins and diagnostics in forms a test compares whole.

#include <string>
#include <vector>

#include "frontend/reshade/ReshadePreprocessor.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {

struct ReshadeRun {
    PreprocessedReshade out;
    Diagnostics diagnostics;
    std::string main;  // the path of the effect file, as origins name it

    // The output's lines with their origins, "file:line|text", the scratch folder cut from names.
    std::vector<std::string> annotated(const std::string& folder) const {
        std::vector<std::string> lines;
        size_t at = 0;
        for (const SourceLocation& origin : out.lineOrigins) {
            const size_t end = out.code.find('\n', at);
            std::string file = origin.file;
            if (file.rfind(folder, 0) == 0) file = file.substr(folder.size() + 1);
            lines.push_back(file + ":" + std::to_string(origin.line) + "|" + out.code.substr(at, end - at));
            at = end + 1;
        }
        return lines;
    }
    // The output's lines that are not empty (blanks aside), "file:line|text".
    std::vector<std::string> solid(const std::string& folder) const {
        std::vector<std::string> lines;
        for (const std::string& line : annotated(folder))
            if (line.find_first_not_of(' ', line.find('|') + 1) != std::string::npos) lines.push_back(line);
        return lines;
    }
    // Every diagnostic formatted, the scratch folder cut from names.
    std::vector<std::string> problems(const std::string& folder) const {
        std::vector<std::string> formatted;
        for (const Diagnostic& d : diagnostics) {
            std::string text = d.format();
            for (size_t at; (at = text.find(folder + "/")) != std::string::npos;) text.erase(at, folder.size() + 1);
            formatted.push_back(text);
        }
        return formatted;
    }
};

// Writes `code` as main.fx in `dir` and preprocesses it with `settings`.
inline ReshadeRun preprocessText(const ScratchDir& dir, const std::string& code, ReshadeSettings settings = {}) {
    ReshadeRun run;
    ReshadeInput input;
    input.file = dir.write("main.fx", code);
    input.settings = std::move(settings);
    run.main = input.file.string();
    run.out = preprocessReshade(input, run.diagnostics);
    return run;
}

}  // namespace rmfx::test
