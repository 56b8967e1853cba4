#pragma once
// The syntax tree of a ReShade FX effect (ReshadeParser.h builds it): its uniforms, textures,
// samplers, storages, structs, constants, functions and techniques, each with the place the user
// wrote it. Names inside a namespace are qualified ("Ns::Name"). Function bodies are kept as spans
// of the preprocessed code, to be translated later; everything else is read to values.
//
//   uniform float Strength < ui_type = "slider"; ui_min = 0.0; > = 0.5;
//     → ReshadeUniform{name "Strength", type float, annotations {ui_type "slider", ui_min 0.0},
//                      initializer 0.5}

#include <array>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Diagnostic.h"
#include "frontend/reshade/ReshadeStates.h"

namespace rmfx {

// A constant: an annotation's value, a uniform's initial value, a `static const`'s value.
struct ReshadeValue {
    enum class Kind { Bool, Int, Uint, Float, String };
    Kind kind = Kind::Int;
    // The components: one for a scalar, N for a vector, rows * columns for a matrix (row by row),
    // every element's in turn for an array. Bools are 0 or 1.
    std::vector<double> components;
    std::string text;  // a String's text, escapes resolved ("A\0B\0" holds two NULs)

    static ReshadeValue number(Kind kind, double value) { return {kind, {value}, {}}; }
    static ReshadeValue string(std::string text) { return {Kind::String, {}, std::move(text)}; }
    bool isNumber() const { return kind != Kind::String; }
    double at(size_t i = 0) const { return i < components.size() ? components[i] : 0.0; }
    // A plain spelling for messages and tests: 1, 0.5, true, "text", {1, 2, 3}.
    std::string describe() const;
};

struct ReshadeAnnotation {
    std::string name;
    ReshadeValue value;
    SourceLocation where;
};

using ReshadeAnnotations = std::vector<ReshadeAnnotation>;

// The annotation called `name`, or null.
const ReshadeAnnotation* findAnnotation(const ReshadeAnnotations& annotations, std::string_view name);

enum class ReshadeBaseType { Void, Bool, Int, Uint, Float, String, Struct, Texture, Sampler, Storage };

struct ReshadeType {
    ReshadeBaseType base = ReshadeBaseType::Float;
    int rows = 1;         // a vector's size, or a matrix's rows
    int cols = 1;         // a matrix's columns; 1 for scalars and vectors
    int arrayLength = 0;  // 0: not an array; -1: `[]`, sized by the initializer
    int dimensions = 2;   // textures, samplers, storages: 1, 2 or 3
    std::string name;     // as written ("float4", "texture2D"); a struct's qualified name
    std::string element;  // the `<…>` of `sampler2D<uint>`; empty when none

    bool isNumeric() const {
        return base == ReshadeBaseType::Bool || base == ReshadeBaseType::Int || base == ReshadeBaseType::Uint ||
               base == ReshadeBaseType::Float;
    }
    bool isObject() const {
        return base == ReshadeBaseType::Texture || base == ReshadeBaseType::Sampler || base == ReshadeBaseType::Storage;
    }
};

// Qualifiers written before a type, a bit each.
enum ReshadeQualifier : unsigned {
    kReshadeStatic = 1u << 0,
    kReshadeConst = 1u << 1,
    kReshadeUniform = 1u << 2,
    kReshadeExtern = 1u << 3,
    kReshadeGroupshared = 1u << 4,
    kReshadeVolatile = 1u << 5,
    kReshadePrecise = 1u << 6,
    kReshadeIn = 1u << 7,
    kReshadeOut = 1u << 8,  // `inout` is both
    kReshadeLinear = 1u << 9,
    kReshadeNoPerspective = 1u << 10,
    kReshadeCentroid = 1u << 11,
    kReshadeNoInterpolation = 1u << 12,
};

// A part of the preprocessed code (PreprocessedReshade::code): [begin, end) in bytes.
struct ReshadeSpan {
    size_t begin = 0;
    size_t end = 0;
    SourceLocation where;  // where it starts
    bool empty() const { return begin == end; }
};

struct ReshadeUniform {
    std::string name;
    ReshadeType type;
    unsigned qualifiers = 0;
    bool implicit = false;  // declared without `uniform` (a global that is not static is one)
    ReshadeAnnotations annotations;
    std::optional<ReshadeValue> initializer;
    SourceLocation where;
};

struct ReshadeTexture {
    std::string name;
    ReshadeType type;
    std::string semantic;  // "COLOR", "DEPTH" (upper case), or empty
    ReshadeAnnotations annotations;  // source = "file.png", pooled = true, …
    int width = 1;
    int height = 1;
    int depth = 1;
    int mipLevels = 1;
    ReshadeTextureFormat format = ReshadeTextureFormat::RGBA8;
    SourceLocation where;
};

struct ReshadeSampler {
    std::string name;
    ReshadeType type;
    std::string texture;  // the texture's qualified name
    ReshadeAnnotations annotations;
    std::array<ReshadeAddressMode, 3> address{ReshadeAddressMode::Clamp, ReshadeAddressMode::Clamp,
                                              ReshadeAddressMode::Clamp};  // U, V, W
    ReshadeFilter magFilter = ReshadeFilter::Linear;
    ReshadeFilter minFilter = ReshadeFilter::Linear;
    ReshadeFilter mipFilter = ReshadeFilter::Linear;
    float minLod = 0.0f;
    float maxLod = FLT_MAX;
    float mipLodBias = 0.0f;
    bool srgb = false;  // SRGBTexture
    SourceLocation where;
};

struct ReshadeStorage {
    std::string name;
    ReshadeType type;
    std::string texture;  // the texture's qualified name
    int mipLevel = 0;
    SourceLocation where;
};

struct ReshadeField {
    ReshadeType type;
    unsigned qualifiers = 0;
    std::string name;
    std::string semantic;  // as written; empty when none
    std::optional<ReshadeValue> defaultValue;  // a parameter's `= value`, when it has one
    SourceLocation where;
};

struct ReshadeStruct {
    std::string name;
    std::vector<ReshadeField> fields;
    SourceLocation where;
};

// A global that is not a uniform: `static const float PI = 3.14159;`, `groupshared int t[64];`.
struct ReshadeVariable {
    std::string name;
    ReshadeType type;
    unsigned qualifiers = 0;
    std::optional<ReshadeValue> value;  // the initializer's value, when it is a constant rmfx computes
    ReshadeSpan initializer;            // its text; empty when there is none
    SourceLocation where;
};

// An attribute before a function: `[shader("vertex")]`, `[numthreads(8, 8, 1)]`.
struct ReshadeAttribute {
    std::string name;
    std::vector<ReshadeValue> arguments;
    SourceLocation where;
};

struct ReshadeFunction {
    std::vector<ReshadeAttribute> attributes;
    std::string name;
    ReshadeType returnType;
    std::string returnSemantic;
    std::vector<ReshadeField> parameters;  // qualifiers: in, out (inout is both), interpolation
    ReshadeSpan body;                      // from its '{' to just after its '}'
    SourceLocation where;
};

// A pass state as written, in order: `SrcBlend = INVSRCALPHA;` → {"SrcBlend", "INVSRCALPHA"}.
struct ReshadePassState {
    std::string name;
    std::string value;
    SourceLocation where;
};

struct ReshadePass {
    std::string name;  // empty when unnamed
    SourceLocation where;
    // Entry points' qualified function names; empty when not set.
    std::string vertexShader;
    std::string pixelShader;
    std::string computeShader;
    std::array<int, 3> threadGroupSize{1, 1, 1};  // ComputeShader = CS<X, Y, Z>
    std::array<int, 3> dispatchSize{0, 0, 1};     // DispatchSizeX/Y/Z; X and Y 0 when not set
    std::array<std::string, 8> renderTargets;     // qualified texture names; empty: none (0: the back buffer)
    bool clearRenderTargets = false;
    bool generateMipMaps = true;
    bool srgbWriteEnable = false;
    std::array<bool, 8> blendEnable{};
    std::array<ReshadeBlendOp, 8> blendOp{};
    std::array<ReshadeBlendOp, 8> blendOpAlpha{};
    std::array<ReshadeBlendFactor, 8> srcBlend;
    std::array<ReshadeBlendFactor, 8> destBlend;
    std::array<ReshadeBlendFactor, 8> srcBlendAlpha;
    std::array<ReshadeBlendFactor, 8> destBlendAlpha;
    std::array<uint8_t, 8> colorWriteMask;
    bool stencilEnable = false;
    uint8_t stencilReadMask = 0xFF;
    uint8_t stencilWriteMask = 0xFF;
    ReshadeCompareFunc stencilFunc = ReshadeCompareFunc::Always;
    uint32_t stencilRef = 0;
    ReshadeStencilOp stencilPass = ReshadeStencilOp::Keep;
    ReshadeStencilOp stencilFail = ReshadeStencilOp::Keep;
    ReshadeStencilOp stencilDepthFail = ReshadeStencilOp::Keep;
    ReshadePrimitiveTopology topology = ReshadePrimitiveTopology::TriangleList;
    uint32_t vertexCount = 3;
    std::vector<ReshadePassState> states;

    ReshadePass() {
        srcBlend.fill(ReshadeBlendFactor::One);
        destBlend.fill(ReshadeBlendFactor::Zero);
        srcBlendAlpha.fill(ReshadeBlendFactor::One);
        destBlendAlpha.fill(ReshadeBlendFactor::Zero);
        colorWriteMask.fill(0xF);
    }
};

struct ReshadeTechnique {
    std::string name;
    ReshadeAnnotations annotations;  // ui_label, ui_tooltip, enabled, hidden, timeout, toggle, …
    std::vector<ReshadePass> passes;
    SourceLocation where;
};

// Which list a declaration went to, and where in it: the effect's declarations in their order.
struct ReshadeDeclaration {
    enum class Kind { Uniform, Texture, Sampler, Storage, Struct, Variable, Function, Technique };
    Kind kind;
    size_t index;
};

struct ReshadeEffect {
    std::vector<ReshadeUniform> uniforms;
    std::vector<ReshadeTexture> textures;
    std::vector<ReshadeSampler> samplers;
    std::vector<ReshadeStorage> storages;
    std::vector<ReshadeStruct> structs;
    std::vector<ReshadeVariable> variables;
    std::vector<ReshadeFunction> functions;
    std::vector<ReshadeTechnique> techniques;
    std::vector<ReshadeDeclaration> order;
};

}  // namespace rmfx
