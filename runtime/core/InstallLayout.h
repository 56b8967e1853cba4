#pragma once
// Where an installed rmfx (cmake --install, docs/library.md) keeps its parts, found from the file
// that holds rmfx's code in this process: the rmfx program in PREFIX/bin, librmfx.so in
// PREFIX/lib (or lib/<multiarch>), the Python module in its site folder. The folders are the
// build's (GNUInstallDirs, relative to the prefix), so a package installed with any --prefix
// finds its image codecs module and its helper programs, wherever the build folder went.

#include <filesystem>
#include <optional>
#include <string>

namespace rmfx {

enum class InstallFolder {
    Bin,      // the programs: rmfx, rmfx-edit
    Lib,      // librmfx.so and rmfx-image-codecs.so
    Libexec,  // rmfx's own helper programs (libexec/rmfx/: rmfx-hlsl-worker)
};

// The folder relative to the prefix (as the build configured it: "bin", "lib" or
// "lib/x86_64-linux-gnu", "libexec/rmfx"); empty where the build gave an absolute one.
std::filesystem::path installFolder(InstallFolder folder);

// The program or shared library that holds this code (dladdr), as a canonical path; empty when
// unknown.
std::filesystem::path codeHolder();

// The install prefix whose bin, lib or Python folder `holderFolder` is; none when it is none of
// them (a build folder, a program elsewhere).
std::optional<std::filesystem::path> installPrefixOf(const std::filesystem::path& holderFolder);

// PREFIX/<folder>/name for the install that holds this code; none outside an install.
std::optional<std::filesystem::path> installedFile(InstallFolder folder, const std::string& name);

}  // namespace rmfx
