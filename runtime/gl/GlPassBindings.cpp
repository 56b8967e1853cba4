#include "gl/GlPassBindings.h"

#include <algorithm>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "frontend/shader/PassProgram.h"
#include "gl/GlFormats.h"
#include "gl/GlProgramBuild.h"
#include "model/VertexUsageName.h"
#include "validation/GlslangCheck.h"

namespace rmfx {
namespace {

// <stream usage="texcoord" index="0" attribute="rm_TexCoord0"> (line 12), for messages.
std::string streamLabel(const VertexStream& stream) {
    std::string label = std::string("<stream usage=\"") + vertexUsageName(stream.usage) + "\"";
    if (stream.usage == VertexUsage::TexCoord || stream.usageIndex != 0)
        label += " index=\"" + std::to_string(stream.usageIndex) + "\"";
    if (!stream.attribute.empty()) label += " attribute=\"" + stream.attribute + "\"";
    return label + "> (line " + std::to_string(stream.where.line) + ")";
}

// The compatibility built-in a stream without an attribute feeds; empty for tangents and binormals.
std::string builtinAttributeName(const VertexStream& stream) {
    switch (stream.usage) {
        case VertexUsage::Position: return "gl_Vertex";
        case VertexUsage::Normal: return "gl_Normal";
        case VertexUsage::TexCoord: return "gl_MultiTexCoord" + std::to_string(stream.usageIndex);
        case VertexUsage::Color: return "gl_Color";
        case VertexUsage::Tangent:
        case VertexUsage::Binormal: break;
    }
    return {};
}

// Why a sampler that the compiled shader still uses reads a target with no memory.
std::string unallocatedRead(const FramePlan& plan, const GpuPass& gp, const Sampler& sampler) {
    std::string head = "pass '" + gp.pass->name + "' samples target '" + sampler.target + "'";
    for (auto& [off, g] : plan.graphs) {
        const PassNode& node = g.nodes[static_cast<size_t>(gp.index)];
        for (const std::string& skipped : node.skippedInputs) {
            if (skipped != sampler.target) continue;
            const Effect* owner = nullptr;
            for (const PassNode& n : g.nodes)
                if (n.target == skipped && n.effect) owner = n.effect;
            std::string effect = owner ? owner->name : "?";
            return head + ", which only effect '" + effect + "' writes, and that effect is not asked for; guard the "
                   "read with `if (" + effectMacro(effect) + ")` so that it compiles away";
        }
    }
    return head + ", which no scheduled pass writes";
}

SamplerHandle samplerObject(const Sampler& spec) {
    SamplerHandle handle = createSampler();
    const GLuint s = handle.get();
    glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(gl::minFilter(spec.filter, spec.mipmap)));
    glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(gl::magFilter(spec.filter)));
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, static_cast<GLint>(gl::wrapMode(spec.wrapS)));
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, static_cast<GLint>(gl::wrapMode(spec.wrapT)));
    glSamplerParameteri(s, GL_TEXTURE_WRAP_R, static_cast<GLint>(gl::wrapMode(spec.wrapR)));
    glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, glm::value_ptr(spec.border));
    return handle;
}

}  // namespace

Result<void> bindStreams(GpuPass& gp, bool compatibilityProfile) {
    gp.streams.clear();
    const Pass& pass = *gp.pass;
    if (pass.streams.empty() && !compatibilityProfile) return {};
    const std::set<std::string> inputs = activeInputs(gp.program.get());
    if (pass.streams.empty()) {
        // The mesh's default arrays are the generic attributes 0-2 (rm_Position, rm_NormalIn,
        // rm_TexCoordIn). A program that reads the built-ins gets exactly what it reads instead:
        // NVIDIA aliases generic attribute 2 with gl_Normal (and 3 with gl_Color, 8 with
        // gl_MultiTexCoord0), so with both arrays enabled gl_Normal read the texture coordinates.
        const VertexUsage defaults[3] = {VertexUsage::Position, VertexUsage::Normal, VertexUsage::TexCoord};
        bool readsBuiltins = false;
        auto builtinOf = [](VertexUsage usage) { VertexStream s; s.usage = usage; return builtinAttributeName(s); };
        for (VertexUsage usage : defaults) readsBuiltins |= inputs.count(builtinOf(usage)) > 0;
        if (!readsBuiltins) return {};
        for (int a = 0; a < 3; ++a)
            if (inputs.count(builtinAttributeLocations[a])) gp.streams.push_back({defaults[a], 0, a});
        for (VertexUsage usage : defaults)
            if (inputs.count(builtinOf(usage))) gp.streams.push_back({usage, 0, -1});
        return {};
    }
    Diagnostics d;
    auto warn = [&](const VertexStream& stream, const std::string& why) {
        d.push_back({Diagnostic::Severity::Warning, stream.where, passLabel(pass), "stream " + streamLabel(stream) + " " + why});
    };
    for (const VertexStream& stream : pass.streams) {
        if (!stream.attribute.empty()) {
            // Validation warns about attributes the shaders do not read; one the driver's
            // optimiser dropped as well is no news.
            GLint location = glGetAttribLocation(gp.program.get(), stream.attribute.c_str());
            if (location < 0) continue;
            gp.streams.push_back({stream.usage, stream.usageIndex, location});
            continue;
        }
        std::string builtin = builtinAttributeName(stream);
        if (builtin.empty()) {
            if (!stream.shared) warn(stream, "names no attribute, and tangents and binormals have no compatibility built-in");
        } else if (!compatibilityProfile) {
            warn(stream, "feeds the built-in " + builtin + ", which needs <workspace profile=\"compatibility\">");
        } else if (!inputs.count(builtin)) {
            if (!stream.shared) warn(stream, "feeds the built-in " + builtin + ", which the shaders do not read");
        } else {
            gp.streams.push_back({stream.usage, stream.usageIndex, -1});
        }
    }
    return d;
}

Result<void> bindUniforms(GpuPass& gp, const UniformSources& sources) {
    const Pass& pass = *gp.pass;
    Diagnostics d;
    auto error = [&](const SourceLocation& where, const std::string& element, const std::string& message) {
        d.push_back({Diagnostic::Severity::Error, where, element, message});
    };
    int unit = 0;
    for (const ProgramUniform& active : programUniforms(gp.program.get())) {
        const std::string& name = active.name;
        UniformType type = uniformTypeFromGl(active.glType);
        if (name.rfind("rmfx_health_", 0) == 0) continue;  // the health check's (gl/HealthInstrumentation.h)
        if (name.rfind("rmfx_effect_", 0) == 0) {  // declared by the effect prelude
            UniformSlot slot;
            slot.location = active.location;
            slot.name = name;
            slot.type = type;
            slot.effectSwitch = name.substr(12);
            gp.uniforms.push_back(std::move(slot));
            continue;
        }
        UniformSource source = resolveUniform(sources.ws, pass, name);
        if (std::holds_alternative<Unbound>(source) && keepsInitialValue(gp.initializedUniforms, name)) continue;
        if (unboundUniformIsZero(pass, source, type)) continue;  // validation warned: GL's initial zero stays
        if (std::string why = bindingMismatch(sources.ws, pass, source, name, type, active.arraySize); !why.empty()) {
            error(pass.where, passLabel(pass), why);
            continue;
        }
        if (const auto* s = std::get_if<BoundSampler>(&source)) {
            SamplerSlot slot;
            slot.unit = unit++;
            slot.sampler = s->sampler;
            glProgramUniform1i(gp.program.get(), active.location, slot.unit);
            if (!s->sampler->texture.empty()) {
                slot.texture = sources.textures.object(s->sampler->texture);
            } else {
                slot.target = sources.targets.find(s->sampler->target);
                if (!slot.target || !slot.target->resource) {
                    error(s->sampler->where, "<sampler name=\"" + name + "\">", unallocatedRead(sources.plan, gp, *s->sampler));
                    continue;
                }
            }
            slot.samplerObject = samplerObject(*s->sampler);
            gp.samplers.push_back(std::move(slot));
            continue;
        }
        UniformSlot slot;
        slot.location = active.location;
        slot.name = name;
        slot.type = type;
        slot.source = source;
        if (const auto* m = std::get_if<BoundSemantic>(&source)) {
            slot.semantic = m->info;
            slot.transposed = std::any_of(gp.pass->shaders.begin(), gp.pass->shaders.end(), [](const ShaderSource& s) {
                return s.dialect == ShaderDialect::Hlsl && s.matrixOrder == HlslMatrixOrder::ColumnVector;
            });
        }
        else if (const auto* c = std::get_if<BoundConstant>(&source)) slot.value = &c->constant->value;
        else if (const auto* v = std::get_if<BoundVariable>(&source)) slot.value = &sources.values.at(v->variable->name);
        gp.uniforms.push_back(std::move(slot));
    }
    return d;
}

}  // namespace rmfx
