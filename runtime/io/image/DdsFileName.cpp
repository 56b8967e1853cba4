#include <algorithm>
#include <cctype>
#include <string>

#include "io/image/DdsCubeMap.h"

namespace rmfx {

bool isDdsFile(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".dds";
}

}  // namespace rmfx
