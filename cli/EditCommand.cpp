#include <iostream>

#include "cli/Commands.h"

#ifdef RMFX_HAVE_EDITOR
#include "editor/Editor.h"
#endif

namespace rmfx::cli {

std::vector<std::string> editOptionNames() {
    std::vector<std::string> names;
#ifdef RMFX_HAVE_EDITOR
    std::string error;
    (void)editor::parseEditorOptions({}, &error, &names);
#endif
    return names;
}

int editCommand(const std::vector<std::string>& args) {
#ifdef RMFX_HAVE_EDITOR
    std::string error;
    auto options = editor::parseEditorOptions(args, &error);
    if (!options) {
        std::cerr << "rmfx edit: " << error << "\n";
        return 1;
    }
    return editor::runEditor(*options);
#else
    (void)args;
    std::cerr << "rmfx edit: this rmfx was built without the editor (configure with -DRMFX_BUILD_EDITOR=ON; "
                 "it needs GLFW and Dear ImGui, installed by scripts/setup.sh)\n";
    return 2;
#endif
}

}  // namespace rmfx::cli
