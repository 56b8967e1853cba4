// ReshadeParserRun's techniques and their passes: every pass state ReShade knows, each value a
// function, a texture, a name from the state's enumeration or a constant.
#include "frontend/reshade/ReshadeParserRun.h"

#include <algorithm>
#include <cmath>

namespace rmfx {
namespace {

using DK = ReshadeDeclaration::Kind;
using TK = ReshadeToken::Kind;

enum class Value { Bool, Uint, Enum };

struct StateSpec {
    std::string_view name;
    Value value;
    const ReshadeEnum& (*table)();
    bool indexed;  // also NAME0 … NAME7, one render target's; NAME sets all eight
};

constexpr StateSpec kStates[] = {
    {"SRGBWriteEnable", Value::Bool, nullptr, false},
    {"BlendEnable", Value::Bool, nullptr, true},
    {"StencilEnable", Value::Bool, nullptr, false},
    {"ClearRenderTargets", Value::Bool, nullptr, false},
    {"GenerateMipMaps", Value::Bool, nullptr, false},
    {"GenerateMipmaps", Value::Bool, nullptr, false},
    {"ColorWriteMask", Value::Uint, nullptr, true},
    {"RenderTargetWriteMask", Value::Uint, nullptr, true},
    {"ColorWriteEnable", Value::Uint, nullptr, true},
    {"StencilReadMask", Value::Uint, nullptr, false},
    {"StencilMask", Value::Uint, nullptr, false},
    {"StencilWriteMask", Value::Uint, nullptr, false},
    {"BlendOp", Value::Enum, reshadeBlendOps, true},
    {"BlendOpAlpha", Value::Enum, reshadeBlendOps, true},
    {"SrcBlend", Value::Enum, reshadeBlendFactors, true},
    {"SrcBlendAlpha", Value::Enum, reshadeBlendFactors, true},
    {"DestBlend", Value::Enum, reshadeBlendFactors, true},
    {"DestBlendAlpha", Value::Enum, reshadeBlendFactors, true},
    {"StencilFunc", Value::Enum, reshadeCompareFuncs, false},
    {"StencilRef", Value::Uint, nullptr, false},
    {"StencilPass", Value::Enum, reshadeStencilOps, false},
    {"StencilPassOp", Value::Enum, reshadeStencilOps, false},
    {"StencilFail", Value::Enum, reshadeStencilOps, false},
    {"StencilFailOp", Value::Enum, reshadeStencilOps, false},
    {"StencilZFail", Value::Enum, reshadeStencilOps, false},
    {"StencilDepthFail", Value::Enum, reshadeStencilOps, false},
    {"StencilDepthFailOp", Value::Enum, reshadeStencilOps, false},
    {"VertexCount", Value::Uint, nullptr, false},
    {"PrimitiveType", Value::Enum, reshadePrimitiveTopologies, false},
    {"PrimitiveTopology", Value::Enum, reshadePrimitiveTopologies, false},
    {"DispatchSizeX", Value::Uint, nullptr, false},
    {"DispatchSizeY", Value::Uint, nullptr, false},
    {"DispatchSizeZ", Value::Uint, nullptr, false},
};

const StateSpec* findState(std::string_view name) {
    for (const StateSpec& s : kStates)
        if (s.name == name) return &s;
    return nullptr;
}

uint32_t toUint(double v) {
    if (std::isnan(v) || v <= 0) return 0;
    return v >= 4294967295.0 ? 0xFFFFFFFFu : static_cast<uint32_t>(v);
}

template <class T, class V>
void setIndexed(std::array<T, 8>& values, int index, V value) {
    if (index < 0) values.fill(static_cast<T>(value));
    else values[static_cast<size_t>(index)] = static_cast<T>(value);
}

void apply(ReshadePass& pass, std::string_view state, int index, double value) {
    const bool on = value != 0;
    const uint32_t n = toUint(value);
    const int e = static_cast<int>(value);
    if (state == "SRGBWriteEnable") pass.srgbWriteEnable = on;
    else if (state == "BlendEnable") setIndexed(pass.blendEnable, index, on);
    else if (state == "StencilEnable") pass.stencilEnable = on;
    else if (state == "ClearRenderTargets") pass.clearRenderTargets = on;
    else if (state == "GenerateMipMaps" || state == "GenerateMipmaps") pass.generateMipMaps = on;
    else if (state == "ColorWriteMask" || state == "RenderTargetWriteMask" || state == "ColorWriteEnable")
        setIndexed(pass.colorWriteMask, index, n & 0xFF);
    else if (state == "StencilReadMask" || state == "StencilMask") pass.stencilReadMask = static_cast<uint8_t>(n & 0xFF);
    else if (state == "StencilWriteMask") pass.stencilWriteMask = static_cast<uint8_t>(n & 0xFF);
    else if (state == "BlendOp") setIndexed(pass.blendOp, index, static_cast<ReshadeBlendOp>(e));
    else if (state == "BlendOpAlpha") setIndexed(pass.blendOpAlpha, index, static_cast<ReshadeBlendOp>(e));
    else if (state == "SrcBlend") setIndexed(pass.srcBlend, index, static_cast<ReshadeBlendFactor>(e));
    else if (state == "SrcBlendAlpha") setIndexed(pass.srcBlendAlpha, index, static_cast<ReshadeBlendFactor>(e));
    else if (state == "DestBlend") setIndexed(pass.destBlend, index, static_cast<ReshadeBlendFactor>(e));
    else if (state == "DestBlendAlpha") setIndexed(pass.destBlendAlpha, index, static_cast<ReshadeBlendFactor>(e));
    else if (state == "StencilFunc") pass.stencilFunc = static_cast<ReshadeCompareFunc>(e);
    else if (state == "StencilRef") pass.stencilRef = n;
    else if (state == "StencilPass" || state == "StencilPassOp") pass.stencilPass = static_cast<ReshadeStencilOp>(e);
    else if (state == "StencilFail" || state == "StencilFailOp") pass.stencilFail = static_cast<ReshadeStencilOp>(e);
    else if (state == "StencilZFail" || state == "StencilDepthFail" || state == "StencilDepthFailOp")
        pass.stencilDepthFail = static_cast<ReshadeStencilOp>(e);
    else if (state == "VertexCount") pass.vertexCount = n;
    else if (state == "PrimitiveType" || state == "PrimitiveTopology") pass.topology = static_cast<ReshadePrimitiveTopology>(e);
    else if (state == "DispatchSizeX") pass.dispatchSize[0] = static_cast<int>(std::min<uint32_t>(n, 0x7FFFFFFF));
    else if (state == "DispatchSizeY") pass.dispatchSize[1] = static_cast<int>(std::min<uint32_t>(n, 0x7FFFFFFF));
    else if (state == "DispatchSizeZ") pass.dispatchSize[2] = static_cast<int>(std::min<uint32_t>(n, 0x7FFFFFFF));
}

}  // namespace

void ReshadeParserRun::parseTechnique() {
    c_.next();
    const SourceLocation where = c_.here();
    std::optional<std::string> name = c_.expectIdentifier("technique", "a technique name");
    if (!name) return recover();
    ReshadeTechnique technique;
    technique.name = *name;
    technique.where = where;
    const std::string element = "technique " + technique.name;
    technique.annotations = parseAnnotations(element);
    if (!c_.expect("{", element)) return recover();
    while (!c_.atEnd() && !c_.is("}")) {
        if (!c_.is("pass")) {
            const size_t before = c_.position();
            c_.error(c_.here(), element, "expected 'pass' or '}', found " + c_.describe(c_.peek()));
            skipUntil("pass");
            if (c_.position() == before) c_.next();
            continue;
        }
        ReshadePass pass;
        c_.next();
        pass.where = c_.where(c_.previous());
        if (c_.isKind(TK::Identifier)) pass.name = std::string(c_.text(c_.next()));
        const std::string passElement =
            "pass " + (pass.name.empty() ? std::to_string(technique.passes.size() + 1) : pass.name) + " of " + element;
        parsePass(pass, passElement);
        technique.passes.push_back(std::move(pass));
    }
    if (!c_.accept("}")) c_.error(where, element, "the technique's '{' is never closed");
    if (technique.passes.empty()) c_.warning(where, element, "the technique has no passes");
    const size_t index = effect_.techniques.size();
    effect_.techniques.push_back(std::move(technique));
    addDeclaration(DK::Technique, index);
}

void ReshadeParserRun::parsePass(ReshadePass& pass, const std::string& element) {
    if (!c_.expect("{", element)) {
        skipUntil("}");
        c_.accept("}");
        return;
    }
    const size_t errorsBefore = c_.errorCount();
    while (!c_.atEnd() && !c_.is("}")) {
        const size_t before = c_.position();
        const SourceLocation where = c_.here();
        std::optional<std::string> state = c_.expectIdentifier(element, "a pass state");
        if (state && c_.expect("=", element)) {
            const size_t valueStart = c_.position();
            const size_t errors = c_.errorCount();
            parsePassState(pass, *state, where, element);
            if (c_.position() > valueStart) {
                const size_t begin = c_.token(valueStart).offset;
                pass.states.push_back({*state, c_.code().substr(begin, c_.previous().offset + c_.previous().length - begin), where});
            }
            if (c_.accept(";")) {
                // next state
            } else if (c_.is("}") || (c_.isKind(TK::Identifier) && c_.is("=", 1))) {
                c_.expect(";", element);  // a missing ';': read on
            } else {
                if (c_.errorCount() == errors)
                    c_.error(c_.here(), element, *state + ": unexpected " + c_.describe(c_.peek()) + " after the value");
                skipUntil(";");
                c_.accept(";");
            }
        } else {
            skipUntil(";");
            c_.accept(";");
        }
        if (c_.position() == before) c_.next();
    }
    if (!c_.accept("}")) {
        c_.error(pass.where, element, "the pass's '{' is never closed");
        return;
    }
    if (c_.errorCount() != errorsBefore) return;  // what is missing may be what failed
    if (!pass.computeShader.empty()) {
        if (pass.dispatchSize[0] == 0 || pass.dispatchSize[1] == 0)
            c_.error(pass.where, element, "a compute pass needs DispatchSizeX and DispatchSizeY");
    } else {
        if (pass.vertexShader.empty()) c_.error(pass.where, element, "the pass has no VertexShader");
        if (pass.pixelShader.empty()) c_.error(pass.where, element, "the pass has no PixelShader");
    }
}

void ReshadeParserRun::parsePassState(ReshadePass& pass, const std::string& state, const SourceLocation& where,
                                      const std::string& element) {
    const bool shader = state == "VertexShader" || state == "PixelShader" || state == "ComputeShader";
    const bool target = state.rfind("RenderTarget", 0) == 0 &&
                        (state.size() == 12 || (state.size() == 13 && state[12] >= '0' && state[12] <= '7'));
    if (shader || target) {
        const SourceLocation at = c_.here();
        if (!c_.isKind(TK::Identifier) && !c_.is("::")) {
            c_.error(at, element, state + ": expected a " + (shader ? "function" : "texture") + " name, found " + c_.describe(c_.peek()));
            return;
        }
        if (target) {
            if (std::optional<std::string> texture = readTextureName(element))
                pass.renderTargets[state.size() == 12 ? 0 : static_cast<size_t>(state[12] - '0')] = *texture;
            return;
        }
        const std::string written = readQualifiedName();
        std::array<int, 3> threads{1, 1, 1};
        if (c_.accept("<")) {
            for (size_t k = 0; k < 3; ++k) {
                if (k > 0 && !(k == 2 ? c_.accept(",") : c_.expect(",", element))) break;
                std::string error;
                const SourceLocation numberAt = c_.here();
                std::optional<ReshadeValue> n = readReshadeConstant(c_, lookup(), error, true);
                if (!n || !n->isNumber() || n->at() < 1) {
                    c_.error(numberAt, element, state + ": a thread group size must be a positive constant" + (error.empty() ? "" : ": " + error));
                    return;
                }
                threads[k] = static_cast<int>(std::min(n->at(), 65536.0));
            }
            if (!c_.expect(">", element)) return;
        }
        const Symbol* symbol = resolve(written, DK::Function);
        if (!symbol) {
            c_.error(at, element, state + ": undeclared identifier '" + written + "', expected a function");
            return;
        }
        if (symbol->kind != DK::Function) {
            c_.error(at, element, state + ": '" + written + "' is not a function");
            return;
        }
        const std::string& function = effect_.functions[symbol->index].name;
        if (state[0] == 'V') pass.vertexShader = function;
        else if (state[0] == 'P') pass.pixelShader = function;
        else {
            pass.computeShader = function;
            pass.threadGroupSize = threads;
        }
        return;
    }
    std::string_view base = state;
    int index = -1;
    const StateSpec* spec = findState(base);
    if (!spec && !state.empty() && state.back() >= '0' && state.back() <= '7') {
        base.remove_suffix(1);
        spec = findState(base);
        if (spec && !spec->indexed) spec = nullptr;
        index = state.back() - '0';
    }
    if (!spec) {
        c_.error(where, element, "unknown pass state '" + state + "'");
        skipUntil(";");
        return;
    }
    std::optional<ReshadeValue> value = readStateValue(spec->table ? &spec->table() : nullptr, state, element);
    if (!value) return;
    if (spec->value == Value::Bool && value->kind == ReshadeValue::Kind::Float)
        c_.warning(where, element, state + " is a float; it is read as " + (value->at() != 0 ? "true" : "false"));
    apply(pass, base, index, value->at());
}

}  // namespace rmfx
