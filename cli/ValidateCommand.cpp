#include <iostream>

#include "cli/Commands.h"
#include "io/media/MediaArguments.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::cli {

static std::string counted(size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

int validateCommand(const std::vector<std::string>& args) {
    if (args.empty()) {
        std::cerr << "rmfx validate: name one or more workspace files\n";
        return 1;
    }
    ValidationOptions options;
    WorkspaceLoadOptions load;
    std::vector<std::string> paths;
    for (size_t i = 0; i < args.size(); ++i) {
        if (auto media = takeMediaArgument(args, i, options.media)) {
            if (media->empty()) continue;
            std::cerr << "rmfx validate: " << *media << "\n";
            return 1;
        }
        if (args[i] == "--effect") {
            if (i + 1 >= args.size()) {
                std::cerr << "rmfx validate: --effect needs a value\n";
                return 1;
            }
            load.effect = args[++i];
            continue;
        }
        if (!args[i].empty() && args[i][0] == '-') {
            std::cerr << "rmfx validate: unknown option '" << args[i] << "'\n";
            return 1;
        }
        paths.push_back(args[i]);
    }
    if (paths.empty()) {
        std::cerr << "rmfx validate: name one or more workspace files\n";
        return 1;
    }
    int status = 0;
    for (const std::string& path : paths) {
        Result<Workspace> loaded = loadWorkspace(path, options, load);
        std::cerr << formatAll(loaded.diagnostics());
        if (!loaded) {
            status = 1;
            continue;
        }
        const Workspace& ws = *loaded;
        std::cout << path << ": ok (" << counted(ws.passes.size(), "pass", "passes") << ", "
                  << counted(ws.targets.size(), "target", "targets") << ", "
                  << counted(ws.variables.size(), "variable", "variables") << ")\n";
    }
    return status;
}

}  // namespace rmfx::cli
