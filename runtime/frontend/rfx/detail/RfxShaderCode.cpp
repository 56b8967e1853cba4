#include "frontend/rfx/detail/RfxShaderCode.h"

#include <algorithm>

namespace rmfx::rfx {

std::optional<RfxShaderCode> shaderCodeOf(const RfxElement& shader) {
    RfxShaderCode out;
    if (const tinyxml2::XMLElement* child = shader.xml()->FirstChildElement("RmShaderCode")) {
        const tinyxml2::XMLNode* text = child->FirstChild();
        if (text && text->ToText()) {
            out.code = text->Value();
            out.line = text->GetLineNum();
        } else {
            out.line = child->GetLineNum();
        }
        return out;
    }
    if (std::optional<std::string> code = shader.text("CODE", false)) {
        // The attribute holds every line of the code on the element's one line of the file, so no
        // line of the file matches a line of the code: the code's first line is put on the
        // element's line, a message about its n-th line points n - 1 lines past it, and one about
        // the declarations (first, on lines of their own, as RenderMonkey compiled them) before it.
        const std::string declarations = shader.text("DECLARATION_BLOCK", false).value_or("");
        int declarationLines = 0;
        for (char c : declarations) declarationLines += c == '\n' ? 1 : 0;
        if (!declarations.empty() && declarations.back() != '\n') ++declarationLines;
        out.code = declarations + (declarations.empty() || declarations.back() == '\n' ? "" : "\n") + *code;
        out.line = std::max(1, shader.line() - declarationLines);
        return out;
    }
    shader.error("it has no <RmShaderCode> (nor a CODE attribute, where RenderMonkey 1.0 kept the code)");
    return std::nullopt;
}

}  // namespace rmfx::rfx
