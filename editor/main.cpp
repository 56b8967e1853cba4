// rmfx-edit: the editor's window (GLFW, Dear ImGui). `rmfx edit ARGS` checks ARGS and starts this
// program with them, so that the headless rmfx links no windowing library; run on its own it takes
// the same arguments.

#include <iostream>
#include <string>
#include <vector>

#include "editor/Editor.h"
#include "io/image/ImageCodecs.h"

int main(int argc, char** argv) {
    rmfx::startLoadingImageCodecs();  // on its own thread, while the workspace loads and the window opens
    const std::vector<std::string> args(argv + 1, argv + argc);
    std::string error;
    auto options = rmfx::apps::parseEditorOptions(args, &error);
    if (!options) {
        std::cerr << "rmfx edit: " << error << "\n";
        return 1;
    }
    return rmfx::editor::runEditor(*options);
}
