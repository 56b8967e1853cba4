// ReshadePreprocessor and ReshadeParser over real effects, when there are some: RMFX_RESHADE_CORPUS
// names folders (':' between them), each a shader repository's checkout (crosire/reshade-shaders,
// CeeJayDK/SweetFX, …). Every .fx under a folder is opened as ReShade opens it, with every folder
// holding a .fx or .fxh as an include path, and the test prints how many read without an error and
// the first error of each that did not. It fails only on a crash; without the variable it skips.
//
//   RMFX_RESHADE_CORPUS=/tmp/rs/reshade-slim:/tmp/rs/sweetfx build/tests/rmfx_frontend_tests
//     --gtest_filter='ReshadeParserCorpus*'
#include "frontend/Test/ReshadeParserTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>

namespace rmfx {

TEST(ReshadeParserCorpus, RealEffectsReadWithoutErrors) {
    const char* corpus = std::getenv("RMFX_RESHADE_CORPUS");
    if (!corpus || !*corpus) GTEST_SKIP() << "RMFX_RESHADE_CORPUS names no folders";
    std::stringstream folders(corpus);
    for (std::string folder; std::getline(folders, folder, ':');) {
        std::vector<std::filesystem::path> effects;
        std::set<std::filesystem::path> includePaths;
        std::error_code ec;
        for (auto it = std::filesystem::recursive_directory_iterator(folder, ec); it != std::filesystem::recursive_directory_iterator();
             it.increment(ec)) {
            const std::filesystem::path& p = it->path();
            if (p.extension() == ".fx") effects.push_back(p);
            if (p.extension() == ".fx" || p.extension() == ".fxh") includePaths.insert(p.parent_path());
        }
        std::sort(effects.begin(), effects.end());
        size_t clean = 0;
        std::vector<std::string> failures;
        for (const std::filesystem::path& effect : effects) {
            ReshadeInput input;
            input.file = effect;
            input.settings.includePaths.assign(includePaths.begin(), includePaths.end());
            Diagnostics diagnostics;
            PreprocessedReshade pre = preprocessReshade(input, diagnostics);
            const bool preprocessed = !hasErrors(diagnostics);
            if (preprocessed) (void)parseReshadeEffect(pre, diagnostics);
            auto firstError = std::find_if(diagnostics.begin(), diagnostics.end(),
                                           [](const Diagnostic& d) { return d.severity == Diagnostic::Severity::Error; });
            if (firstError == diagnostics.end()) {
                ++clean;
                continue;
            }
            std::string text = firstError->format();
            for (size_t at; (at = text.find(folder + "/")) != std::string::npos;) text.erase(at, folder.size() + 1);
            const size_t errors = static_cast<size_t>(std::count_if(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& d) {
                return d.severity == Diagnostic::Severity::Error;
            }));
            failures.push_back((preprocessed ? "parse: " : "preprocess: ") + text + " (" + std::to_string(errors) + " errors)");
        }
        std::cout << folder << ": " << clean << " of " << effects.size() << " read without an error\n";
        for (const std::string& f : failures) std::cout << "  " << f << "\n";
    }
}

}  // namespace rmfx
