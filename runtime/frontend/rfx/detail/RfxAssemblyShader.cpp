#include "frontend/rfx/detail/RfxAssemblyShader.h"

#include <algorithm>

#include "frontend/rfx/detail/RfxShaderCode.h"
#include "frontend/shader/D3DAsmHlslNames.h"
#include "frontend/shader/D3DAsmParser.h"

namespace rmfx::rfx {

std::optional<ShaderSource> readAssemblyShader(const RfxElement& c, const AssemblyContext& context, std::string& why) {
    const bool pixel = c.flag("PIXEL_SHADER", false).value_or(false);
    const std::string stage = pixel ? "pixel" : "vertex";
    why = "its " + stage + " shader " + c.label() + " (line " + std::to_string(c.line()) + ") ";
    std::optional<RfxShaderCode> codeOf = shaderCodeOf(c);
    if (!codeOf) {
        why += "has no code";
        return std::nullopt;
    }
    ShaderSource s;
    s.stage = pixel ? ShaderStage::Fragment : ShaderStage::Vertex;
    s.where = c.where();
    s.dialect = ShaderDialect::Hlsl;
    s.matrixOrder = HlslMatrixOrder::ColumnVector;  // m4x4 reads register base+i as row i
    std::string code = std::move(codeOf->code);
    s.codeLine = codeOf->line;

    bool failed = false;
    auto report = [&](const std::vector<d3dasm::Message>& messages) {
        for (const d3dasm::Message& m : messages) {
            const bool error = m.error && context.passEnabled;
            failed = failed || m.error;
            c.diagnostics().push_back({error ? Diagnostic::Severity::Error : Diagnostic::Severity::Warning,
                                       {c.file(), s.codeLine + std::max(m.line, 1) - 1}, c.label(), m.text});
        }
    };
    d3dasm::ParseResult parsed = d3dasm::parseAssembly(code);
    report(parsed.messages);
    if (failed) {
        why += "is assembly rmfx cannot read";
        return std::nullopt;
    }
    if (parsed.program.pixel != pixel) {
        c.error(std::string("PIXEL_SHADER is ") + (pixel ? "TRUE" : "FALSE") + " but the code is a " +
                (parsed.program.pixel ? "pixel" : "vertex") + " shader");
        why += "does not match its stage";
        return std::nullopt;
    }

    std::vector<d3dasm::ConstantBinding> constants;
    std::vector<d3dasm::SamplerBinding> samplers = context.samplers;
    for (const XMLElement* x = c.xml()->FirstChildElement(); x; x = x->NextSiblingElement()) {
        RfxElement child(x, c.file(), c.diagnostics());
        const std::string tag = x->Name();
        if (tag != "RmShaderConstant" && tag != "RmSampler") continue;
        auto reg = child.integer("REGISTER", 0, tag == "RmSampler" ? 15 : 255);
        if (!reg) continue;
        if (!d3dasm::hlslIdentifier(child.name())) {
            c.diagnostics().push_back({context.passEnabled ? Diagnostic::Severity::Error : Diagnostic::Severity::Warning,
                                       child.where(), child.label(),
                                       "'" + child.name() + "' cannot be the name of an HLSL global (a keyword, a register's "
                                       "name or not an identifier), which the translated assembly binds it through"});
            failed = true;
            continue;
        }
        if (tag == "RmSampler") {
            std::erase_if(samplers, [&](const d3dasm::SamplerBinding& b) { return b.name == child.name(); });
            d3dasm::SamplerKind kind = d3dasm::SamplerKind::Unknown;
            for (const d3dasm::SamplerBinding& b : context.samplers)
                if (b.name == child.name()) kind = b.kind;
            samplers.insert(samplers.begin(), {child.name(), static_cast<int>(*reg), kind});
            continue;
        }
        const Variable* v = context.variable ? context.variable(child.name()) : nullptr;
        if (!v) continue;  // the register reads 0, which the translation warns about where it is read
        constants.push_back({child.name(), static_cast<int>(*reg), v->value.type, 0});
    }

    if (failed) {
        why += "could not be translated from assembly";
        return std::nullopt;
    }
    d3dasm::HlslFromAsm hlsl = d3dasm::translateAssembly(parsed.program, constants, samplers, context.streams);
    report(hlsl.messages);
    if (failed) {
        why += "could not be translated from assembly";
        return std::nullopt;
    }
    const std::string version = std::string(pixel ? "ps" : "vs") + "_" + std::to_string(parsed.program.major) + "_" +
                                std::to_string(parsed.program.minor);
    c.warning("Direct3D assembly (" + version + ") translated to HLSL for rmfx's HLSL path");
    s.code = std::move(hlsl.hlsl);
    s.entryPoint = hlsl.entryPoint;
    // The version it was written for, not the ps_3_0 the generated HLSL is compiled as: Direct3D's
    // fixed-function fog follows a ps_1_x or ps_2_x shader.
    s.profile = version;
    return s;
}

}  // namespace rmfx::rfx
