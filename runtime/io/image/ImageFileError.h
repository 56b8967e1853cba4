#pragma once
// Error messages for image file operations, shared by the reader and the writer.

#include <filesystem>
#include <string>

#include "core/Result.h"

namespace rmfx {

inline Error imageFileError(const std::filesystem::path& file, const std::string& what) {
    return Error{file.string() + ": " + what};
}

// OpenImageIO's messages can span lines and end in a newline; this gives one line.
inline std::string oneLine(std::string message) {
    for (char& c : message)
        if (c == '\n') c = ';';
    while (!message.empty() && (message.back() == ';' || message.back() == ' ')) message.pop_back();
    return message.empty() ? "unknown error" : message;
}

}  // namespace rmfx
