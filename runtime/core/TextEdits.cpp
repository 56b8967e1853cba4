#include "core/TextEdits.h"

#include <algorithm>

namespace rmfx {

std::string applyTextEdits(const std::string& original, std::vector<TextEdit> edits) {
    std::stable_sort(edits.begin(), edits.end(),
                     [](const TextEdit& a, const TextEdit& b) { return a.at < b.at || (a.at == b.at && a.length < b.length); });
    std::string out;
    size_t copied = 0;
    for (const TextEdit& edit : edits) {
        if (edit.at < copied || edit.at > original.size()) continue;  // overlapping or outside: a caller's bug
        out.append(original, copied, edit.at - copied);
        out += edit.text;
        copied = std::min(original.size(), edit.at + edit.length);
    }
    out.append(original, copied, std::string::npos);
    return out;
}

}  // namespace rmfx
