#include "frontend/shader/HlslSemantics.h"

#include <cctype>

namespace rmfx {

std::pair<std::string, int> splitSemantic(const std::string& semantic) {
    std::string s = semantic;
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    size_t digits = s.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(s[digits - 1]))) --digits;
    if (digits == s.size() || digits == 0) return {s, 0};
    return {s.substr(0, digits), std::stoi(s.substr(digits, 6))};
}

bool isPositionSemantic(const std::string& semantic) {
    auto [name, index] = splitSemantic(semantic);
    return (name == "POSITION" || name == "SV_POSITION") && index == 0;
}

std::string hlslVaryingName(const std::string& semantic) {
    auto [name, index] = splitSemantic(semantic);
    return "rm_hlsl_" + name + std::to_string(index);
}

std::string hlslVertexInputName(VertexUsage usage, int usageIndex) {
    const char* name = "POSITION";
    switch (usage) {
        case VertexUsage::Position: name = "POSITION"; break;
        case VertexUsage::Normal: name = "NORMAL"; break;
        case VertexUsage::TexCoord: name = "TEXCOORD"; break;
        case VertexUsage::Tangent: name = "TANGENT"; break;
        case VertexUsage::Binormal: name = "BINORMAL"; break;
        case VertexUsage::Color: name = "COLOR"; break;
    }
    return std::string("rm_hlsl_in_") + name + std::to_string(usageIndex);
}

}  // namespace rmfx
