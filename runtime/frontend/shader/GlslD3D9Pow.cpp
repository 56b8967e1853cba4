#include "frontend/shader/GlslD3D9Pow.h"

#include "core/IdentifierSearch.h"

namespace rmfx {

std::string powOfAbsoluteBase(std::string glsl) {
    // SPIRV-Cross names nothing else pow: every whole-word pow is the built-in's call.
    if (!mentionsIdentifier(glsl, "pow")) return glsl;
    replaceIdentifier(glsl, "pow", "rm_d3d9_pow");
    std::string definitions;
    // 0^0 is 1, as Direct3D 9 gives it (fxc folds pow(x, 0); the instruction's exp(0 * log(0))
    // multiplies by zero first), where GLSL leaves it undefined (NaN on Mesa).
    definitions += "float rm_d3d9_pow(float x, float y) { return y == 0.0 ? 1.0 : pow(abs(x), y); }\n";
    for (const char* type : {"vec2", "vec3", "vec4"})
        definitions += std::string(type) + " rm_d3d9_pow(" + type + " x, " + type + " y) { return mix(pow(abs(x), y), " + type +
                       "(1.0), equal(y, " + type + "(0.0))); }\n";
    size_t after = 0;
    if (glsl.rfind("#version", 0) == 0) after = glsl.find('\n') == std::string::npos ? glsl.size() : glsl.find('\n') + 1;
    // #extension lines must come before any declaration.
    for (size_t line = after; glsl.compare(line, 10, "#extension") == 0;) {
        const size_t end = glsl.find('\n', line);
        after = line = end == std::string::npos ? glsl.size() : end + 1;
    }
    glsl.insert(after, definitions);
    return glsl;
}

}  // namespace rmfx
