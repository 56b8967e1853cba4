#include "frontend/shader/GlslMainEnd.h"

namespace rmfx {

std::optional<size_t> endOfMain(const std::string& glsl) {
    const size_t main = glsl.find("void main()");
    if (main == std::string::npos) return std::nullopt;
    const size_t open = glsl.find('{', main);
    if (open == std::string::npos) return std::nullopt;
    int depth = 0;
    for (size_t i = open; i < glsl.size(); ++i) {
        if (glsl[i] == '{') ++depth;
        if (glsl[i] == '}' && --depth == 0) return i;
    }
    return std::nullopt;
}

}  // namespace rmfx
