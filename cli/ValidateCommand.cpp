#include <iostream>

#include "apps/ArgumentParser.h"
#include "cli/Commands.h"
#include "apps/OptionValues.h"
#include "io/media/MediaArguments.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::cli {

using namespace rmfx::apps;  // the shared argument loop and option values

static std::string counted(size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

namespace {

struct ValidateArguments {
    WorkspaceLoadOptions load;
    std::vector<std::string> paths;
};

ArgumentParser validateParser(ValidateArguments& a) {
    ArgumentParser parser;
    parser.own([&](const std::vector<std::string>& all, size_t& i) { return takeMediaArgument(all, i, a.load.media); },
               kMediaOptionNames)
        .option({"--effect"}, [&](const std::string& value) { a.load.effect = value; return ""; },
                ArgumentParser::EmptyValue::Allowed)
        .option({"--rfx-matrices"}, rfxMatricesValue(a.load.rfxMatrices))
        .positional([&](const std::string& path) { a.paths.push_back(path); return ""; })
        .unknownOptionHint("");
    return parser;
}

}  // namespace

std::vector<std::string> validateOptionNames() {
    ValidateArguments a;
    return validateParser(a).names();
}

int validateCommand(const std::vector<std::string>& args) {
    if (args.empty()) {
        std::cerr << "rmfx validate: name one or more workspace files\n";
        return 1;
    }
    ValidationOptions options;
    ValidateArguments a;
    const WorkspaceLoadOptions& load = a.load;
    const std::vector<std::string>& paths = a.paths;
    if (std::string message = validateParser(a).parse(args); !message.empty()) {
        std::cerr << "rmfx validate: " << message << "\n";
        return 1;
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
