#include "frontend/rfx/detail/RfxDoctype.h"

namespace rmfx::rfx {

std::string blankDoctype(std::string text) {
    size_t begin = text.find("<!DOCTYPE");
    if (begin == std::string::npos) return text;
    // The subset's declarations may hold quoted '>' and ']' (attribute defaults), so quotes are
    // skipped; comments inside it hold no quotes RenderMonkey writes.
    size_t i = begin + 9;
    bool inSubset = false;
    char quote = 0;
    for (; i < text.size(); ++i) {
        char c = text[i];
        if (quote) {
            if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '[') {
            inSubset = true;
        } else if (c == ']') {
            inSubset = false;
        } else if (c == '>' && !inSubset) {
            break;
        }
    }
    if (i >= text.size()) return text;
    for (size_t k = begin; k <= i; ++k)
        if (text[k] != '\n' && text[k] != '\r') text[k] = ' ';
    return text;
}

}  // namespace rmfx::rfx
