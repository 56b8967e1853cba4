#include <iostream>

#include "cli/Commands.h"
#include "runtime/WorkspaceLoader.h"

namespace rmfx::cli {

static std::string counted(size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

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
        const Workspace& ws = *loaded.workspace;
        std::cout << path << ": ok (" << counted(ws.passes.size(), "pass", "passes") << ", "
                  << counted(ws.targets.size(), "target", "targets") << ", "
                  << counted(ws.variables.size(), "variable", "variables") << ")\n";
    }
    return status;
}

}  // namespace rmfx::cli
