#include "frontend/shader/HlslFixedFunctionFog.h"

#include "core/IdentifierSearch.h"
#include "frontend/shader/GlslFloatLiteral.h"
#include "frontend/shader/GlslMainEnd.h"

namespace rmfx {
namespace {

std::string number(float v) { return glslFloatLiteral(static_cast<double>(v)); }

// The fog factor of depth `rm_fog_d`, before clamping.
std::string factor(const FixedFunctionFog& fog) {
    switch (fog.mode.value_or(FogMode::Linear)) {
        case FogMode::Exp: return "exp(-" + number(fog.density) + " * rm_fog_d)";
        case FogMode::Exp2: return "exp(-pow(" + number(fog.density) + " * rm_fog_d, 2.0))";
        case FogMode::Linear: break;
    }
    // Direct3D divides by end − start; equal ones leave no range, and everything is fog or not.
    if (fog.end == fog.start) return "(rm_fog_d < " + number(fog.end) + " ? 1.0 : 0.0)";
    return "(" + number(fog.end) + " - rm_fog_d) / " + number(fog.end - fog.start);
}

}  // namespace

bool appendFixedFunctionFog(std::string& glsl, const FixedFunctionFog& fog) {
    const std::string output = "rm_hlsl_out_COLOR0";
    if (!mentionsIdentifier(glsl, output)) return false;
    const std::optional<size_t> close = endOfMain(glsl);
    if (!close) return false;
    const std::string colour = "vec3(" + number(fog.color.r) + ", " + number(fog.color.g) + ", " + number(fog.color.b) + ")";
    glsl.insert(*close, " { float rm_fog_d = 1.0 / gl_FragCoord.w; float rm_fog = clamp(" + factor(fog) + ", 0.0, 1.0); " +
                           output + ".rgb = mix(" + colour + ", " + output + ".rgb, rm_fog); } ");
    return true;
}

}  // namespace rmfx
