#include "core/InstallLayout.h"

#include <dlfcn.h>

#include <system_error>
#include <vector>

// The install's folders relative to its prefix (runtime/core/CMakeLists.txt from GNUInstallDirs and
// the Python module's site folder); empty where absolute or unknown.
#ifndef RMFX_INSTALL_BINDIR
#define RMFX_INSTALL_BINDIR ""
#endif
#ifndef RMFX_INSTALL_LIBDIR
#define RMFX_INSTALL_LIBDIR ""
#endif
#ifndef RMFX_INSTALL_LIBEXECDIR
#define RMFX_INSTALL_LIBEXECDIR ""
#endif
#ifndef RMFX_INSTALL_PYTHONDIR
#define RMFX_INSTALL_PYTHONDIR ""
#endif

namespace rmfx {

namespace fs = std::filesystem;

fs::path codeHolder() {
    Dl_info info{};
    if (!dladdr(reinterpret_cast<void*>(&codeHolder), &info) || !info.dli_fname) return {};
    std::error_code error;
    fs::path holder = fs::canonical(info.dli_fname, error);
    return error ? fs::path() : holder;
}

namespace {

// `folder` without its last components `tail` (a relative path), or none when it does not end so.
std::optional<fs::path> withoutTail(const fs::path& folder, const fs::path& tail) {
    if (tail.empty() || tail.is_absolute()) return std::nullopt;
    std::vector<fs::path> parts(tail.begin(), tail.end());
    fs::path rest = folder;
    for (auto part = parts.rbegin(); part != parts.rend(); ++part) {
        if (*part == "." || part->empty()) continue;
        if (rest.filename() != *part || !rest.has_parent_path() || rest == rest.root_path()) return std::nullopt;
        rest = rest.parent_path();
    }
    return rest;
}

}  // namespace

fs::path installFolder(InstallFolder folder) {
    switch (folder) {
        case InstallFolder::Bin: return RMFX_INSTALL_BINDIR;
        case InstallFolder::Lib: return RMFX_INSTALL_LIBDIR;
        case InstallFolder::Libexec: return fs::path(RMFX_INSTALL_LIBEXECDIR).empty() ? fs::path() : fs::path(RMFX_INSTALL_LIBEXECDIR) / "rmfx";
    }
    return {};
}

std::optional<fs::path> installPrefixOf(const fs::path& holderFolder) {
    for (const char* tail : {RMFX_INSTALL_BINDIR, RMFX_INSTALL_LIBDIR, RMFX_INSTALL_PYTHONDIR})
        if (auto prefix = withoutTail(holderFolder, tail)) return prefix;
    return std::nullopt;
}

std::optional<fs::path> installedFile(InstallFolder folder, const std::string& name) {
    const fs::path holder = codeHolder();
    const fs::path relative = installFolder(folder);
    if (holder.empty() || relative.empty()) return std::nullopt;
    auto prefix = installPrefixOf(holder.parent_path());
    if (!prefix) return std::nullopt;
    return *prefix / relative / name;
}

}  // namespace rmfx
