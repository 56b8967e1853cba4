#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "cli/Commands.h"
#include "core/ProgramBeside.h"

#include "apps/EditorOptions.h"

namespace rmfx::cli {

std::vector<std::string> editOptionNames() {
    std::vector<std::string> names;
    std::string error;
    (void)apps::parseEditorOptions({}, &error, &names);
    return names;
}

// The arguments are checked here, so that a mistake is said before a window opens; the editor is
// its own program (rmfx-edit), started in this process's place with the same arguments.
int editCommand(const std::vector<std::string>& args) {
    std::string error;
    if (!apps::parseEditorOptions(args, &error)) {
        std::cerr << "rmfx edit: " << error << "\n";
        return 1;
    }
#ifdef RMFX_HAVE_EDITOR
    Result<std::string> program =
        findProgram({"rmfx-edit", "RMFX_EDITOR", RMFX_EDITOR_BUILD_PATH, "the editor's program"});
    if (!program) {
        std::cerr << "rmfx edit: " << program.error() << "\n";
        return 2;
    }
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>("rmfx-edit"));
    for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    ::execv(program->c_str(), argv.data());
    std::cerr << "rmfx edit: cannot start '" << *program << "': " << std::strerror(errno) << "\n";
    return 2;
#else
    std::cerr << "rmfx edit: this rmfx was built without the editor (configure with -DRMFX_BUILD_EDITOR=ON; "
                 "it needs GLFW and Dear ImGui, installed by scripts/setup.sh)\n";
    return 2;
#endif
}

}  // namespace rmfx::cli
