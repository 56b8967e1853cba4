#include "io/file/FileNamePart.h"

#include <cctype>

namespace rmfx {

std::string fileNamePart(const std::string& name) {
    std::string part = name;
    for (char& ch : part)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '-' && ch != '.') ch = '_';
    if (part.empty() || part[0] == '.') part = "_" + part;
    return part;
}

}  // namespace rmfx
