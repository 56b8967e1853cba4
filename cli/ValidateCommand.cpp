#include <iostream>

#include "cli/Commands.h"
#include "runtime/WorkspaceLoader.h"

namespace rmfx::cli {

int validateCommand(const std::vector<std::string>& args) {
    if (args.empty()) {
        std::cerr << "rmfx validate: name one or more workspace files\n";
        return 1;
    }
    int status = 0;
    for (const std::string& path : args) {
        if (!path.empty() && path[0] == '-') {
            std::cerr << "rmfx validate: unknown option '" << path << "'\n";
            return 1;
        }
        LoadedWorkspace loaded = loadWorkspace(path);
        std::cerr << formatAll(loaded.diagnostics);
        if (!loaded.workspace) {
            status = 1;
            continue;
        }
        std::cout << path << ": ok (" << loaded.workspace->passes.size() << " passes, "
                  << loaded.workspace->targets.size() << " targets, " << loaded.workspace->variables.size()
                  << " variables)\n";
    }
    return status;
}

}  // namespace rmfx::cli
