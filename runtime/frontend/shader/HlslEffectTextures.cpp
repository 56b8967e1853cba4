#include "frontend/shader/HlslEffectTextures.h"

#include <cctype>

#include "core/IdentifierSearch.h"
#include "frontend/shader/HlslBlankedCode.h"

namespace rmfx {

namespace {

void blank(std::string& out, size_t from, size_t to) {
    for (size_t k = from; k < to; ++k)
        if (out[k] != '\n') out[k] = ' ';
}

// `= sampler_state { … }` after a sampler's name: blanked from '=' to the block's '}'.
void blankSamplerStates(const std::string& scanned, std::string& out) {
    const std::string keyword = "sampler_state";
    for (size_t at = scanned.find(keyword); at != std::string::npos; at = scanned.find(keyword, at + 1)) {
        if ((at > 0 && isIdentifierChar(scanned[at - 1])) ||
            (at + keyword.size() < scanned.size() && isIdentifierChar(scanned[at + keyword.size()])))
            continue;
        size_t equals = at;
        while (equals > 0 && std::isspace(static_cast<unsigned char>(scanned[equals - 1]))) --equals;
        if (equals == 0 || scanned[equals - 1] != '=') continue;
        --equals;
        size_t open = at + keyword.size();
        while (open < scanned.size() && std::isspace(static_cast<unsigned char>(scanned[open]))) ++open;
        if (open >= scanned.size() || scanned[open] != '{') continue;
        const size_t close = scanned.find('}', open);  // state assignments hold no braces
        if (close == std::string::npos) continue;
        blank(out, equals, close + 1);
    }
}

}  // namespace

std::string blankEffectTextures(const std::string& code) {
    const std::string scanned = blankedHlsl(code);
    std::string out = code;
    blankSamplerStates(scanned, out);
    int depth = 0;
    size_t statement = 0;  // where the current file-scope statement starts
    for (size_t i = 0; i < scanned.size(); ++i) {
        const char c = scanned[i];
        if (c == '{' || c == '(') ++depth;
        else if ((c == '}' || c == ')') && depth > 0) {
            if (--depth == 0 && c == '}') statement = i + 1;
        } else if (c == ';' && depth == 0) {
            size_t word = statement;
            while (word < i && std::isspace(static_cast<unsigned char>(scanned[word]))) ++word;
            size_t end = word;
            while (end < i && isIdentifierChar(scanned[end])) ++end;
            if (end - word == 7 && scanned.compare(word, 7, "texture") == 0) {
                // An annotation (`< string file = "grass.dds"; >`) holds ';' of its own.
                int angles = 0;
                for (size_t k = end; k < i; ++k) angles += scanned[k] == '<' ? 1 : scanned[k] == '>' ? -1 : 0;
                if (angles > 0) continue;
                blank(out, word, i + 1);
            }
            statement = i + 1;
        }
    }
    return out;
}

}  // namespace rmfx
