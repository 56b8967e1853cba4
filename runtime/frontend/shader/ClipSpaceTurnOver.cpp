#include "frontend/shader/ClipSpaceTurnOver.h"

#include <algorithm>

#include "core/IdentifierSearch.h"

namespace rmfx {

bool declaresInvTargetSize(std::string_view code) {
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; };
    auto skipSpace = [&](size_t i) {
        while (i < code.size() && space(code[i])) ++i;
        return i;
    };
    // `vec2 rm_InvTargetSize` at `i`, the name a whole word.
    auto declaration = [&](size_t i) {
        if (code.substr(i, 4) != "vec2") return false;
        const size_t name = skipSpace(i + 4);
        constexpr std::string_view kName = "rm_InvTargetSize";
        if (name == i + 4 || code.substr(name, kName.size()) != kName) return false;
        return name + kName.size() == code.size() || !isIdentifierChar(code[name + kName.size()]);
    };
    constexpr std::string_view kUniform = "uniform";
    for (size_t at = code.find(kUniform); at != std::string_view::npos; at = code.find(kUniform, at + 1)) {
        if (at > 0 && isIdentifierChar(code[at - 1])) continue;
        const size_t type = skipSpace(at + kUniform.size());
        if (type == at + kUniform.size()) continue;
        if (declaration(type)) return true;
        size_t wordEnd = type;  // a qualifier first: `uniform highp vec2 rm_InvTargetSize`
        while (wordEnd < code.size() && isIdentifierChar(code[wordEnd])) ++wordEnd;
        const size_t next = skipSpace(wordEnd);
        if (wordEnd > type && next > wordEnd && declaration(next)) return true;
    }
    return false;
}

void turnClipSpaceOver(PreprocessedShader& shader, TextureSpace space) {
    if (!rowsTopFirst(space)) return;
    std::string& code = shader.code;
    // After the #version line (which preprocessShader put first), or first when there is none.
    const std::optional<OpeningVersion> version = openingVersion(code);
    const size_t at = version ? version->end : 0;
    const size_t lineIndex = static_cast<size_t>(std::count(code.begin(), code.begin() + static_cast<long>(at), '\n'));
    const SourceLocation where = shader.origin(static_cast<int>(lineIndex) + 1);
    code.insert(at, "#define main rm_d3d_main\n");
    shader.lineOrigins.insert(shader.lineOrigins.begin() + static_cast<long>(std::min(lineIndex, shader.lineOrigins.size())),
                              where);

    if (!code.empty() && code.back() != '\n') code += '\n';
    std::string tail = "#undef main\n";
    const bool halfPixel = space == TextureSpace::Direct3D9;
    if (halfPixel && !declaresInvTargetSize(code)) tail += "uniform vec2 rm_InvTargetSize;\n";
    tail += "void main() {\n    rm_d3d_main();\n    gl_Position.y = -gl_Position.y;\n";
    if (halfPixel) tail += "    gl_Position.xy += rm_InvTargetSize * gl_Position.w;\n";
    tail += "}\n";
    // The added lines are reported at the shader's last line.
    const SourceLocation last = shader.lineOrigins.empty() ? where : shader.lineOrigins.back();
    code += tail;
    const size_t lines = static_cast<size_t>(std::count(code.begin(), code.end(), '\n')) + 1;
    if (shader.lineOrigins.size() < lines) shader.lineOrigins.resize(lines, last);
}

}  // namespace rmfx
