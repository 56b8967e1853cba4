#include "frontend/reshade/ReshadeSettings.h"

namespace rmfx {
namespace {

std::string trim(const std::string& s) {
    const size_t first = s.find_first_not_of(" \t");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

}  // namespace

std::vector<std::pair<std::string, std::string>> predefinedMacros(const ReshadeSettings& s) {
    return {
        {"__RESHADE__", std::to_string(s.version)},
        {"__RESHADE_PERFORMANCE_MODE__", s.performanceMode ? "1" : "0"},
        {"__VENDOR__", std::to_string(s.vendor)},
        {"__DEVICE__", std::to_string(s.device)},
        {"__RENDERER__", std::to_string(s.renderer)},
        {"__APPLICATION__", std::to_string(s.application)},
        {"BUFFER_WIDTH", std::to_string(s.width)},
        {"BUFFER_HEIGHT", std::to_string(s.height)},
        {"BUFFER_RCP_WIDTH", "(1.0 / BUFFER_WIDTH)"},
        {"BUFFER_RCP_HEIGHT", "(1.0 / BUFFER_HEIGHT)"},
        {"BUFFER_COLOR_SPACE", std::to_string(s.colorSpace)},
        {"BUFFER_COLOR_BIT_DEPTH", std::to_string(s.colorBitDepth)},
    };
}

const char* reshadeCompatibilityMacros() {
    return "#define tex2Doffset(s, coords, offset) tex2D(s, coords, offset)\n"
           "#define tex2Dlodoffset(s, coords, offset) tex2Dlod(s, coords, offset)\n"
           "#define tex2Dgather(s, t, c) tex2Dgather##c(s, t)\n"
           "#define tex2Dgatheroffset(s, t, o, c) tex2Dgather##c(s, t, o)\n"
           "#define tex2Dgather0 tex2DgatherR\n"
           "#define tex2Dgather1 tex2DgatherG\n"
           "#define tex2Dgather2 tex2DgatherB\n"
           "#define tex2Dgather3 tex2DgatherA\n";
}

std::pair<std::string, std::string> splitDefine(const std::string& define) {
    const size_t equals = define.find('=');
    std::string name = trim(define.substr(0, equals));
    std::string value = equals == std::string::npos ? std::string() : trim(define.substr(equals + 1));
    if (value.empty()) value = "1";
    return {std::move(name), std::move(value)};
}

}  // namespace rmfx
