#include "frontend/shader/D3DAsmHlslNames.h"

#include <cctype>
#include <set>

namespace rmfx::d3dasm {

bool hlslIdentifier(const std::string& name) {
    static const std::set<std::string> reserved = {
        "bool", "int", "uint", "half", "float", "double", "vector", "matrix", "void", "true", "false",
        "in", "out", "inout", "uniform", "static", "const", "extern", "shared", "volatile", "register", "struct",
        "typedef", "sampler", "sampler1D", "sampler2D", "sampler3D", "samplerCUBE", "texture", "if", "else",
        "for", "while", "do", "return", "break", "continue", "discard",
        "row_major", "column_major", "snorm", "unorm", "packoffset", "cbuffer", "tbuffer", "namespace", "switch",
        "case", "default", "inline", "precise", "centroid", "linear", "nointerpolation", "noperspective", "string"};
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0])) || reserved.count(name)) return false;
    if (name.rfind("rm_", 0) == 0) return false;  // the translation's own names
    for (char ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_') return false;
    const std::string lowered = [&] {
        std::string l = name;
        for (char& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return l;
    }();
    // Register-like names would meet the locals the translation declares (r0, c, oPos…).
    if (lowered == "c" || lowered == "a0" || lowered == "al" || lowered == "opos" || lowered == "ofog" ||
        lowered == "opts" || lowered == "odepth" || lowered == "vface" || lowered == "vpos")
        return false;
    if (lowered.size() >= 2 && std::string("rvtibo").find(lowered[0]) != std::string::npos) {
        size_t k = 1;
        if (lowered[0] == 'o' && (lowered[1] == 'd' || lowered[1] == 't' || lowered[1] == 'c')) k = 2;
        bool digits = k < lowered.size();
        for (size_t i = k; i < lowered.size(); ++i) digits = digits && std::isdigit(static_cast<unsigned char>(lowered[i]));
        if (digits) return false;
    }
    return true;
}


}  // namespace rmfx::d3dasm
