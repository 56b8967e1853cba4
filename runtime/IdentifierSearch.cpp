#include "runtime/IdentifierSearch.h"

#include <cctype>

namespace rmfx {

static bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool mentionsIdentifier(std::string_view code, std::string_view name) {
    if (name.empty()) return false;
    for (size_t at = code.find(name); at != std::string_view::npos; at = code.find(name, at + 1)) {
        bool before = at > 0 && identifierChar(code[at - 1]);
        bool after = at + name.size() < code.size() && identifierChar(code[at + name.size()]);
        if (!before && !after) return true;
    }
    return false;
}

}  // namespace rmfx
