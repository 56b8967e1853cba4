#include "core/ProgramBeside.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace rmfx {

namespace {
bool executable(const std::string& path) { return !path.empty() && ::access(path.c_str(), X_OK) == 0; }
}  // namespace

Result<std::string> findProgram(const ProgramSearch& search) {
    if (const char* chosen = std::getenv(search.environment.c_str()); chosen && *chosen) {
        if (executable(chosen)) return std::string(chosen);
        return Error{search.environment + " names '" + std::string(chosen) + "', which is not a program that can be run"};
    }
    std::error_code error;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    std::string beside = error ? std::string() : (self.parent_path() / search.name).string();
    if (executable(beside)) return beside;
    const std::optional<std::filesystem::path> installed = installedFile(search.installed, search.name);
    if (installed && executable(installed->string())) return installed->string();
    if (executable(search.buildPath)) return search.buildPath;
    return Error{"cannot find " + search.name + ", " + search.purpose + ": not at " +
                 (beside.empty() ? std::string() : "'" + beside + "' (beside this program) nor at ") +
                 (installed ? "'" + installed->string() + "' (in the installed package) nor at " : std::string()) + "'" +
                 search.buildPath + "' (where this build put it); set " + search.environment + " to its path"};
}

}  // namespace rmfx
