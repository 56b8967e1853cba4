#include "frontend/shader/HlslAlphaTest.h"

#include "core/IdentifierSearch.h"
#include "frontend/shader/GlslFloatLiteral.h"
#include "frontend/shader/GlslMainEnd.h"

namespace rmfx {

bool appendAlphaTest(std::string& glsl, const AlphaTest& test) {
    const std::string output = "rm_hlsl_out_COLOR0";
    if (!mentionsIdentifier(glsl, output)) return false;
    const std::optional<size_t> close = endOfMain(glsl);
    if (!close) return false;
    const std::string ref = glslFloatLiteral(static_cast<double>(test.ref));
    const std::string alpha = output + ".a";
    std::string passes;
    switch (test.func) {
        case CompareFunc::Never: passes = "false"; break;
        case CompareFunc::Less: passes = alpha + " < " + ref; break;
        case CompareFunc::Equal: passes = alpha + " == " + ref; break;
        case CompareFunc::LessEqual: passes = alpha + " <= " + ref; break;
        case CompareFunc::Greater: passes = alpha + " > " + ref; break;
        case CompareFunc::NotEqual: passes = alpha + " != " + ref; break;
        case CompareFunc::GreaterEqual: passes = alpha + " >= " + ref; break;
        case CompareFunc::Always: return true;
    }
    glsl.insert(*close, " if (!(" + passes + ")) discard; ");
    return true;
}

}  // namespace rmfx
