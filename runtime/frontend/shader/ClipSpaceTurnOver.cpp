#include "frontend/shader/ClipSpaceTurnOver.h"

#include <algorithm>
#include <regex>

namespace rmfx {

namespace {

bool declaresInvTargetSize(const std::string& code) {
    static const std::regex declaration(R"(\buniform\s+(\w+\s+)?vec2\s+rm_InvTargetSize\b)");
    return std::regex_search(code, declaration);
}

}  // namespace

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
