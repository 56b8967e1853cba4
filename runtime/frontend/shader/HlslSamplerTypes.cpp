#include "frontend/shader/HlslSamplerTypes.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <string_view>
#include <vector>

#include "core/IdentifierSearch.h"
#include "core/TextEdits.h"

namespace rmfx {
namespace {

// Every whole identifier in `code`, with its offset.
std::vector<std::pair<size_t, std::string_view>> identifiers(std::string_view code) {
    std::vector<std::pair<size_t, std::string_view>> out;
    for (size_t i = 0; i < code.size();) {
        if (!isIdentifierChar(code[i]) || std::isdigit(static_cast<unsigned char>(code[i]))) {
            // Skip a number whole (1e5f, 0x1F), so its letters are not taken for identifiers.
            if (std::isdigit(static_cast<unsigned char>(code[i])))
                while (i < code.size() && (isIdentifierChar(code[i]) || code[i] == '.')) ++i;
            else
                ++i;
            continue;
        }
        size_t start = i;
        while (i < code.size() && isIdentifierChar(code[i])) ++i;
        out.emplace_back(start, code.substr(start, i - start));
    }
    return out;
}

// The sampler type a texture function's name implies, or "" for tex2D… and anything else.
std::string_view impliedType(std::string_view function) {
    if (function.starts_with("texCUBE")) return "samplerCUBE";
    if (function.starts_with("tex3D")) return "sampler3D";
    if (function.starts_with("tex1D")) return "sampler1D";
    if (function.starts_with("tex2D")) return "sampler2D";
    return "";
}

}  // namespace

std::string typeGenericSamplers(const std::string& original) {
    const std::string blanked = withoutComments(original);
    const std::string_view code = blanked;
    const auto words = identifiers(code);
    // Declarations: `sampler NAME` at brace depth 0.
    std::map<std::string_view, size_t> declared;  // name → offset of its `sampler` keyword
    int depth = 0;
    size_t scanned = 0;
    for (size_t w = 0; w + 1 < words.size(); ++w) {
        for (; scanned < words[w].first; ++scanned) depth += code[scanned] == '{' ? 1 : code[scanned] == '}' ? -1 : 0;
        if (depth == 0 && words[w].second == "sampler") declared.emplace(words[w + 1].second, words[w].first);
    }
    if (declared.empty()) return original;
    // Reads: FUNCTION ( NAME , … ); a plain two-argument tex1D's second argument is kept too.
    struct Tex1DCall {
        size_t function, argument, end;  // offsets: `tex1D`, its second argument, the closing ')'
    };
    std::map<std::string_view, std::set<std::string_view>> reads;
    std::map<std::string_view, std::vector<Tex1DCall>> plainTex1D;
    std::set<std::string_view> otherTex1D;  // read with tex1Dlod, tex1Dbias… too
    for (size_t w = 0; w + 1 < words.size(); ++w) {
        std::string_view type = impliedType(words[w].second);
        if (type.empty()) continue;
        const size_t after = words[w].first + words[w].second.size();
        const size_t paren = code.find_first_not_of(" \t\r\n", after);
        if (paren == std::string_view::npos || code[paren] != '(') continue;
        const size_t argument = code.find_first_not_of(" \t\r\n", paren + 1);
        const std::string_view name = words[w + 1].second;
        if (argument == std::string_view::npos || argument != words[w + 1].first || !declared.count(name)) continue;
        reads[name].insert(type);
        if (type != "sampler1D") continue;
        // The arguments, split at top-level commas, up to the matching ')'.
        std::vector<size_t> commas;
        int nesting = 0;
        size_t close = std::string_view::npos;
        for (size_t i = paren + 1; i < code.size() && close == std::string_view::npos; ++i) {
            if (code[i] == '(') ++nesting;
            else if (code[i] == ')' && nesting-- == 0) close = i;
            else if (code[i] == ',' && nesting == 0) commas.push_back(i);
        }
        if (words[w].second == "tex1D" && commas.size() == 1 && close != std::string_view::npos)
            plainTex1D[name].push_back({words[w].first, commas[0] + 1, close});
        else
            otherTex1D.insert(name);
    }
    std::vector<TextEdit> edits;
    for (const auto& [name, types] : reads) {
        if (types.size() != 1 || *types.begin() == "sampler2D") continue;
        if (*types.begin() == "sampler1D" && !otherTex1D.count(name)) {
            // Direct3D 9 has no 1D textures: RenderMonkey's are images one texel high, and rmfx
            // binds them as 2D textures. The sampler stays 2D; each tex1D reads the middle row.
            for (const Tex1DCall& call : plainTex1D[name]) {
                edits.push_back({call.function, 5, "tex2D"});
                edits.push_back({call.argument, 0, "float2("});
                edits.push_back({call.end, 0, ", 0.5)"});
            }
            continue;
        }
        edits.push_back({declared.at(name), std::string_view("sampler").size(), std::string(*types.begin())});
    }
    if (edits.empty()) return original;
    std::string out = applyTextEdits(original, std::move(edits));
    return out;
}

}  // namespace rmfx
