#include "frontend/rfx/detail/RfxRenderStates.h"

#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <string_view>

#include "core/Value.h"
#include "frontend/rfx/detail/RfxPackedColor.h"

namespace rmfx::rfx {
namespace {

constexpr long long kInt32Min = -2147483648LL, kUInt32Max = 4294967295LL;

template <class E>
struct Choice {
    long long value;
    E meaning;
};

template <class E, size_t N>
std::optional<E> pick(const RfxElement& state, const char* what, long long value, const Choice<E> (&choices)[N]) {
    for (const auto& c : choices)
        if (c.value == value) return c.meaning;
    std::string known;
    for (const auto& c : choices) known += (known.empty() ? "" : ", ") + std::to_string(c.value);
    state.error("VALUE " + std::to_string(value) + " is not a " + what + " (it takes " + known + ")");
    return std::nullopt;
}

// D3DFOGMODE: NONE, EXP, EXP2, LINEAR.
constexpr Choice<std::optional<FogMode>> d3dFogModes[] = {
    {0, std::nullopt}, {1, FogMode::Exp}, {2, FogMode::Exp2}, {3, FogMode::Linear}};

// Compare functions: RenderMonkey's OpenGL enumeration numbers them as D3DCMPFUNC does.
constexpr Choice<CompareFunc> compareFuncs[] = {
    {1, CompareFunc::Never},   {2, CompareFunc::Less},     {3, CompareFunc::Equal},        {4, CompareFunc::LessEqual},
    {5, CompareFunc::Greater}, {6, CompareFunc::NotEqual}, {7, CompareFunc::GreaterEqual}, {8, CompareFunc::Always}};
// RenderMonkey's OpenGL enumerations.
constexpr Choice<BlendFactor> glBlend[] = {
    {1, BlendFactor::Zero},           {2, BlendFactor::One},
    {3, BlendFactor::SrcColor},       {4, BlendFactor::OneMinusSrcColor},
    {5, BlendFactor::DstColor},       {6, BlendFactor::OneMinusDstColor},
    {7, BlendFactor::SrcAlpha},       {8, BlendFactor::OneMinusSrcAlpha},
    {9, BlendFactor::DstAlpha},       {10, BlendFactor::OneMinusDstAlpha},
    {11, BlendFactor::ConstantColor}, {12, BlendFactor::OneMinusConstantColor}};
constexpr Choice<BlendOp> blendOps[] = {  // the same numbers in both APIs
    {1, BlendOp::Add}, {2, BlendOp::Subtract}, {3, BlendOp::ReverseSubtract}, {4, BlendOp::Min}, {5, BlendOp::Max}};
constexpr Choice<CullFace> glCull[] = {{1, CullFace::None}, {2, CullFace::Front}, {3, CullFace::Back}};
constexpr Choice<bool> glFrontFace[] = {{1, true}, {2, false}};  // → frontCounterClockwise
constexpr Choice<bool> boolean[] = {{0, false}, {1, true}};
constexpr Choice<PolygonMode> glPolygonModes[] = {{1, PolygonMode::Point}, {2, PolygonMode::Line}, {3, PolygonMode::Fill}};
// D3DFILLMODE: 1 D3DFILL_POINT, 2 D3DFILL_WIREFRAME, 3 D3DFILL_SOLID.
constexpr Choice<PolygonMode> d3dFillModes[] = {{1, PolygonMode::Point}, {2, PolygonMode::Line}, {3, PolygonMode::Fill}};

// Direct3D 9 enumerations.
constexpr Choice<BlendFactor> d3dBlend[] = {
    {1, BlendFactor::Zero},       {2, BlendFactor::One},
    {3, BlendFactor::SrcColor},   {4, BlendFactor::OneMinusSrcColor},
    {5, BlendFactor::SrcAlpha},   {6, BlendFactor::OneMinusSrcAlpha},
    {7, BlendFactor::DstAlpha},   {8, BlendFactor::OneMinusDstAlpha},
    {9, BlendFactor::DstColor},   {10, BlendFactor::OneMinusDstColor},
    {11, BlendFactor::SrcAlphaSaturate},
    {14, BlendFactor::ConstantColor}, {15, BlendFactor::OneMinusConstantColor}};
// D3DBLEND_BOTHSRCALPHA (12) and D3DBLEND_BOTHINVSRCALPHA (13) set the source and the destination
// factor at once: (SRCALPHA, INVSRCALPHA) and (INVSRCALPHA, SRCALPHA).
constexpr long long kD3dBothSrcAlpha = 12, kD3dBothInvSrcAlpha = 13;

// GL states rmfx knows but cannot express; those marked float hold IEEE-754 bits.
struct Unmodelled {
    std::string_view name;
    bool isFloat;
};
constexpr Unmodelled glUnmodelled[] = {
    {"GL_CurrentColor", false},  {"GL_SecondaryColor", false},   {"GL_ClearColor", false},
    {"GL_ClearDepth", true},     {"GL_ShadeModel", false},       {"GL_EdgeFlag", false},
    {"GL_DepthNear", true},      {"GL_DepthFar", true},          {"GL_FogColor", false},
    {"GL_FogDensity", true},     {"GL_FogStart", true},          {"GL_FogEnd", true},
    {"GL_FogMode", false},       {"GL_PointSize", true},         {"GL_PointMin", true},
    {"GL_PointMax", true},       {"GL_PointSmooth", false},      {"GL_LineWidth", true},
    {"GL_LineSmooth", false},
    {"GL_PolySmooth", false},    {"GL_PolyOffsetFactor", true},  {"GL_PolyOffsetUnits", true},
    {"GL_PolyOffsetPoint", false}, {"GL_PolyOffsetLine", false}, {"GL_PolyOffsetFill", false},
    {"GL_AlphaEnable", false},   {"GL_AlphaFunction", false},    {"GL_AlphaReference", true},
    {"GL_WriteMaskColor", false}, {"GL_VertexProgramTwoSideARB", false},
    {"GL_StencilEnable", false}, {"GL_StencilFunction", false},  {"GL_StencilValueMask", false},
    {"GL_StencilReference", false}, {"GL_StencilFail", false},   {"GL_StencilPassDepthFail", false},
    {"GL_StencilPassDepthPass", false}, {"GL_WriteMaskStencil", false}, {"GL_ClearStencil", false},
};

void warnUnmodelled(const RfxElement& state, const std::string& name, long long value, bool isFloat) {
    std::string shown = isFloat ? formatValue(Value::ofFloat(floatFromBits(value))) : std::to_string(value);
    state.warning("render state " + name + " = " + shown + " has no equivalent in rmfx's pass model; ignored");
}

// D3DRS_FOGSTART, FOGEND, FOGDENSITY, POINTSIZE, POINTSIZE_MIN, POINTSCALE_A, POINTSIZE_MAX,
// DEPTHBIAS, SLOPESCALEDEPTHBIAS. (ALPHAREF is a byte, 0 to 255.)
bool isFloatD3dRenderState(long long number) {
    for (long long f : {36, 37, 38, 154, 155, 156, 159, 195, 196})
        if (number == f) return true;
    return false;
}

bool isFloatGlRenderState(std::string_view name) {
    for (const Unmodelled& u : glUnmodelled)
        if (u.name == name) return u.isFloat;
    return false;
}

}  // namespace

std::optional<long long> stateValue(const RfxElement& state, bool isFloat) {
    std::optional<std::string> text = state.text("VALUE");
    if (!text) return std::nullopt;
    const bool decimal = text->find_first_of(".eE") != std::string::npos && text->find_first_of("xX") == std::string::npos;
    if (!decimal) return state.integer("VALUE", kInt32Min, kUInt32Max);
    char* end = nullptr;
    const double v = std::strtod(text->c_str(), &end);
    while (end && *end == ' ') ++end;
    if (!end || *end != '\0' || !std::isfinite(v)) {
        state.error("attribute VALUE: '" + *text + "' is not a number");
        return std::nullopt;
    }
    if (isFloat) return static_cast<long long>(std::bit_cast<uint32_t>(static_cast<float>(v)));
    if (v != std::floor(v) || v < static_cast<double>(kInt32Min) || v > static_cast<double>(kUInt32Max)) {
        state.error("attribute VALUE: '" + *text + "' is not a whole number, and this state takes one");
        return std::nullopt;
    }
    return static_cast<long long>(v);
}

float floatFromBits(long long bits) {
    return std::bit_cast<float>(static_cast<uint32_t>(static_cast<uint64_t>(bits)));
}

void setRenderMonkeyDefaults(Pass& pass) {
    pass.depth = DepthState{true, true, CompareFunc::LessEqual};
    pass.blend = BlendState{};
    pass.raster = RasterState{};
}

void applyGlRenderState(const RfxElement& state, Pass& pass) {
    std::string name = state.name();
    auto value = stateValue(state, isFloatGlRenderState(name));
    if (!value) return;
    long long v = *value;
    auto set = [&](auto& field, const auto& choices, const char* what) {
        if (auto m = pick(state, what, v, choices)) field = *m;
    };
    if (name == "GL_CullMode") {
        if (v == 4) {
            state.error("VALUE 4 (cull front and back faces) would draw nothing; rmfx does not support it");
            return;
        }
        set(pass.raster.cull, glCull, "cull mode");
    } else if (name == "GL_FrontFace") {
        set(pass.raster.frontCounterClockwise, glFrontFace, "front face (1 CCW, 2 CW)");
    } else if (name == "GL_DepthEnable") {
        set(pass.depth.test, boolean, "boolean");
    } else if (name == "GL_DepthFunction") {
        set(pass.depth.func, compareFuncs, "compare function");
    } else if (name == "GL_WriteMaskDepth") {
        set(pass.depth.write, boolean, "boolean");
    } else if (name == "GL_BlendEnable") {
        set(pass.blend.enabled, boolean, "boolean");
    } else if (name == "GL_BlendSourceRGB") {
        set(pass.blend.srcColor, glBlend, "blend factor rmfx supports");
    } else if (name == "GL_BlendDestRGB") {
        set(pass.blend.dstColor, glBlend, "blend factor rmfx supports");
    } else if (name == "GL_BlendSourceAlpha") {
        set(pass.blend.srcAlpha, glBlend, "blend factor rmfx supports");
    } else if (name == "GL_BlendDestAlpha") {
        set(pass.blend.dstAlpha, glBlend, "blend factor rmfx supports");
    } else if (name == "GL_BlendEquation") {
        if (auto op = pick(state, "blend equation", v, blendOps)) pass.blend.colorOp = pass.blend.alphaOp = *op;
    } else if (name == "GL_BlendColor") {
        pass.blend.constant = unpackArgb(v);
    } else if (name == "GL_PolyFrontMode" || name == "GL_PolyBackMode") {
        // RenderMonkey's enumeration: 1 GL_POINT, 2 GL_LINE, 3 GL_FILL.
        PolygonMode& mode = name == "GL_PolyFrontMode" ? pass.raster.frontMode : pass.raster.backMode;
        set(mode, glPolygonModes, "polygon mode");
        pass.raster.polygonModeWhere = state.where();
    } else if (name == "GL_LineWidth") {
        const float width = floatFromBits(v);
        if (width >= 1.0f && width <= 64.0f) pass.raster.lineWidth = width;
        else state.error("VALUE " + formatValue(Value::ofFloat(width)) + " is not a line width from 1 to 64 pixels");
    } else {
        for (const Unmodelled& u : glUnmodelled)
            if (u.name == name) return warnUnmodelled(state, name, v, u.isFloat);
        state.warning("unknown OpenGL render state '" + name + "'; ignored");
    }
}

void applyD3dRenderState(const RfxElement& state, Pass& pass, bool& separateAlpha) {
    auto number = state.integer("STATE", 0, kUInt32Max);
    if (!number) return;
    auto value = stateValue(state, isFloatD3dRenderState(*number));
    if (!value) return;
    long long v = *value;
    auto set = [&](auto& field, const auto& choices, const char* what) {
        if (auto m = pick(state, what, v, choices)) field = *m;
    };
    std::string name = state.name().empty() ? "STATE " + std::to_string(*number) : state.name();
    switch (*number) {
        case 7:  // D3DRS_ZENABLE (2, D3DZB_USEW, is a depth test too)
            if (v == 2) v = 1;
            set(pass.depth.test, boolean, "D3DZBUFFERTYPE rmfx supports (0 off, 1 on)");
            break;
        case 14: set(pass.depth.write, boolean, "boolean"); break;        // D3DRS_ZWRITEENABLE
        case 23: set(pass.depth.func, compareFuncs, "D3DCMPFUNC"); break;   // D3DRS_ZFUNC
        case 27: set(pass.blend.enabled, boolean, "boolean"); break;      // D3DRS_ALPHABLENDENABLE
        case 19: case 20: case 207: case 208: {  // D3DRS_SRCBLEND, DESTBLEND, SRCBLENDALPHA, DESTBLENDALPHA
            const bool alpha = *number > 200, source = *number == 19 || *number == 207;
            BlendFactor& src = alpha ? pass.blend.srcAlpha : pass.blend.srcColor;
            BlendFactor& dst = alpha ? pass.blend.dstAlpha : pass.blend.dstColor;
            if (v == kD3dBothSrcAlpha || v == kD3dBothInvSrcAlpha) {
                const bool inverse = v == kD3dBothInvSrcAlpha;
                src = inverse ? BlendFactor::OneMinusSrcAlpha : BlendFactor::SrcAlpha;
                dst = inverse ? BlendFactor::SrcAlpha : BlendFactor::OneMinusSrcAlpha;
                if (!source)
                    state.warning(std::string(inverse ? "D3DBLEND_BOTHINVSRCALPHA" : "D3DBLEND_BOTHSRCALPHA") +
                                  " is a source factor that sets the destination too; read as such here");
            } else {
                set(source ? src : dst, d3dBlend, "D3DBLEND rmfx supports");
            }
            break;
        }
        case 171: set(pass.blend.colorOp, blendOps, "D3DBLENDOP"); break;  // D3DRS_BLENDOP
        case 209: set(pass.blend.alphaOp, blendOps, "D3DBLENDOP"); break;  // D3DRS_BLENDOPALPHA
        case 193: pass.blend.constant = unpackArgb(v); break;              // D3DRS_BLENDFACTOR
        case 22:  // D3DRS_CULLMODE: 1 none, 2 cull clockwise faces, 3 cull counter-clockwise faces
            if (v == 1) {
                pass.raster.cull = CullFace::None;
            } else if (v == 2 || v == 3) {  // Direct3D's front faces are the clockwise ones
                pass.raster.cull = v == 2 ? CullFace::Front : CullFace::Back;
                pass.raster.frontCounterClockwise = false;
            } else {
                state.error("VALUE " + std::to_string(v) + " is not a D3DCULL (it takes 1, 2, 3)");
            }
            break;
        case 8:  // D3DRS_FILLMODE: both faces
            if (auto mode = pick(state, "D3DFILLMODE", v, d3dFillModes)) {
                pass.raster.frontMode = pass.raster.backMode = *mode;
                pass.raster.polygonModeWhere = state.where();
            }
            break;
        case 206:  // D3DRS_SEPARATEALPHABLENDENABLE
            if (auto separate = pick(state, "boolean", v, boolean)) separateAlpha = *separate;
            break;
        case 28:  // D3DRS_FOGENABLE
            set(pass.fog.enabled, boolean, "boolean");
            pass.fog.where = state.where();
            break;
        case 34: {  // D3DRS_FOGCOLOR (its alpha is unused)
            const glm::vec4 c = unpackArgb(v);
            pass.fog.color = glm::vec3(c);
            break;
        }
        case 35: case 140:  // D3DRS_FOGTABLEMODE, FOGVERTEXMODE: D3DFOGMODE
            if (auto m = pick(state, "D3DFOGMODE", v, d3dFogModes)) {
                if (*number == 35) pass.fog.mode = *m;
                else pass.fog.vertexFog = m->has_value();
            }
            break;
        case 36: pass.fog.start = floatFromBits(v); break;    // D3DRS_FOGSTART
        case 37: pass.fog.end = floatFromBits(v); break;      // D3DRS_FOGEND
        case 38: pass.fog.density = floatFromBits(v); break;  // D3DRS_FOGDENSITY
        case 15: set(pass.alphaTest.enabled, boolean, "boolean"); break;  // D3DRS_ALPHATESTENABLE
        case 25: set(pass.alphaTest.func, compareFuncs, "D3DCMPFUNC"); break;  // D3DRS_ALPHAFUNC
        case 24:  // D3DRS_ALPHAREF: the low byte
            if (v < 0 || v > 255) state.error("VALUE " + std::to_string(v) + " is not an alpha reference (0 to 255)");
            else pass.alphaTest.ref = static_cast<float>(v) / 255.0f;
            break;
        case 154: case 155: case 156: case 159: case 195: case 196:
            // D3DRS_POINTSIZE, POINTSIZE_MIN, POINTSCALE_A, POINTSIZE_MAX, DEPTHBIAS,
            // SLOPESCALEDEPTHBIAS: floats
            warnUnmodelled(state, name, v, true);
            break;
        default: warnUnmodelled(state, name, v, false); break;
    }
}

void finishD3dRenderStates(Pass& pass, bool separateAlpha) {
    if (separateAlpha) return;
    pass.blend.srcAlpha = pass.blend.srcColor;
    pass.blend.dstAlpha = pass.blend.dstColor;
    pass.blend.alphaOp = pass.blend.colorOp;
}

void applyRenderStateBlock(const RfxElement& block, RfxApi api, Pass& pass, bool& separateAlpha) {
    for (const tinyxml2::XMLElement* x = block.xml()->FirstChildElement("RmState"); x; x = x->NextSiblingElement("RmState")) {
        RfxElement state(x, block.file(), block.diagnostics());
        if (api == RfxApi::Direct3D) applyD3dRenderState(state, pass, separateAlpha);
        else applyGlRenderState(state, pass);
    }
}

}  // namespace rmfx::rfx
