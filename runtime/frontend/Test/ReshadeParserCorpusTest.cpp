// ReshadePreprocessor and ReshadeParser over real effects, when there are some: RMFX_RESHADE_CORPUS
// names folders (':' between them), each a shader repository's checkout (crosire/reshade-shaders,
// CeeJayDK/SweetFX, …). Every .fx under a folder is opened as ReShade opens it, with every folder
// holding a .fx or .fxh as an include path, then those RMFX_RESHADE_INCLUDE names (':' between
// them; the standard headers, ReShade.fxh and ReShadeUI.fxh, that a ReShade install puts beside
// repositories that do not ship them). The test prints how many read without an error and the
// first error of each that did not. It fails only on a crash; without the variable it skips.
//
//   RMFX_RESHADE_CORPUS=/tmp/rs/reshade-slim:/tmp/rs/sweetfx build/tests/rmfx_frontend_tests
//     --gtest_filter='ReshadeParserCorpus*'
#include "frontend/Test/ReshadeParserTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
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
        size_t clean = 0, techniques = 0, passes = 0, uniforms = 0, functions = 0, textures = 0, warnings = 0;
        std::vector<std::string> failures;
        std::map<std::string, size_t> warningCounts;
        for (const std::filesystem::path& effect : effects) {
            ReshadeInput input;
            input.file = effect;
            input.settings.includePaths.assign(includePaths.begin(), includePaths.end());
            if (const char* more = std::getenv("RMFX_RESHADE_INCLUDE")) {
                std::stringstream extra(more);
                for (std::string path; std::getline(extra, path, ':');)
                    if (!path.empty()) input.settings.includePaths.push_back(path);
            }
            Diagnostics diagnostics;
            PreprocessedReshade pre = preprocessReshade(input, diagnostics);
            const bool preprocessed = !hasErrors(diagnostics);
            if (preprocessed) {
                const ReshadeEffect effect = parseReshadeEffect(pre, diagnostics);
                techniques += effect.techniques.size();
                for (const ReshadeTechnique& t : effect.techniques) passes += t.passes.size();
                uniforms += effect.uniforms.size();
                functions += effect.functions.size();
                textures += effect.textures.size();
            }
            for (const Diagnostic& d : diagnostics)
                if (d.severity == Diagnostic::Severity::Warning) ++warnings, ++warningCounts[d.message];
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
        std::cout << folder << ": " << clean << " of " << effects.size() << " read without an error (" << techniques
                  << " techniques, " << passes << " passes, " << uniforms << " uniforms, " << textures << " textures, "
                  << functions << " functions; " << warnings << " warnings)\n";
        for (const auto& [message, count] : warningCounts) std::cout << "  warning x" << count << ": " << message << "\n";
        for (const std::string& f : failures) std::cout << "  " << f << "\n";
    }
}

}  // namespace rmfx
