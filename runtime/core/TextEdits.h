#pragma once
// Replacements of ranges of a text, made in one pass over it (shader rewrites: each edit names
// offsets in the original, so none has to account for the others).

#include <cstddef>
#include <string>
#include <vector>

namespace rmfx {

struct TextEdit {
    size_t at = 0;      // offset in the original
    size_t length = 0;  // characters replaced there; 0 inserts
    std::string text;
};

// The original with every edit made. Edits must not overlap; at one offset, insertions come
// first, in the order given, then the replacement.
std::string applyTextEdits(const std::string& original, std::vector<TextEdit> edits);

}  // namespace rmfx
