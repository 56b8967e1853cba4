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

std::optional<std::string> pixelSystemValue(const std::string& semantic, const std::string& type) {
    const std::string name = splitSemantic(semantic).first;
    if (name != "VPOS" && name != "VFACE") return std::nullopt;
    int size = 0;
    if (type == "float") size = 1;
    else if (type.size() == 4 && type.compare(0, 3, "vec") == 0 && type[3] >= '2' && type[3] <= '4') size = type[3] - '0';
    else return std::nullopt;
    if (name == "VFACE") return size == 1 ? "(gl_FrontFacing ? 1.0 : -1.0)" : type + "(gl_FrontFacing ? 1.0 : -1.0)";
    if (size == 1) return "(gl_FragCoord.x - 0.5)";
    if (size == 2) return "(gl_FragCoord.xy - 0.5)";
    return type + "(gl_FragCoord.xy - 0.5" + (size == 3 ? ", 0.0)" : ", 0.0, 0.0)");
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
