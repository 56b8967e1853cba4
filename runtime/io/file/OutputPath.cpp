#include "io/file/OutputPath.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace rmfx {
namespace fs = std::filesystem;
namespace {

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

// "" when `folder` is a folder this process may create files in, else why not.
std::string unwritableFolder(const fs::path& folder) {
    struct stat info {};
    if (::stat(folder.c_str(), &info) != 0) {
        if (errno == ENOENT) return "the folder " + quoted(folder) + " does not exist";
        return "cannot look at the folder " + quoted(folder) + ": " + std::strerror(errno);
    }
    if (!S_ISDIR(info.st_mode)) return quoted(folder) + " is not a folder";
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        return "cannot write in the folder " + quoted(folder) + ": " + std::strerror(errno);
    return "";
}

fs::path folderOf(const fs::path& path) { return path.parent_path().empty() ? fs::path(".") : path.parent_path(); }

}  // namespace

Result<void> checkOutputFile(const fs::path& file) {
    if (file.empty()) return Error{"no file name given"};
    if (!file.has_filename() || file.filename() == "." || file.filename() == "..")
        return Error{quoted(file) + " names a folder, not a file"};
    struct stat info {};
    if (::stat(file.c_str(), &info) == 0) {
        if (S_ISDIR(info.st_mode)) return Error{quoted(file) + " is a folder, not a file"};
        if (!S_ISREG(info.st_mode)) return Error{quoted(file) + " exists and is not a regular file"};
    }
    if (std::string why = unwritableFolder(folderOf(file)); !why.empty()) return Error{file.string() + ": " + why};
    return {};
}

Result<void> checkOutputFolder(const fs::path& folder) {
    if (folder.empty()) return Error{"no folder given"};
    fs::path existing = folder;
    std::error_code ec;
    // The nearest part of the path that exists decides: rmfx creates the rest.
    while (!fs::exists(existing, ec)) {
        if (ec && ec != std::errc::no_such_file_or_directory)
            return Error{folder.string() + ": cannot look at " + quoted(existing) + ": " + ec.message()};
        fs::path parent = existing.parent_path();
        if (parent.empty() || parent == existing) {
            existing = ".";
            break;
        }
        existing = parent;
    }
    if (!fs::is_directory(existing, ec))
        return Error{folder.string() + ": " + quoted(existing) + " is a file, not a folder"};
    if (std::string why = unwritableFolder(existing); !why.empty()) return Error{folder.string() + ": " + why};
    return {};
}

}  // namespace rmfx
