#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include "io/image/InputImage.h"

namespace rmfx {

namespace fs = std::filesystem;

std::pair<fs::path, std::string> splitLayerSuffix(const std::string& argument) {
    const size_t colon = argument.rfind(':');
    std::error_code ec;
    if (colon == std::string::npos || colon == 0 || fs::exists(argument, ec)) return {argument, ""};
    const std::string file = argument.substr(0, colon);
    std::string extension = fs::path(file).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".exr" || fs::is_regular_file(file, ec)) return {file, argument.substr(colon + 1)};
    return {argument, ""};
}

}  // namespace rmfx
