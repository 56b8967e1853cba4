#pragma once
// Whether rmfx can write a file or fill a folder there, asked before any work is spent on what
// goes into it: a missing folder, a folder where a file is meant, or a folder rmfx may not write
// into is found when the command starts, not after its last frame.

#include <filesystem>

#include "core/Result.h"

namespace rmfx {

// `file` can be created or replaced: its folder exists and is writable, and `file` is not a
// folder (or anything else that is not a regular file). Errors name the path and what is wrong.
Result<void> checkOutputFile(const std::filesystem::path& file);

// `folder` exists and is a writable folder, or it can be created: the nearest part of it that
// exists is a writable folder.
Result<void> checkOutputFolder(const std::filesystem::path& folder);

}  // namespace rmfx
