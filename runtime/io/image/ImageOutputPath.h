#pragma once
// The image files rmfx writes: the container an output's extension names, and whether a path
// can take one, asked before a render spends any work on it.

#include <filesystem>
#include <optional>

#include "core/Result.h"

namespace rmfx {

enum class ImageContainer { Exr, Rgbe, Png, Jpeg, Tga, Bmp };

// By the extension, ignoring case: .exr .hdr .png .jpg/.jpeg .tga .bmp; nullopt for any other.
std::optional<ImageContainer> imageContainerFor(const std::filesystem::path& file);
// ".exr .hdr .png .jpg .jpeg .tga .bmp", for messages.
const char* knownImageOutputExtensions();

// A known extension, and a file that can be created or replaced there (checkOutputFile).
// Errors name the file.
Result<void> checkImageOutputPath(const std::filesystem::path& file);

}  // namespace rmfx
