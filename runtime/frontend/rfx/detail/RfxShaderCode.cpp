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
        // One attribute on one line of the file: a message about line n of the code names the
        // element's line. The declarations come first, on lines of their own, as RenderMonkey
        // compiled them; a message about them points before the element.
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
