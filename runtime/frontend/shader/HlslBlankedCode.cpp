#include "frontend/shader/HlslBlankedCode.h"

#include "core/IdentifierSearch.h"

namespace rmfx {

std::string blankedHlsl(const std::string& code) {
    std::string out = withoutComments(code);
    size_t line = 0;
    while (line < out.size()) {
        size_t first = out.find_first_not_of(" \t", line);
        if (first != std::string::npos && out[first] == '#')
            for (size_t i = first; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
        size_t next = out.find('\n', line);
        if (next == std::string::npos) break;
        line = next + 1;
    }
    return out;
}

}  // namespace rmfx
