#include "graph/UniformBinding.h"

#include <algorithm>

namespace rmfx {

UniformSource resolveUniform(const Workspace& ws, const Pass& pass, const std::string& name) {
    for (size_t i = 0; i < pass.samplers.size(); ++i)
        if (pass.samplers[i].uniform == name) return BoundSampler{&pass.samplers[i], static_cast<int>(i)};
    auto semantic = [](const Variable& v) { return v.semantic.empty() ? std::nullopt : findSemantic(v.semantic); };
    for (const Variable& c : pass.constants) {
        if (c.name != name) continue;
        if (auto s = semantic(c)) return BoundSemantic{&c, *s};
        return BoundConstant{&c};
    }
    if (const Variable* v = ws.findVariable(name)) {
        if (auto s = semantic(*v)) return BoundSemantic{v, *s};
        return BoundVariable{v};
    }
    if (auto p = findPredefined(name)) return BoundPredefined{*p};
    return Unbound{};
}

namespace {

std::string where(const SourceLocation& at) { return at.file + ":" + std::to_string(at.line); }

bool hasHlsl(const Pass& pass) {
    return std::any_of(pass.shaders.begin(), pass.shaders.end(), [](const ShaderSource& s) { return s.dialect == ShaderDialect::Hlsl; });
}

// A Direct3D constant register is four floats: a wider float vector variable set it whole, and
// the shader read as many as its constant declared. (An int or bool has one component, never
// more than a constant wants; a 2x2 matrix has four but is no vector.)
bool registerTakesFirstComponents(UniformType uniform, ValueType variable) {
    const int wanted = floatVectorWidth(uniform), given = componentCount(variable);
    return wanted > 0 && given > wanted && given <= 4 && variable != ValueType::Mat2;
}

}  // namespace

std::string bindingMismatch(const Workspace& ws, const Pass& pass, const UniformSource& source, const std::string& uniform,
                            UniformType type, int arraySize) {
    std::string declared = "uniform '" + uniform + "' is declared " + uniformTypeName(type) +
                           (arraySize > 1 ? "[" + std::to_string(arraySize) + "]" : "");
    const bool direct3d = hasHlsl(pass);
    const bool fedByValue = std::holds_alternative<BoundVariable>(source) || std::holds_alternative<BoundConstant>(source);
    if (arraySize > 1 && !(direct3d && fedByValue)) return declared + ", but arrays cannot be bound to variables";
    if (const auto* s = std::get_if<BoundSampler>(&source)) {
        TextureKind kind = TextureKind::Texture2D;
        if (!s->sampler->texture.empty())
            if (const Texture* t = ws.findTexture(s->sampler->texture)) kind = t->kind;
        UniformType wanted = kind == TextureKind::Cube     ? UniformType::SamplerCube
                             : kind == TextureKind::Volume ? UniformType::Sampler3D
                                                           : UniformType::Sampler2D;
        if (type == wanted) return {};
        return declared + ", but <sampler name=\"" + uniform + "\"> (" + where(s->sampler->where) + ") binds " +
               (kind == TextureKind::Cube     ? "a cube map and needs samplerCube"
                : kind == TextureKind::Volume ? "a volume (3D) texture and needs sampler3D"
                                              : "a 2D image and needs sampler2D");
    }
    auto variableMismatch = [&](const Variable& v, const char* kind) -> std::string {
        if (uniformAccepts(type, v.value.type) || (direct3d && registerTakesFirstComponents(type, v.value.type))) return {};
        return declared + ", but " + kind + " '" + v.name + "' (" + where(v.where) + ") is a " +
               valueTypeName(v.value.type) + " (binds to GLSL " + glslTypeName(v.value.type) + ")";
    };
    if (const auto* c = std::get_if<BoundConstant>(&source)) return variableMismatch(*c->constant, "pass constant");
    if (const auto* v = std::get_if<BoundVariable>(&source)) return variableMismatch(*v->variable, "variable");
    if (const auto* s = std::get_if<BoundSemantic>(&source)) {
        if (semanticFeeds(s->info, type)) return {};
        return declared + ", but variable '" + s->variable->name + "' (" + where(s->variable->where) + ") has semantic " +
               s->info.name + ", a " + uniformTypeName(s->info.type);
    }
    if (const auto* p = std::get_if<BoundPredefined>(&source)) {
        if (p->info.type == type) return {};
        return declared + ", but the predefined " + p->info.name + " is a " + uniformTypeName(p->info.type);
    }
    if (isSampler(type))
        return declared + ", but the pass has no <sampler name=\"" + uniform + "\">";
    return declared + ", but no variable, pass constant or predefined value has that name";
}

bool unboundUniformIsZero(const Pass& pass, const UniformSource& source, UniformType type) {
    return std::holds_alternative<Unbound>(source) && !isSampler(type) &&
           std::any_of(pass.shaders.begin(), pass.shaders.end(),
                       [](const ShaderSource& s) { return s.dialect == ShaderDialect::Hlsl; });
}

}  // namespace rmfx
