#pragma once
// The helper programs rmfx starts (rmfx-hlsl-worker, rmfx-edit): where to find the one to run.

#include <string>

#include "core/InstallLayout.h"
#include "core/Result.h"

namespace rmfx {

struct ProgramSearch {
    std::string name;              // the program's file name, e.g. "rmfx-edit"
    std::string environment;       // a variable that, once set, must name the program
    std::string buildPath;         // where this build wrote it
    std::string purpose;           // what it does, for the error: "the editor's window"
    InstallFolder installed = InstallFolder::Bin;  // where an installed package keeps it
};

// The first that exists of: $environment (once set, it must name a program that can be run), the
// program beside this process's executable, the one in the installed package that holds this code
// (core/InstallLayout.h: an installed rmfx, librmfx.so or the Python module), the one this build
// wrote.
// Otherwise an error saying where it looked.
Result<std::string> findProgram(const ProgramSearch& search);

}  // namespace rmfx
