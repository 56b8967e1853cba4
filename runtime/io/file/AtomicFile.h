#pragma once
// Reading a whole file, and replacing one so that a crash or a full disk never leaves it half
// written.

#include <filesystem>
#include <string>
#include <string_view>

#include "core/Result.h"

namespace rmfx {

// The file's bytes as they are; errors name the path and the system's reason.
Result<std::string> readWholeFile(const std::filesystem::path& path);

// Writes `contents` to a temporary file in the folder of `path`, flushes it to disk (fsync),
// gives it the permissions (and, where allowed, the owner) of the file it replaces, and renames
// it over `path`; then syncs the folder. With keepBackup the previous version stays as
// "PATH.bak" (a hard link, or a copy where links are not supported, put in place by a rename),
// so at every instant `path` holds either the old or the new complete file. A symbolic link at
// `path` is kept: the file it points to is replaced.
// Errors name the path and the system's reason; no temporary file is left behind.
Result<void> writeFileAtomically(const std::filesystem::path& path, std::string_view contents, bool keepBackup = true);

}  // namespace rmfx
