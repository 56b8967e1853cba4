#include "frontend/shader/HlslColorOutputs.h"

#include <cctype>
#include <regex>

#include "frontend/shader/GlslMainEnd.h"

namespace rmfx {

namespace {

bool belowShaderModel3(const std::string& profile) {
    std::string p;
    for (char c : profile) p += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return p.rfind("vs_1_", 0) == 0 || p.rfind("vs_2_", 0) == 0;
}

}  // namespace

std::string clampColorOutputs(std::string glsl, const std::string& profile) {
    if (!belowShaderModel3(profile)) return glsl;
    static const std::regex output(R"(\bout\s+(?:float|vec[234])\s+(rm_hlsl_COLOR\d+)\s*;)");
    std::string clamps;
    for (auto it = std::sregex_iterator(glsl.begin(), glsl.end(), output); it != std::sregex_iterator(); ++it) {
        const std::string name = (*it)[1];
        clamps += " " + name + " = clamp(" + name + ", 0.0, 1.0);";
    }
    if (clamps.empty()) return glsl;
    const std::optional<size_t> close = endOfMain(glsl);
    if (!close) return glsl;
    glsl.insert(*close, clamps + " ");
    return glsl;
}

}  // namespace rmfx
